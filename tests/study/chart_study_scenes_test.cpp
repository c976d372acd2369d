// The bounce study's scenes: valid scene files, the wall a box the path tracer hits.
#include <gtest/gtest.h>

#include "ref/embree_scene.h"
#include "ref/scene_geometry.h"
#include "scene/camera.h"
#include "scene/scene_parse.h"
#include "scene/scene_validate.h"
#include "scene/scene_write.h"
#include "study/chart_scenes.h"
#include "world/world.h"

namespace proxygi::study {
namespace {

ChartSceneOptions study_options() {
  ChartSceneOptions options;
  options.size = 96;
  options.frame_count = 1;
  options.shared_dir = "/nonexistent";
  options.assets_dir = PROXYGI_SOURCE_DIR "/assets";
  options.rig_cache_dir = PROXYGI_TEST_OUTPUT_DIR "/chart-study-rigs";
  options.only = {"contact", "wall", "pair-distance", "crowd"};
  return options;
}

TEST(ChartStudyScenes, GroupsExpandToEveryDistance) {
  auto scenes = chart_scenes(study_options());
  ASSERT_TRUE(scenes.ok()) << scenes.message();
  std::vector<std::string> names;
  for (const ChartScene& chart : *scenes) names.push_back(chart.name);
  EXPECT_EQ(names, (std::vector<std::string>{"contact", "wall-0.5", "wall-1", "wall-2", "wall-4", "pair-0.5", "pair-1",
                                             "pair-2", "pair-5", "crowd"}));
  for (const ChartScene& chart : *scenes) {
    EXPECT_EQ(chart.scene.output.width, 96) << chart.name;
    EXPECT_EQ(chart.frames.size(), 1u) << chart.name;
  }
  const auto& pair = (*scenes)[8].scene.characters;
  ASSERT_EQ(pair.size(), 2u);
  EXPECT_FLOAT_EQ(pair[1].transform.translation.x - pair[0].transform.translation.x, 5.0f);
}

TEST(ChartStudyScenes, EveryStudySceneWritesAValidSceneFileThatLoads) {
  auto scenes = chart_scenes(study_options());
  ASSERT_TRUE(scenes.ok()) << scenes.message();
  for (const ChartScene& chart : *scenes) {
    ASSERT_TRUE(scene::validate_scene(chart.scene).ok()) << chart.name << ": " << scene::validate_scene(chart.scene).message();
    auto json = scene::to_json(chart.scene);
    ASSERT_TRUE(json.ok()) << chart.name << ": " << json.message();
    auto parsed = scene::parse_scene(*json, PROXYGI_TEST_OUTPUT_DIR "/" + chart.name + ".json");
    ASSERT_TRUE(parsed.ok()) << chart.name << ": " << parsed.message();
    EXPECT_EQ(*scene::to_json(*parsed), *json) << chart.name;
    auto world = world::World::load(*parsed, {.assets_dir = PROXYGI_SOURCE_DIR "/assets", .load_rigs = false});
    ASSERT_TRUE(world.ok()) << chart.name << ": " << world.message();
    EXPECT_EQ((*world)->static_models().size(), chart.name.rfind("wall-", 0) == 0 ? 1u : 0u) << chart.name;
  }
}

TEST(ChartStudyScenes, ThePathTracerHitsTheWallAtItsDistance) {
  ChartSceneOptions options = study_options();
  options.only = {"wall-1", "wall-4"};
  auto scenes = chart_scenes(options);
  ASSERT_TRUE(scenes.ok()) << scenes.message();
  ASSERT_EQ(scenes->size(), 2u);
  for (const ChartScene& chart : *scenes) {
    const float d = chart.name == "wall-1" ? 1.0f : 4.0f;
    auto world = world::World::load(chart.scene, {.assets_dir = options.assets_dir, .load_rigs = false});
    ASSERT_TRUE(world.ok()) << world.message();
    world::WorldState state;
    ASSERT_TRUE((*world)->evaluate(scene::frame_time_s(chart.scene.output, chart.frames[0]), std::nullopt, state).ok());
    auto meshes = ref::world_meshes(**world, state, ref::make_scene_geometry(**world));
    ASSERT_TRUE(meshes.ok()) << meshes.message();
    auto embree = ref::EmbreeScene::build(std::move(*meshes));
    ASSERT_TRUE(embree.ok()) << embree.message();
    // Above the mannequin's head, toward -X: the wall's face at x = -d, gray, not a character.
    const auto hit = embree->intersect(glm::vec3(0.0f, 2.2f, 0.0f), glm::vec3(-1.0f, 0.0f, 0.0f));
    ASSERT_TRUE(hit.has_value()) << chart.name;
    EXPECT_NEAR(hit->distance, d, 1e-4f) << chart.name;
    EXPECT_NEAR(hit->geometric_normal.x, 1.0f, 1e-5f) << chart.name;
    EXPECT_FALSE(hit->character) << chart.name;
    EXPECT_NEAR(hit->albedo.g, 0.8f, 1e-6f) << chart.name;
    // The camera sees the wall: some pixel-centre ray hits it.
    const scene::CameraState camera = scene::evaluate_scene_camera(chart.scene, 0.0);
    int wall_pixels = 0;
    for (int y = 0; y < 32; ++y)
      for (int x = 0; x < 32; ++x) {
        const scene::Ray ray = scene::ray_through_pixel(camera, 32, 32, float(x) + 0.5f, float(y) + 0.5f);
        const auto seen = embree->intersect(ray.origin, ray.direction);
        if (seen && std::abs(seen->position.x + d) < 1e-3f) ++wall_pixels;
      }
    EXPECT_GT(wall_pixels, 32) << chart.name;
  }
}

TEST(ChartStudyScenes, WallCornerIsTheProjectsPrtScene) {
  ChartSceneOptions options = study_options();
  options.only = {"wall-corner"};
  auto scenes = chart_scenes(options);
  ASSERT_TRUE(scenes.ok()) << scenes.message();
  ASSERT_EQ(scenes->size(), 1u);
  EXPECT_EQ((*scenes)[0].name, "wall-corner");
  EXPECT_FALSE((*scenes)[0].scene.static_meshes.empty()) << "the walls and steps";
  EXPECT_EQ((*scenes)[0].scene.output.width, 96);
  EXPECT_EQ((*scenes)[0].frames.size(), 1u);
}

}  // namespace
}  // namespace proxygi::study
