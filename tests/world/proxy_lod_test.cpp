// render.proxy_lod auto over a world (world/proxy_lod.h): a farther character streams fewer
// spheres; the cross-fade has no step over 1/255 of the unshadowed shade between frames on the
// frame's CPU twins (a hard switch of the same levels at the same frames has); the weighted log
// sum is (1 − t) Σ_A + t Σ_B; and the choice at a frame does not depend on the frames before.
#include "world/proxy_lod.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include <gtest/gtest.h>

#include "render/frame_tables.h"
#include "render/shading.h"
#include "scene/scene_defaults.h"

namespace proxygi::world {
namespace {

const std::filesystem::path kAssets = PROXYGI_SOURCE_DIR "/assets";
constexpr std::uint32_t kHeight = 512;

std::unique_ptr<World> load(const scene::Scene& scene) {
  auto world = World::load(scene, {.assets_dir = kAssets, .load_rigs = true, .write_rig_cache = false});
  EXPECT_TRUE(world.ok()) << world.message();
  return world.ok() ? std::move(*world) : nullptr;
}

// The default scene's mannequin standing at the origin (its walk frozen at t = 0), the camera
// backing away from 3 m to 60 m over `frames` frames.
struct Dolly {
  std::unique_ptr<World> world;
  WorldState still;
  int frames = 600;
  scene::CameraState camera(int f) const {
    scene::CameraState c = still.camera;
    c.target = glm::vec3(0.0f, 0.9f, 0.0f);
    c.eye = c.target + glm::vec3(0.0f, 0.0f, 3.0f + 57.0f * float(f) / float(frames - 1));
    return c;
  }
  WorldState at(int f) const {
    WorldState s = still;
    s.time_s = scene::frame_time_s(world->scene().output, f);
    s.camera = camera(f);
    return s;
  }
};
Dolly dolly() {
  scene::Scene scene = scene::default_scene();
  scene.characters[0].path.reset();
  Dolly d;
  d.world = load(scene);
  if (d.world) {
    EXPECT_TRUE(d.world->evaluate(0.0, std::nullopt, d.still).ok());
  }
  return d;
}

render::FrameTables tables_of(const World& world) {
  auto environment = world.environment(world.scene().render.sh_order);
  EXPECT_TRUE(environment.ok()) << environment.message();
  return render::make_frame_tables((*environment)->lighting, world.scene().render);
}

// Ground receivers around the feet: irradiance per receiver and channel, and HYB's squarings.
std::vector<glm::vec3> ground_points() {
  std::vector<glm::vec3> points;
  for (int i = -10; i <= 10; ++i)
    for (int j = -10; j <= 10; ++j) points.push_back({0.12f * float(i), 0.0f, 0.12f * float(j)});
  return points;
}
struct Shade {
  std::vector<glm::vec3> irradiance;
  std::vector<int> squarings;
};
Shade shade(const render::FrameTables& tables, std::span<const render::Sphere> spheres) {
  Shade out;
  for (const glm::vec3& p : ground_points()) {
    const std::vector<float> f = render::accumulate_log_occlusion(tables, p, glm::vec3(0, 1, 0), spheres);
    const render::DirectResult direct = render::exponentiate_and_shade(tables, f, tables.settings.hyb_tau, p, glm::vec3(0, 1, 0));
    out.irradiance.push_back(direct.irradiance);
    out.squarings.push_back(direct.squarings);
  }
  return out;
}
// The largest change between two frames, in u = 1/255 of the unshadowed irradiance, over all
// receivers; those whose HYB squaring count changed are also counted in `switch_steps` and their
// largest step in `switch_worst` (before HYB blended toward the next count, the exponential
// jumped there by up to 1.8 u: F7, stability sweep S3).
struct Steps {
  double worst = 0.0, switch_worst = 0.0;
  int switch_steps = 0;
};
void add_steps(const Shade& a, const Shade& b, const Shade& open, Steps& steps) {
  for (std::size_t i = 0; i < a.irradiance.size(); ++i)
    for (int c = 0; c < 3; ++c) {
      const double step = std::abs(double(a.irradiance[i][c]) - b.irradiance[i][c]) / (open.irradiance[i][c] / 255.0);
      steps.worst = std::max(steps.worst, step);
      if (a.squarings[i] != b.squarings[i]) {
        steps.switch_worst = std::max(steps.switch_worst, step);
        steps.switch_steps += c == 0;
      }
    }
}

TEST(ProxyLod, AFartherCharacterStreamsFewerSpheres) {
  const Dolly d = dolly();
  ASSERT_TRUE(d.world);
  auto lod = ProxyLod::build(*d.world);
  ASSERT_TRUE(lod.ok()) << lod.message();
  const auto counts = (*lod)->models()[0].levels.counts();
  ASSERT_GE(counts.size(), 2u);
  EXPECT_EQ(counts.front(), int(d.world->models()[0]->rig.spheres.size()));
  std::vector<std::size_t> streamed;
  std::vector<render::Sphere> out;
  for (int f = 0; f < d.frames; ++f) {
    out.clear();
    ASSERT_TRUE((*lod)->select(d.at(f), kHeight, out).ok());
    streamed.push_back(out.size());
  }
  EXPECT_EQ(streamed.front(), std::size_t(counts.front()));  // 3 m: the whole rig
  EXPECT_EQ(streamed.back(), std::size_t(counts.back()));    // 60 m: the coarsest level
  // Outside the fades (which stream both levels) the count never grows as the camera backs away.
  std::size_t settled = streamed.front();
  for (int f = 0; f < d.frames; ++f) {
    if (std::find(counts.begin(), counts.end(), int(streamed[std::size_t(f)])) == counts.end()) continue;
    EXPECT_LE(streamed[std::size_t(f)], settled) << "frame " << f;
    settled = streamed[std::size_t(f)];
  }
}

TEST(ProxyLod, CrossFadeHasNoStepOverOneOver255BetweenFrames) {
  const Dolly d = dolly();
  ASSERT_TRUE(d.world);
  const render::FrameTables tables = tables_of(*d.world);
  auto lod = ProxyLod::build(*d.world);
  ASSERT_TRUE(lod.ok()) << lod.message();
  const Shade open = shade(tables, {});
  // The fade as streamed, and a hard switch (one fade frame) of the same levels at the same sizes.
  proxies::LodChooser hard = (*lod)->chooser(0);
  hard.fade_frames = 1;
  proxies::LodChoice hard_choice;
  std::vector<std::vector<proxies::WorldSphere>> scratch;
  Shade previous, previous_hard;
  Steps steps, hard_steps;
  int switches = 0;
  for (int f = 0; f < d.frames; ++f) {
    std::vector<render::Sphere> spheres;
    const WorldState state = d.at(f);
    ASSERT_TRUE((*lod)->select(state, kHeight, spheres).ok());
    const InstanceLod& instance = (*lod)->instances()[0];
    const proxies::LodChoice before = hard_choice;
    hard_choice = f == 0 ? instance.choice : hard.step(hard_choice, instance.radius_px);
    switches += hard_choice.to != before.to && f > 0;
    std::vector<proxies::WeightedSphere> weighted;
    proxies::append_lod_spheres((*lod)->models()[0].levels, hard_choice, 1.0f, state.instances[0].spheres, scratch, weighted);
    std::vector<render::Sphere> hard_spheres;
    for (const auto& w : weighted) hard_spheres.push_back({w.sphere.center, w.sphere.radius, w.sphere.albedo, w.weight});
    const Shade now = shade(tables, spheres), now_hard = shade(tables, hard_spheres);
    if (f > 0) add_steps(now, previous, open, steps), add_steps(now_hard, previous_hard, open, hard_steps);
    previous = now, previous_hard = now_hard;
  }
  EXPECT_GE(switches, 2);                             // 32 → 16 → 8 on the way out
  const proxies::LodChoice last = (*lod)->instances()[0].choice;
  EXPECT_EQ(last.from, last.to);  // the fades finished within the dolly
  EXPECT_GT(hard_steps.worst, 1.0);                   // what the fade is for: a hard switch pops
  EXPECT_LE(steps.worst, 1.0) << "hard switch: " << hard_steps.worst << " u";
  std::printf("largest step between frames: fade %.3f u, hard switch %.3f u; HYB squaring switches crossed by the fade: "
              "%d receiver steps, largest %.3f u\n",
              steps.worst, hard_steps.worst, steps.switch_steps, steps.switch_worst);
}

TEST(ProxyLod, WeightedLogSumIsTheBlendOfTheTwoLevels) {
  const Dolly d = dolly();
  ASSERT_TRUE(d.world);
  const render::FrameTables tables = tables_of(*d.world);
  auto lod = ProxyLod::build(*d.world);
  ASSERT_TRUE(lod.ok()) << lod.message();
  const auto& levels = (*lod)->models()[0].levels;
  const auto& tracked = d.still.instances[0].spheres;
  std::vector<std::vector<proxies::WorldSphere>> scratch;
  auto spheres_of = [&](proxies::LodChoice choice, float t) {
    std::vector<proxies::WeightedSphere> weighted;
    proxies::append_lod_spheres(levels, choice, t, tracked, scratch, weighted);
    std::vector<render::Sphere> out;
    for (const auto& w : weighted) out.push_back({w.sphere.center, w.sphere.radius, w.sphere.albedo, w.weight});
    return out;
  };
  const auto a = spheres_of({0, 0, 0}, 1.0f), b = spheres_of({1, 1, 0}, 1.0f), faded = spheres_of({0, 1, 5}, 0.3f);
  EXPECT_LT(b.size(), a.size());
  double largest = 0.0, worst = 0.0;
  for (const glm::vec3& p : ground_points()) {
    const auto fa = render::accumulate_log_occlusion(tables, p, glm::vec3(0, 1, 0), a);
    const auto fb = render::accumulate_log_occlusion(tables, p, glm::vec3(0, 1, 0), b);
    const auto ff = render::accumulate_log_occlusion(tables, p, glm::vec3(0, 1, 0), faded);
    for (std::size_t i = 0; i < ff.size(); ++i) {
      largest = std::max(largest, std::abs(double(fa[i])));
      worst = std::max(worst, std::abs(double(ff[i]) - (0.7 * fa[i] + 0.3 * fb[i])));
    }
  }
  EXPECT_GT(largest, 0.1);  // the receivers are shadowed
  EXPECT_LE(worst, 1e-5 * largest) << "largest |f| " << largest;
}

TEST(ProxyLod, AFrameStreamsTheSameWhateverWasRenderedBefore) {
  auto world = load(scene::crowd_scene());
  ASSERT_TRUE(world);
  auto sequential = ProxyLod::build(*world), jumped = ProxyLod::build(*world);
  ASSERT_TRUE(sequential.ok() && jumped.ok());
  WorldState state;
  std::vector<render::Sphere> a, b;
  for (int f = 0; f <= 72; f += 1) {
    ASSERT_TRUE(world->evaluate(scene::frame_time_s(world->scene().output, f), std::nullopt, state).ok());
    a.clear();
    ASSERT_TRUE((*sequential)->select(state, kHeight, a).ok());
  }
  // Jump to frame 72 after a later frame (a restart from frame 0).
  ASSERT_TRUE(world->evaluate(scene::frame_time_s(world->scene().output, 90), std::nullopt, state).ok());
  ASSERT_TRUE((*jumped)->select(state, kHeight, b).ok());
  ASSERT_TRUE(world->evaluate(scene::frame_time_s(world->scene().output, 72), std::nullopt, state).ok());
  b.clear();
  ASSERT_TRUE((*jumped)->select(state, kHeight, b).ok());
  ASSERT_EQ(a.size(), b.size());
  EXPECT_EQ(std::memcmp(a.data(), b.data(), a.size() * sizeof(render::Sphere)), 0);
  EXPECT_LT(a.size(), world->proxy_count());  // the crowd's far characters stream fewer spheres
  // The same frame again with the same camera streams the same spheres.
  b.clear();
  ASSERT_TRUE((*jumped)->select(state, kHeight, b).ok());
  EXPECT_EQ(std::memcmp(a.data(), b.data(), a.size() * sizeof(render::Sphere)), 0);
}

}  // namespace
}  // namespace proxygi::world
