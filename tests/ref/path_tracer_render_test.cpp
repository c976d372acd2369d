// Whole-image rendering: determinism across seeds and thread counts, resumable accumulation,
// agreement of the path tracer's pixels with the rasterizer's projection, and the scene's
// geometry at a frame.
#include <algorithm>
#include <csignal>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <vector>

#include <gtest/gtest.h>

#include "small_scene.h"

#include "image/image.h"
#include "ref/embree_scene.h"
#include "ref/path_tracer.h"
#include "ref/reference_render.h"
#include "ref/scene_geometry.h"
#include "scene/camera.h"
#include "scene/character_motion.h"
#include "scene/scene_defaults.h"
#include "world/world.h"

namespace proxygi::ref {
namespace {

using test_scenes::small_camera;
using test_scenes::small_scene;

bool same_bits(const SampleSums& a, const SampleSums& b) {
  auto bits = [](const std::vector<glm::dvec3>& x, const std::vector<glm::dvec3>& y) {
    return x.size() == y.size() && std::memcmp(x.data(), y.data(), x.size() * sizeof(glm::dvec3)) == 0;
  };
  return a.samples == b.samples && bits(a.radiance, b.radiance) && bits(a.radiance_squared, b.radiance_squared) &&
         bits(a.indirect, b.indirect);
}

std::vector<char> file_bytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

class PathTracerRender : public ::testing::Test {
 protected:
  EmbreeScene scene_ = small_scene();
  scene::Environment environment_;  // default analytic sky with a sun: exercises both strategies
  EnvironmentLight light_ = EnvironmentLight::analytic_sky(environment_);
  PathTracer tracer_{scene_, light_, light_, PathTracerSettings{LightTransport::multi_bounce}};
  scene::CameraState camera_ = small_camera();

  SampleSums render(RenderJob job) {
    auto sums = render_samples(tracer_, camera_, job);
    EXPECT_TRUE(sums.ok()) << (sums.ok() ? "" : sums.message());
    return std::move(*sums);
  }
};

TEST_F(PathTracerRender, SameSeedSameBitsWhateverTheThreads) {
  RenderJob job;
  job.width = 24;
  job.height = 20;
  job.spp = 4;
  job.seed = 11;
  job.threads = 1;
  const SampleSums one = render(job);
  job.threads = 2;
  job.tile_size = 5;  // different tiles, different order
  const SampleSums two = render(job);
  job.threads = 3;
  job.tile_size = 16;
  const SampleSums three = render(job);
  EXPECT_TRUE(same_bits(one, two));
  EXPECT_TRUE(same_bits(one, three));

  // The EXR files are byte-identical too.
  const std::filesystem::path dir = std::filesystem::path(PROXYGI_TEST_OUTPUT_DIR) / "path_tracer";
  std::filesystem::create_directories(dir);
  ASSERT_TRUE(image::write_exr(dir / "one.exr", to_images(one).radiance).ok());
  ASSERT_TRUE(image::write_exr(dir / "two.exr", to_images(two).radiance).ok());
  EXPECT_EQ(file_bytes(dir / "one.exr"), file_bytes(dir / "two.exr"));
  EXPECT_FALSE(file_bytes(dir / "one.exr").empty());

  job.seed = 12;
  EXPECT_FALSE(same_bits(one, render(job)));
}

TEST_F(PathTracerRender, SplitSampleRangesMergeIntoOneRun) {
  RenderJob job;
  job.width = 16;
  job.height = 16;
  job.seed = 3;
  job.spp = 6;
  const SampleSums whole = render(job);
  job.spp = 2;
  SampleSums first = render(job);
  job.first_sample = 2;
  job.spp = 4;
  ASSERT_TRUE(first.merge(render(job)).ok());
  ASSERT_EQ(first.samples, 6u);
  for (std::size_t i = 0; i < whole.radiance.size(); ++i)
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(first.radiance[i][c], whole.radiance[i][c], 1e-12 * (1.0 + whole.radiance[i][c]));
      EXPECT_NEAR(first.indirect[i][c], whole.indirect[i][c], 1e-12 * (1.0 + whole.indirect[i][c]));
    }
  // Resuming from the written float images keeps the means to float precision.
  auto resumed = from_images(to_images(whole), whole.samples);
  ASSERT_TRUE(resumed.ok());
  const ReferenceImages again = to_images(*resumed), original = to_images(whole);
  for (std::size_t i = 0; i < original.radiance.pixels.size(); ++i) {
    EXPECT_NEAR(again.radiance.pixels[i].g, original.radiance.pixels[i].g, 1e-6f * (1.0f + original.radiance.pixels[i].g));
    EXPECT_NEAR(again.variance.pixels[i].g, original.variance.pixels[i].g, 1e-4f * (1e-3f + original.variance.pixels[i].g));
  }
}

// Stopping (the SIGINT flag) after whole rounds and continuing from the kept sums gives the
// same doubles as one uninterrupted run: what `reference` Ctrl-C + --accumulate relies on.
TEST_F(PathTracerRender, StoppedRunContinuesToTheSameBits) {
  RenderJob job;
  job.width = 16;
  job.height = 12;
  job.seed = 5;
  job.spp = 5;
  job.tile_size = 5;
  const SampleSums whole = render(job);

  volatile std::sig_atomic_t stop = 0;
  job.stop = &stop;
  SampleSums kept;
  kept.width = job.width;
  kept.height = job.height;
  kept.radiance.assign(std::size_t(job.width * job.height), glm::dvec3(0.0));
  kept.radiance_squared = kept.indirect = kept.radiance;
  std::uint32_t reported = 0;
  auto stop_after_two = [&](const RenderProgress& p) {
    reported = p.samples_done;
    if (p.samples_done == 2) stop = 1;
  };
  ASSERT_TRUE(accumulate_samples(tracer_, camera_, job, kept, nullptr, stop_after_two).ok());
  EXPECT_EQ(kept.samples, 2u);
  EXPECT_EQ(reported, 2u);
  EXPECT_FALSE(same_bits(kept, whole));

  stop = 0;
  job.first_sample = kept.samples;
  job.spp = 3;
  job.threads = 3;  // another thread count: still the same bits
  ASSERT_TRUE(accumulate_samples(tracer_, camera_, job, kept).ok());
  EXPECT_TRUE(same_bits(kept, whole));

  // A flag already raised traces nothing.
  stop = 1;
  SampleSums untouched = kept;
  ASSERT_TRUE(accumulate_samples(tracer_, camera_, job, untouched).ok());
  EXPECT_TRUE(same_bits(untouched, kept));
}

TEST_F(PathTracerRender, PixelsSeeWhatTheRasterizerProjectsThere) {
  // The feature pass traces the center ray of each pixel; rebuilding the hit point from its eye
  // depth and projecting it with the rasterizer's matrices must land on that pixel center.
  const int width = 40, height = 30;
  const PixelFeatures features = render_features(scene_, camera_, width, height);
  const glm::vec3 forward = glm::normalize(camera_.target - camera_.eye);
  int checked = 0;
  for (int y = 0; y < height; y += 3)
    for (int x = 0; x < width; x += 3) {
      if (features.mask.at(x, y).r == 0.0f) continue;
      const scene::Ray ray = scene::ray_through_pixel(camera_, width, height, x + 0.5f, y + 0.5f);
      const float depth = features.depth.at(x, y).r;
      const glm::vec3 world = ray.origin + ray.direction * (depth / glm::dot(ray.direction, forward));
      const glm::vec2 pixel = scene::project_to_pixel(camera_, width, height, world);
      EXPECT_NEAR(pixel.x, x + 0.5f, 2e-3f);
      EXPECT_NEAR(pixel.y, y + 0.5f, 2e-3f);
      ++checked;
    }
  EXPECT_GT(checked, 60);
  // The sphere's top (world (0, 1.1, 0)) is covered where the rasterizer puts it, and red.
  const glm::vec2 top = scene::project_to_pixel(camera_, width, height, {0.0f, 1.05f, 0.0f});
  const glm::vec4 albedo = features.albedo.at(int(top.x), int(top.y));
  EXPECT_FLOAT_EQ(albedo.r, 0.9f);
  EXPECT_FLOAT_EQ(albedo.g, 0.2f);
  // A pixel above the horizon sees the sky: no coverage.
  EXPECT_EQ(features.mask.at(width / 2, 0).r, 0.0f);
}

TEST(PathTracerScene, DefaultSceneGeometryAtAFrame) {
  const scene::Scene scene = scene::default_scene();
  auto world = world::World::load(scene, {.assets_dir = std::filesystem::path(PROXYGI_SOURCE_DIR) / "assets", .load_rigs = false});
  ASSERT_TRUE(world.ok()) << world.message();
  const double t = 1.0;
  world::WorldState state;
  ASSERT_TRUE((*world)->evaluate(t, std::nullopt, state).ok());
  auto meshes = world_meshes(**world, state, make_scene_geometry(**world));
  ASSERT_TRUE(meshes.ok()) << meshes.message();
  ASSERT_GT(meshes->size(), 1u);
  EXPECT_EQ(meshes->front().name, "ground");
  glm::vec3 lo(1e9f), hi(-1e9f);
  std::size_t triangles = 0;
  for (std::size_t i = 1; i < meshes->size(); ++i) {
    for (const glm::vec3& p : (*meshes)[i].positions) {
      lo = glm::min(lo, p);
      hi = glm::max(hi, p);
    }
    triangles += (*meshes)[i].indices.size() / 3;
  }
  EXPECT_GT(triangles, 1000u);
  // The walker stands on the ground, about 1.8 m tall, around its walk-path position.
  const glm::vec3 root = scene::character_root_position(scene.characters[0], t);
  EXPECT_NEAR(lo.y, 0.0f, 0.1f);
  EXPECT_NEAR(hi.y, 1.8f, 0.15f);
  EXPECT_NEAR(0.5f * (lo.x + hi.x), root.x, 0.5f);
  EXPECT_NEAR(0.5f * (lo.z + hi.z), root.z, 0.5f);
  auto embree = EmbreeScene::build(std::move(*meshes));
  ASSERT_TRUE(embree.ok()) << embree.message();
  EXPECT_EQ(embree->triangle_count(), triangles + 2);
}

}  // namespace
}  // namespace proxygi::ref
