// The world with the shared sample characters (../shared/assets/gltf; skipped when absent):
// several files shared by several instances, clips by name and by index, and textured
// materials reaching the reference's meshes.
#include <filesystem>

#include <gtest/gtest.h>

#include "ref/scene_geometry.h"
#include "scene/scene_defaults.h"
#include "world/world.h"

namespace proxygi::world {
namespace {

const std::filesystem::path kGltf = std::filesystem::path(PROXYGI_SHARED_ASSETS_DIR) / "gltf";

scene::Character character(const char* file, scene::ClipRef clip, float x) {
  scene::Character c;
  c.model = (kGltf / file).string();
  c.clip = std::move(clip);
  c.transform.translation = glm::vec3(x, 0.0f, 0.0f);
  return c;
}

scene::Scene sample_scene() {
  scene::Scene scene = scene::default_scene();
  scene.characters = {character("Fox.glb", std::string("Walk"), -2.0f), character("CesiumMan.glb", 0, 0.0f),
                      character("Fox.glb", 1, 2.0f), character("RiggedSimple.glb", 0, 4.0f)};
  return scene;
}

bool have_samples() {
  for (const char* file : {"Fox.glb", "CesiumMan.glb", "RiggedSimple.glb"})
    if (!std::filesystem::exists(kGltf / file)) return false;
  return true;
}

TEST(WorldSharedAssets, FilesAreSharedAndClipsResolved) {
  if (!have_samples()) GTEST_SKIP() << kGltf << " is absent";
  auto world = World::load(sample_scene(), {.assets_dir = PROXYGI_SOURCE_DIR "/assets", .load_rigs = false});
  ASSERT_TRUE(world.ok()) << world.message();
  const World& w = **world;
  ASSERT_EQ(w.instances().size(), 4u);
  EXPECT_EQ(w.models().size(), 3u);
  EXPECT_EQ(w.instances()[0].model, w.instances()[2].model);
  EXPECT_NE(w.instances()[0].model, w.instances()[1].model);
  auto walk = anim::find_clip(w.instances()[0].model->character, "Walk");
  ASSERT_TRUE(walk.ok()) << walk.message();
  EXPECT_EQ(w.instances()[0].clip, *walk);
  EXPECT_EQ(w.instances()[1].clip, 0);
  EXPECT_EQ(w.instances()[2].clip, 1);

  WorldState state;
  ASSERT_TRUE(w.evaluate(0.5, std::nullopt, state).ok());
  auto meshes = ref::world_meshes(w, state, ref::make_scene_geometry(w));
  ASSERT_TRUE(meshes.ok()) << meshes.message();
  bool textured_cesium_man = false;
  for (const ref::TriangleMesh& mesh : *meshes)
    if (mesh.name.find("CesiumMan") != std::string::npos && mesh.material.texture) textured_cesium_man = true;
  EXPECT_TRUE(textured_cesium_man) << "CesiumMan's base color texture did not reach the reference";
}

TEST(WorldSharedAssets, BadClipsNameTheCharacter) {
  if (!have_samples()) GTEST_SKIP() << kGltf << " is absent";
  scene::Scene scene = sample_scene();
  scene.characters[2].clip = std::string("Moonwalk");
  auto named = World::load(scene, {.assets_dir = PROXYGI_SOURCE_DIR "/assets", .load_rigs = false});
  ASSERT_FALSE(named.ok());
  EXPECT_NE(named.message().find("characters[2].clip"), std::string::npos) << named.message();
  scene = sample_scene();
  scene.characters[1].clip = 7;  // CesiumMan has one clip
  auto indexed = World::load(scene, {.assets_dir = PROXYGI_SOURCE_DIR "/assets", .load_rigs = false});
  ASSERT_FALSE(indexed.ok());
  EXPECT_NE(indexed.message().find("characters[1].clip"), std::string::npos) << indexed.message();
  EXPECT_NE(indexed.message().find("out of range"), std::string::npos) << indexed.message();
}

}  // namespace
}  // namespace proxygi::world
