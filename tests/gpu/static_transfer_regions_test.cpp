// render.static_transfer l0 / ratio / l1 against the path tracer on the wall corner, by region
// (issue 17 item 6; README "Static receivers: PRT" has the table this prints): frame 60 (the
// mannequin a step from the corner) at 192², the frame's PRT defaults (0.1 m, 1024 directions,
// 2 bounces; computed once into the test's cache folder, then read), the multi-bounce reference
// at 128 spp under the frame's own band-limited SH lighting (so the error is the method's, not
// the band limit's). Regions: character (the reference's), near-wall band (floor within 0.5 m of
// a wall or step vertex), open floor (farther than 1 m), walls and steps (static, not floor).
// The frame's floor in the corner and the walls are far too bright at l0; ratio and l1 must
// bring their mean luminance within half of l0's bias and lower the band's relative RMSE. The
// character is not a static receiver: at ratio and l1 the static meshes' visibility grid
// (prt/visibility_grid.h) shadows it, and its mean luminance must come within 5 % of the path
// tracer's (the goal; l0 is +27 %, the walls hide part of its sky).
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>

#include "gpu/scene_renderer.h"
#include "gpu_test_context.h"
#include "prt/surfaces.h"
#include "ref/embree_scene.h"
#include "ref/metrics.h"
#include "ref/path_tracer.h"
#include "ref/reference_render.h"
#include "ref/scene_geometry.h"
#include "scene/scene_defaults.h"
#include "scene/scene_parse.h"

namespace proxygi::gpu {
namespace {

using StaticTransferRegionsTest = testing::GpuTest;

constexpr int kSize = 192;
constexpr int kFrame = 60;
constexpr int kSpp = 128;
constexpr float kBandM = 0.5f, kOpenM = 1.0f;

struct RegionScore {
  double bias = 0.0;          // mean luminance / reference's − 1
  double relative_rmse = 0.0; // rmse / the reference's mean luminance
};

RegionScore score(const image::ImageF& test, const image::ImageF& reference, const ref::ReceiverMask& mask) {
  const double traced = ref::mean_luminance(reference, &mask);
  auto error = ref::rmse(test, reference, &mask);
  EXPECT_TRUE(error.ok()) << error.message();
  return {ref::mean_luminance(test, &mask) / traced - 1.0, error.ok() ? error->mean / traced : 0.0};
}

TEST_F(StaticTransferRegionsTest, RatioAndL1BringTheCornerFloorTowardThePathTracer) {
  auto scene = scene::load_scene(std::filesystem::path(PROXYGI_SOURCE_DIR) / "assets/scenes/wall_corner.json");
  ASSERT_TRUE(scene.ok()) << scene.message();
  scene->output.width = scene->output.height = kSize;
  auto loaded = world::World::load(*scene, {.assets_dir = PROXYGI_SOURCE_DIR "/assets", .load_rigs = true,
                                            .write_rig_cache = false});
  ASSERT_TRUE(loaded.ok()) << loaded.message();
  const std::shared_ptr<const world::World> world(std::move(*loaded));

  world::WorldState state;
  ASSERT_TRUE(world->evaluate(scene::frame_time_s(scene->output, kFrame), std::nullopt, state).ok());
  const ref::SceneGeometry geometry = ref::make_scene_geometry(*world);
  auto meshes = ref::world_meshes(*world, state, geometry);
  ASSERT_TRUE(meshes.ok()) << meshes.message();
  auto embree = ref::EmbreeScene::build(std::move(*meshes));
  ASSERT_TRUE(embree.ok()) << embree.message();
  auto lighting = ref::EnvironmentLight::from_scene(*scene, ref::LightingKind::sh, scene->render.sh_order);
  auto background = ref::EnvironmentLight::from_scene(*scene, ref::LightingKind::full, scene->render.sh_order);
  ASSERT_TRUE(lighting.ok() && background.ok());
  const ref::PathTracer tracer(*embree, *lighting, *background, {.transport = ref::LightTransport::multi_bounce});
  auto sums = ref::render_samples(tracer, state.camera, {.width = kSize, .height = kSize, .spp = kSpp, .seed = 1});
  ASSERT_TRUE(sums.ok()) << sums.message();
  const image::ImageF reference = ref::to_images(*sums).radiance;
  const ref::PixelFeatures features = ref::render_features(*embree, state.camera, kSize, kSize);

  prt::StaticFieldOptions options;
  options.cache_dir = std::filesystem::current_path() / "static-transfer-test-cache";
  settings::RenderSettings render = scene->render;
  auto renderer = SceneRenderer::create(context(), world, render, kSize, kSize, 2, options);
  ASSERT_TRUE(renderer.ok()) << renderer.message();
  auto positions = (*renderer)->render(kFrame).ok() ? (*renderer)->frame().read_gbuffer_positions()
                                                    : Result<image::ImageF>(make_error("frame failed"));
  ASSERT_TRUE(positions.ok()) << positions.message();

  // Distances to the walls and steps: their subdivided vertices (0.1 m apart) stand for them.
  auto receivers = prt::static_receivers(*world, 0.1f, 0.0f);
  ASSERT_TRUE(receivers.ok());
  std::vector<glm::vec3> walls;
  for (const prt::StaticSurface& s : receivers->surfaces)
    if (s.name != "ground") walls.insert(walls.end(), s.positions.begin(), s.positions.end());
  ASSERT_FALSE(walls.empty());
  auto wall_distance = [&](const glm::vec3& p) {
    float best = 1e30f;
    for (const glm::vec3& w : walls) best = std::min(best, glm::length(w - p));
    return best;
  };
  const ref::ReceiverMask character = ref::mask_from_image(features.character);
  std::vector<float> floor_distance(std::size_t(kSize * kSize), -1.0f);  // −1: not floor
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const glm::vec4 p = positions->at(x, y);
      const bool floor = features.mask.at(x, y).r > 0.0f && features.character.at(x, y).r == 0.0f && p.w > 0.0f &&
                         std::abs(p.y) < 1e-3f && features.normal.at(x, y).y > 0.999f;
      if (floor) floor_distance[std::size_t(y * kSize + x)] = wall_distance(glm::vec3(p));
    }
  const ref::ReceiverMask band = ref::mask_where(kSize, kSize, [&](int x, int y) {
    const float d = floor_distance[std::size_t(y * kSize + x)];
    return d >= 0.0f && d < kBandM;
  });
  const ref::ReceiverMask open = ref::mask_where(kSize, kSize, [&](int x, int y) {
    return floor_distance[std::size_t(y * kSize + x)] > kOpenM;
  });
  const ref::ReceiverMask static_meshes = ref::mask_where(kSize, kSize, [&](int x, int y) {
    return features.mask.at(x, y).r > 0.0f && features.character.at(x, y).r == 0.0f &&
           positions->at(x, y).w > 0.0f && floor_distance[std::size_t(y * kSize + x)] < 0.0f &&
           std::abs(positions->at(x, y).y) >= 1e-3f && wall_distance(glm::vec3(positions->at(x, y))) < 0.08f;
  });
  ASSERT_GE(character.count(), 100u);
  ASSERT_GE(band.count(), 500u);
  ASSERT_GE(open.count(), 500u);
  ASSERT_GE(static_meshes.count(), 1000u);

  const ref::ReceiverMask* masks[] = {&character, &band, &open, &static_meshes};
  const char* names[] = {"character", "near-wall band", "open floor", "walls and steps"};
  RegionScore scores[3][4];
  int row = 0;
  for (const auto& [level_name, level] : settings::kStaticTransferNames) {
    render.static_transfer = level;
    ASSERT_TRUE((*renderer)->apply_settings(render, kSize, kSize).ok());
    auto frame = (*renderer)->render(kFrame);
    ASSERT_TRUE(frame.ok()) << frame.message();
    for (int m = 0; m < 4; ++m) scores[row][m] = score(frame->hdr, reference, *masks[m]);
    ++row;
  }
  std::printf("%s\n", describe((*renderer)->static_transfer()).c_str());
  std::printf("wall corner, frame %d, %d², reference multi-bounce %d spp (band-limited SH lighting):\n", kFrame, kSize, kSpp);
  std::printf("%-16s %7s | %-17s | %-17s | %-17s\n", "region", "pixels", "l0 bias / rRMSE", "ratio", "l1");
  for (int m = 0; m < 4; ++m)
    std::printf("%-16s %7zu | %+7.1f%% %6.1f%% | %+7.1f%% %6.1f%% | %+7.1f%% %6.1f%%\n", names[m], masks[m]->count(),
                100 * scores[0][m].bias, 100 * scores[0][m].relative_rmse, 100 * scores[1][m].bias,
                100 * scores[1][m].relative_rmse, 100 * scores[2][m].bias, 100 * scores[2][m].relative_rmse);
  for (int level = 1; level < 3; ++level) {
    EXPECT_LT(std::abs(scores[level][1].bias), 0.5 * std::abs(scores[0][1].bias)) << "level " << level << ": band";
    EXPECT_LT(scores[level][1].relative_rmse, scores[0][1].relative_rmse) << "level " << level << ": band";
    // Shadowed by the visibility grid: body radiance within 5 % of the path tracer.
    EXPECT_LT(std::abs(scores[level][0].bias), 0.05) << "level " << level << ": character";
    EXPECT_LT(scores[level][0].relative_rmse, scores[0][0].relative_rmse) << "level " << level << ": character";
    EXPECT_LT(std::abs(scores[level][3].bias), 0.5 * std::abs(scores[0][3].bias)) << "level " << level << ": walls";
  }
}

}  // namespace
}  // namespace proxygi::gpu
