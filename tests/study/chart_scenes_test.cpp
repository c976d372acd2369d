// The chart's scenes: frames spread over the motion, shared characters framed at 1.7 m.
#include "study/chart_scenes.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "ref/scene_geometry.h"
#include "world/world.h"

namespace proxygi::study {
namespace {

TEST(ChartScenes, FramesAreSpreadInsideTheRange) {
  EXPECT_EQ(spread_frames(0, 96, 2), (std::vector<int>{32, 64}));
  EXPECT_EQ(spread_frames(10, 4, 3), (std::vector<int>{11, 12, 13}));
  EXPECT_EQ(spread_frames(0, 1, 1), (std::vector<int>{0}));
}

TEST(ChartScenes, DefaultSceneNeedsNoSharedFolder) {
  ChartSceneOptions options;
  options.size = 64;
  options.only = {"default", "Fox"};
  options.shared_dir = "/nonexistent";
  options.assets_dir = PROXYGI_SOURCE_DIR "/assets";
  auto scenes = chart_scenes(options);
  ASSERT_TRUE(scenes.ok()) << scenes.message();
  ASSERT_EQ(scenes->size(), 1u);  // Fox skipped: its file is missing
  EXPECT_EQ((*scenes)[0].name, "default");
  EXPECT_EQ((*scenes)[0].scene.output.width, 64);
  EXPECT_EQ((*scenes)[0].frames.size(), 2u);
}

TEST(ChartScenes, SharedCharactersStand1Point7MetresTallOnTheGround) {
  const std::filesystem::path shared = std::filesystem::path(PROXYGI_SHARED_ASSETS_DIR).parent_path();
  if (!std::filesystem::exists(shared / "assets" / "gltf" / "Fox.glb")) GTEST_SKIP() << "../shared is absent";
  ChartSceneOptions options;
  options.shared_dir = shared;
  options.assets_dir = PROXYGI_SOURCE_DIR "/assets";
  options.rig_cache_dir = PROXYGI_TEST_OUTPUT_DIR "/chart-rigs";
  options.only = {"Fox", "RiggedSimple"};
  auto scenes = chart_scenes(options);
  ASSERT_TRUE(scenes.ok()) << scenes.message();
  ASSERT_EQ(scenes->size(), 2u);
  for (const ChartScene& chart : *scenes) {
    scene::Scene alone = chart.scene;
    alone.ground.enabled = false;
    auto world = world::World::load(alone, {.assets_dir = options.assets_dir, .load_rigs = false});
    ASSERT_TRUE(world.ok()) << world.message();
    world::WorldState state;
    ASSERT_TRUE((*world)->evaluate(0.0, std::nullopt, state).ok());
    auto meshes = ref::world_meshes(**world, state, ref::make_scene_geometry(**world));
    ASSERT_TRUE(meshes.ok()) << meshes.message();
    glm::vec3 low(1e30f), high(-1e30f);
    for (const auto& mesh : *meshes)
      for (const glm::vec3& p : mesh.positions) {
        low = glm::min(low, p);
        high = glm::max(high, p);
      }
    const glm::vec3 extent = high - low;
    EXPECT_NEAR(std::max({extent.x, extent.y, extent.z}), 1.7f, 1e-3f) << chart.name;
    EXPECT_NEAR(low.y, 0.0f, 1e-3f) << chart.name;
    EXPECT_GT(chart.scene.output.frame_count, 1) << chart.name;
    for (int frame : chart.frames) EXPECT_LT(frame, chart.scene.output.frame_count) << chart.name;
  }
}

}  // namespace
}  // namespace proxygi::study
