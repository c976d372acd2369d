// The path tracer and the world agree: the reference's meshes at a state are the ground, then
// exactly World::pose_instance's primitives per instance (same order, bitwise positions), then
// the static meshes the world posed.
#include <cstring>
#include <filesystem>

#include <gtest/gtest.h>

#include "ref/scene_geometry.h"
#include "scene/scene_defaults.h"
#include "world/world.h"

namespace proxygi::world {
namespace {

const std::filesystem::path kAssets = PROXYGI_SOURCE_DIR "/assets";

template <class T>
bool same_bytes(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

void expect_reference_matches_world(const scene::Scene& scene, double t) {
  auto world = World::load(scene, {.assets_dir = kAssets, .load_rigs = false, .write_rig_cache = false});
  ASSERT_TRUE(world.ok()) << world.message();
  WorldState state;
  ASSERT_TRUE((*world)->evaluate(t, std::nullopt, state).ok());
  const ref::SceneGeometry geometry = ref::make_scene_geometry(**world);
  auto meshes = ref::world_meshes(**world, state, geometry);
  ASSERT_TRUE(meshes.ok()) << meshes.message();

  std::size_t next = 0;
  if (scene.ground.enabled) {
    ASSERT_GT(meshes->size(), 0u);
    EXPECT_EQ((*meshes)[next].name, "ground");
    EXPECT_EQ((*meshes)[next].material.albedo, scene.ground.albedo);
    ++next;
  }
  for (std::size_t i = 0; i < (*world)->instances().size(); ++i) {
    auto primitives = (*world)->pose_instance(state, i);
    ASSERT_TRUE(primitives.ok()) << primitives.message();
    const anim::Character& character = (*world)->instances()[i].model->character;
    for (const anim::PosedPrimitive& primitive : *primitives) {
      ASSERT_LT(next, meshes->size());
      const ref::TriangleMesh& mesh = (*meshes)[next++];
      EXPECT_EQ(mesh.name, character.source + ":" + primitive.name) << "instance " << i;
      EXPECT_TRUE(same_bytes(mesh.positions, primitive.positions)) << mesh.name << " of instance " << i;
      EXPECT_TRUE(same_bytes(mesh.normals, primitive.normals)) << mesh.name << " of instance " << i;
      EXPECT_EQ(mesh.indices, primitive.indices) << mesh.name << " of instance " << i;
      ASSERT_GE(primitive.material, 0);
      EXPECT_EQ(mesh.material.albedo,
                glm::vec3(character.materials[std::size_t(primitive.material)].base_color_factor));
    }
  }
  for (const StaticModel& model : (*world)->static_models())
    for (const anim::PosedPrimitive& primitive : model.primitives) {
      ASSERT_LT(next, meshes->size());
      const ref::TriangleMesh& mesh = (*meshes)[next++];
      EXPECT_TRUE(same_bytes(mesh.positions, primitive.positions)) << mesh.name;
      if (model.albedo) {
        EXPECT_EQ(mesh.material.albedo, *model.albedo) << mesh.name;
        EXPECT_EQ(mesh.material.texture, nullptr) << mesh.name;
      }
    }
  EXPECT_EQ(next, meshes->size());
}

TEST(WorldReference, DefaultSceneMeshesArePoseInstances) { expect_reference_matches_world(scene::default_scene(), 1.3); }

TEST(WorldReference, CrowdMeshesFollowInstanceOrder) { expect_reference_matches_world(scene::crowd_scene(), 2.7); }

TEST(WorldReference, StaticMeshWithAlbedoOverride) {
  scene::Scene scene = scene::default_scene();
  scene::StaticMesh prop;
  prop.model = (kAssets / "mannequin.glb").string();
  prop.transform.translation = glm::vec3(-3.0f, 0.0f, 1.0f);
  prop.albedo = glm::vec3(0.25f, 0.5f, 0.75f);
  scene.static_meshes = {prop};
  expect_reference_matches_world(scene, 0.5);
}

TEST(WorldReference, GeometryFromAnotherWorldIsRefused) {
  auto world = World::load(scene::default_scene(), {.assets_dir = kAssets, .load_rigs = false});
  ASSERT_TRUE(world.ok()) << world.message();
  WorldState state;
  ASSERT_TRUE((*world)->evaluate(0.0, std::nullopt, state).ok());
  const ref::SceneGeometry empty;
  EXPECT_FALSE(ref::world_meshes(**world, state, empty).ok());
}

}  // namespace
}  // namespace proxygi::world
