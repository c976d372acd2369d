// The world: loading (models shared by file, clips, rigs, static meshes, the mannequin built in
// code), evaluation (deterministic, order-independent, camera override), proxies following the
// pose, and the environment cache.
#include "world/world.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

#include "proxies/rig_file.h"
#include "scene/camera.h"
#include "scene/scene_defaults.h"

namespace proxygi::world {
namespace {

const std::filesystem::path kAssets = PROXYGI_SOURCE_DIR "/assets";

// No rig cache is written next to the committed assets by a test.
WorldOptions test_options(bool load_rigs = true) {
  return {.assets_dir = kAssets, .load_rigs = load_rigs, .write_rig_cache = false};
}

template <class T>
bool same_bytes(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

bool same_camera(const scene::CameraState& a, const scene::CameraState& b) {
  return a.eye == b.eye && a.target == b.target && a.up == b.up && a.fov_y_degrees == b.fov_y_degrees &&
         a.near_m == b.near_m && a.far_m == b.far_m;
}

// Bitwise equality of everything evaluate writes.
void expect_same_state(const WorldState& a, const WorldState& b) {
  EXPECT_EQ(a.time_s, b.time_s);
  ASSERT_EQ(a.instances.size(), b.instances.size());
  for (std::size_t i = 0; i < a.instances.size(); ++i) {
    const anim::PoseBuffers &pa = a.instances[i].pose, &pb = b.instances[i].pose;
    EXPECT_TRUE(same_bytes(pa.world, pb.world)) << "instance " << i;
    EXPECT_TRUE(same_bytes(pa.morph_weights, pb.morph_weights)) << "instance " << i;
    ASSERT_EQ(pa.skin_matrices.size(), pb.skin_matrices.size());
    for (std::size_t s = 0; s < pa.skin_matrices.size(); ++s) {
      EXPECT_TRUE(same_bytes(pa.skin_matrices[s], pb.skin_matrices[s])) << "instance " << i << " skin " << s;
      EXPECT_TRUE(same_bytes(pa.normal_matrices[s], pb.normal_matrices[s])) << "instance " << i << " skin " << s;
    }
    EXPECT_TRUE(same_bytes(a.instances[i].spheres, b.instances[i].spheres)) << "instance " << i;
  }
  ASSERT_EQ(a.spheres.size(), b.spheres.size());
  EXPECT_TRUE(a.spheres.empty() ||
              std::memcmp(a.spheres.data(), b.spheres.data(), a.spheres.size() * sizeof(render::Sphere)) == 0);
  EXPECT_TRUE(same_camera(a.camera, b.camera));
}

TEST(World, LoadsTheDefaultScene) {
  const scene::Scene scene = scene::default_scene();
  auto world = World::load(scene, test_options());
  ASSERT_TRUE(world.ok()) << world.message();
  ASSERT_EQ((*world)->models().size(), 1u);
  ASSERT_EQ((*world)->instances().size(), scene.characters.size());
  const Model& model = *(*world)->models()[0];
  EXPECT_EQ(model.file, kAssets / "mannequin.glb");
  EXPECT_FALSE(model.built_in_code);
  const CharacterInstance& walker = (*world)->instances()[0];
  EXPECT_EQ(walker.model, &model);
  EXPECT_EQ(walker.model_index, 0u);
  auto walk = anim::find_clip(model.character, "walk");
  ASSERT_TRUE(walk.ok()) << walk.message();
  EXPECT_EQ(walker.clip, *walk);
  EXPECT_FALSE(model.rig.spheres.empty());
  EXPECT_EQ(model.tracking.spheres.size(), model.rig.spheres.size());
  EXPECT_EQ((*world)->proxy_count(), model.rig.spheres.size());
  EXPECT_TRUE((*world)->static_models().empty());
}

TEST(World, CrowdSharesModelsByFile) {
  const scene::Scene scene = scene::crowd_scene();
  auto world = World::load(scene, test_options());
  ASSERT_TRUE(world.ok()) << world.message();
  const World& w = **world;
  ASSERT_EQ(w.instances().size(), scene.characters.size());
  EXPECT_LT(w.models().size(), w.instances().size());
  EXPECT_EQ(w.models().size(), 1u);  // twenty mannequins, one file
  std::size_t spheres = 0;
  for (std::size_t i = 0; i < w.instances().size(); ++i) {
    const CharacterInstance& instance = w.instances()[i];
    EXPECT_EQ(instance.scene_character, i);
    ASSERT_LT(instance.model_index, w.models().size());
    EXPECT_EQ(instance.model, w.models()[instance.model_index].get());
    spheres += instance.model->rig.spheres.size();
  }
  EXPECT_EQ(w.proxy_count(), spheres);
  WorldState state;
  ASSERT_TRUE(w.evaluate(2.0, std::nullopt, state).ok());
  EXPECT_EQ(state.spheres.size(), w.proxy_count());
}

TEST(World, EvaluateIsDeterministicAndIndependentOfOrder) {
  auto world = World::load(scene::crowd_scene(), test_options());
  ASSERT_TRUE(world.ok()) << world.message();
  WorldState fresh, reused;
  ASSERT_TRUE((*world)->evaluate(1.0, std::nullopt, fresh).ok());
  ASSERT_TRUE((*world)->evaluate(2.0, std::nullopt, reused).ok());
  ASSERT_TRUE((*world)->evaluate(1.0, std::nullopt, reused).ok());
  expect_same_state(fresh, reused);
  // A second world of the same scene agrees too (nothing depends on load order or history).
  auto again = World::load(scene::crowd_scene(), test_options());
  ASSERT_TRUE(again.ok()) << again.message();
  WorldState other;
  ASSERT_TRUE((*again)->evaluate(1.0, std::nullopt, other).ok());
  expect_same_state(fresh, other);
}

TEST(World, CameraIsTheOverrideOrTheScenesCamera) {
  const scene::Scene scene = scene::crowd_scene();  // an orbiting camera: it moves with time
  auto world = World::load(scene, test_options(false));
  ASSERT_TRUE(world.ok()) << world.message();
  WorldState state;
  for (double t : {0.0, 1.5, 3.25}) {
    ASSERT_TRUE((*world)->evaluate(t, std::nullopt, state).ok());
    EXPECT_TRUE(same_camera(state.camera, scene::evaluate_scene_camera(scene, t))) << "t = " << t;
  }
  scene::CameraState override_camera;
  override_camera.eye = glm::vec3(3.0f, 2.0f, -7.5f);
  override_camera.target = glm::vec3(0.5f, 0.25f, 1.0f);
  override_camera.up = glm::vec3(0.0f, 0.0f, 1.0f);
  override_camera.fov_y_degrees = 31.0f;
  override_camera.near_m = 0.2f;
  override_camera.far_m = 55.0f;
  ASSERT_TRUE((*world)->evaluate(1.5, override_camera, state).ok());
  EXPECT_TRUE(same_camera(state.camera, override_camera));
  EXPECT_FALSE(same_camera(state.camera, scene::evaluate_scene_camera(scene, 1.5)));
}

TEST(World, ProxiesFollowThePose) {
  auto world = World::load(scene::default_scene(), test_options());
  ASSERT_TRUE(world.ok()) << world.message();
  const World& w = **world;
  const std::size_t rig_spheres = w.models()[0]->rig.spheres.size();
  ASSERT_GT(rig_spheres, 0u);
  WorldState early, late;
  ASSERT_TRUE(w.evaluate(0.25, std::nullopt, early).ok());
  ASSERT_TRUE(w.evaluate(0.75, std::nullopt, late).ok());
  for (const WorldState* state : {&early, &late}) {
    ASSERT_EQ(state->instances[0].spheres.size(), rig_spheres);
    ASSERT_EQ(state->spheres.size(), rig_spheres);
    // The flat list is the instance's spheres in order; every sphere sits on the posed body:
    // its center within the skinned mesh's bounds grown by its radius.
    auto primitives = w.pose_instance(*state, 0);
    ASSERT_TRUE(primitives.ok()) << primitives.message();
    glm::vec3 low(std::numeric_limits<float>::max()), high(-std::numeric_limits<float>::max());
    for (const auto& primitive : *primitives)
      for (const glm::vec3& p : primitive.positions) {
        low = glm::min(low, p);
        high = glm::max(high, p);
      }
    for (std::size_t i = 0; i < rig_spheres; ++i) {
      const proxies::WorldSphere& tracked = state->instances[0].spheres[i];
      const render::Sphere& listed = state->spheres[i];
      EXPECT_EQ(listed.center, tracked.center);
      EXPECT_EQ(listed.radius, tracked.radius);
      EXPECT_EQ(listed.albedo, tracked.albedo);
      EXPECT_GT(tracked.radius, 0.0f);
      EXPECT_TRUE(glm::all(glm::greaterThanEqual(tracked.center, low - tracked.radius)) &&
                  glm::all(glm::lessThanEqual(tracked.center, high + tracked.radius)))
          << "sphere " << i << " is off the body";
    }
  }
  // Half a walk cycle apart (and half a metre along the path) the proxies have moved.
  EXPECT_FALSE(same_bytes(early.instances[0].spheres, late.instances[0].spheres));
  float largest_move = 0.0f;
  for (std::size_t i = 0; i < rig_spheres; ++i)
    largest_move = std::max(largest_move, glm::length(late.spheres[i].center - early.spheres[i].center));
  EXPECT_GT(largest_move, 0.1f);
}

TEST(World, WithoutRigsThereAreNoProxies) {
  auto world = World::load(scene::default_scene(), test_options(false));
  ASSERT_TRUE(world.ok()) << world.message();
  EXPECT_TRUE((*world)->models()[0]->rig.spheres.empty());
  EXPECT_EQ((*world)->proxy_count(), 0u);
  WorldState state;
  ASSERT_TRUE((*world)->evaluate(1.0, std::nullopt, state).ok());
  ASSERT_EQ(state.instances.size(), 1u);
  EXPECT_TRUE(state.instances[0].spheres.empty());
  EXPECT_TRUE(state.spheres.empty());
  EXPECT_FALSE(state.instances[0].pose.skin_matrices.empty());
}

TEST(World, ClipIndexOutOfRangeFailsNamingTheField) {
  scene::Scene scene = scene::crowd_scene();
  scene.characters[3].clip = 99;
  auto world = World::load(scene, test_options(false));
  ASSERT_FALSE(world.ok());
  EXPECT_NE(world.message().find("characters[3].clip"), std::string::npos) << world.message();
  EXPECT_NE(world.message().find("99"), std::string::npos) << world.message();
  scene.characters[3].clip = -1;
  world = World::load(scene, test_options(false));
  ASSERT_FALSE(world.ok());
  EXPECT_NE(world.message().find("characters[3].clip"), std::string::npos) << world.message();
}

TEST(World, UnknownClipNameFailsNamingTheField) {
  scene::Scene scene = scene::crowd_scene();
  scene.characters[1].clip = std::string("moonwalk");
  auto world = World::load(scene, test_options(false));
  ASSERT_FALSE(world.ok());
  EXPECT_NE(world.message().find("characters[1].clip"), std::string::npos) << world.message();
  EXPECT_NE(world.message().find("moonwalk"), std::string::npos) << world.message();
}

TEST(World, MissingModelFailsNamingTheCharacter) {
  scene::Scene scene = scene::default_scene();
  scene.characters[0].model = "no-such-model.glb";
  auto world = World::load(scene, test_options(false));
  ASSERT_FALSE(world.ok());
  EXPECT_NE(world.message().find("characters[0]"), std::string::npos) << world.message();
  EXPECT_NE(world.message().find("no-such-model.glb"), std::string::npos) << world.message();
}

// A fresh, empty folder under the test output directory.
std::filesystem::path empty_folder(const std::string& name) {
  const std::filesystem::path folder = std::filesystem::path(PROXYGI_TEST_OUTPUT_DIR) / name;
  std::filesystem::remove_all(folder);
  std::filesystem::create_directories(folder);
  return folder;
}

TEST(World, MannequinIsBuiltInCodeWhenTheAssetsFolderLacksIt) {
  const scene::Scene scene = scene::default_scene();
  const std::filesystem::path empty = empty_folder("world-empty-assets");
  auto built = World::load(scene, {.assets_dir = empty, .load_rigs = false, .write_rig_cache = false});
  ASSERT_TRUE(built.ok()) << built.message();
  auto loaded = World::load(scene, test_options(false));
  ASSERT_TRUE(loaded.ok()) << loaded.message();
  EXPECT_TRUE((*built)->models()[0]->built_in_code);
  EXPECT_EQ((*built)->models()[0]->file, empty / "mannequin.glb");
  EXPECT_EQ((*built)->instances()[0].clip, (*loaded)->instances()[0].clip);
  // The same figure as the asset file, posed the same up to the importer's renormalization of
  // weights and normals (1-ulp changes, anim/ mannequin_test): under a micrometre on a 1.8 m figure.
  WorldState a, b;
  ASSERT_TRUE((*built)->evaluate(0.6, std::nullopt, a).ok());
  ASSERT_TRUE((*loaded)->evaluate(0.6, std::nullopt, b).ok());
  auto pa = (*built)->pose_instance(a, 0);
  auto pb = (*loaded)->pose_instance(b, 0);
  ASSERT_TRUE(pa.ok() && pb.ok());
  ASSERT_EQ(pa->size(), pb->size());
  float largest = 0.0f;
  for (std::size_t i = 0; i < pa->size(); ++i) {
    ASSERT_EQ((*pa)[i].positions.size(), (*pb)[i].positions.size()) << i;
    for (std::size_t v = 0; v < (*pa)[i].positions.size(); ++v)
      largest = std::max(largest, glm::distance((*pa)[i].positions[v], (*pb)[i].positions[v]));
  }
  std::printf("built vs imported mannequin: largest vertex distance %g m\n", double(largest));
  EXPECT_LT(largest, 1e-6f);
}

TEST(World, BuiltMannequinUsesTheAssetFilesRigCache) {
  // The built figure hashes as the asset file's bytes, so the committed rig is a cache hit for it.
  auto asset_hash = proxies::hash_file(kAssets / "mannequin.glb");
  ASSERT_TRUE(asset_hash.ok()) << asset_hash.message();
  const std::filesystem::path folder = empty_folder("world-rig-only");
  std::filesystem::copy_file(kAssets / "mannequin.proxies.json", folder / "mannequin.proxies.json");
  const scene::Scene scene = scene::default_scene();
  auto built = World::load(scene, {.assets_dir = folder, .load_rigs = true, .write_rig_cache = false});
  ASSERT_TRUE(built.ok()) << built.message();
  auto loaded = World::load(scene, test_options());
  ASSERT_TRUE(loaded.ok()) << loaded.message();
  const proxies::ProxyRig &a = (*built)->models()[0]->rig, &b = (*loaded)->models()[0]->rig;
  EXPECT_EQ(a.model_hash, *asset_hash);
  ASSERT_EQ(a.spheres.size(), b.spheres.size());
  for (std::size_t i = 0; i < a.spheres.size(); ++i) {
    EXPECT_EQ(a.spheres[i].center, b.spheres[i].center) << "sphere " << i;
    EXPECT_EQ(a.spheres[i].radius, b.spheres[i].radius) << "sphere " << i;
  }
  // Tracked, they agree up to the same renormalization as the meshes.
  WorldState sa, sb;
  ASSERT_TRUE((*built)->evaluate(0.4, std::nullopt, sa).ok());
  ASSERT_TRUE((*loaded)->evaluate(0.4, std::nullopt, sb).ok());
  ASSERT_EQ(sa.spheres.size(), sb.spheres.size());
  float largest = 0.0f;
  for (std::size_t i = 0; i < sa.spheres.size(); ++i)
    largest = std::max({largest, glm::distance(sa.spheres[i].center, sb.spheres[i].center),
                        std::abs(sa.spheres[i].radius - sb.spheres[i].radius)});
  std::printf("built vs imported mannequin: largest sphere difference %g m\n", double(largest));
  EXPECT_LT(largest, 1e-6f);
}

TEST(World, StaticMeshesArePosedOnceUnderTheirTransform) {
  scene::Scene scene = scene::default_scene();
  scene::StaticMesh crate;
  crate.model = (kAssets / "mannequin.glb").string();
  crate.transform.translation = glm::vec3(4.0f, 0.0f, -2.0f);
  crate.albedo = glm::vec3(0.1f, 0.2f, 0.3f);
  scene.static_meshes = {crate};
  auto world = World::load(scene, test_options(false));
  ASSERT_TRUE(world.ok()) << world.message();
  ASSERT_EQ((*world)->static_models().size(), 1u);
  const StaticModel& model = (*world)->static_models()[0];
  EXPECT_EQ(model.scene_static_mesh, 0u);
  ASSERT_TRUE(model.albedo.has_value());
  EXPECT_EQ(*model.albedo, *crate.albedo);
  ASSERT_FALSE(model.primitives.empty());
  // The rest-pose mannequin stands on y = 0, centered near x = 0, z = 0: moved by the transform.
  glm::vec3 low(std::numeric_limits<float>::max()), high(-std::numeric_limits<float>::max());
  for (const auto& primitive : model.primitives)
    for (const glm::vec3& p : primitive.positions) {
      low = glm::min(low, p);
      high = glm::max(high, p);
    }
  EXPECT_NEAR(low.y, 0.0f, 1e-4f);
  EXPECT_NEAR(high.y, 1.8f, 0.02f);
  EXPECT_NEAR(0.5f * (low.x + high.x), 4.0f, 0.2f);
  EXPECT_NEAR(0.5f * (low.z + high.z), -2.0f, 0.2f);

  scene.static_meshes[0].model = "missing-prop.glb";
  auto broken = World::load(scene, test_options(false));
  ASSERT_FALSE(broken.ok());
  EXPECT_NE(broken.message().find("static_meshes[0]"), std::string::npos) << broken.message();
}

TEST(World, PoseInstanceChecksItsArguments) {
  auto world = World::load(scene::default_scene(), test_options(false));
  ASSERT_TRUE(world.ok()) << world.message();
  WorldState state;
  EXPECT_FALSE((*world)->pose_instance(state, 0).ok());  // not evaluated
  ASSERT_TRUE((*world)->evaluate(0.0, std::nullopt, state).ok());
  EXPECT_TRUE((*world)->pose_instance(state, 0).ok());
  auto out_of_range = (*world)->pose_instance(state, 1);
  ASSERT_FALSE(out_of_range.ok());
  EXPECT_NE(out_of_range.message().find("instance 1"), std::string::npos) << out_of_range.message();
}

TEST(World, EnvironmentIsCachedPerOrder) {
  auto world = World::load(scene::default_scene(), test_options(false));
  ASSERT_TRUE(world.ok()) << world.message();
  auto four = (*world)->environment(4);
  ASSERT_TRUE(four.ok()) << four.message();
  auto again = (*world)->environment(4);
  ASSERT_TRUE(again.ok()) << again.message();
  EXPECT_EQ(*four, *again);
  auto six = (*world)->environment(6);
  ASSERT_TRUE(six.ok()) << six.message();
  EXPECT_NE(*four, *six);
  EXPECT_EQ((*four)->lighting.order, 4);
  EXPECT_EQ((*six)->lighting.order, 6);
  EXPECT_EQ((*four)->lighting.channels[0].size(), 16u);
  EXPECT_EQ((*six)->lighting.channels[0].size(), 36u);
  // What is kept is the scene's projection itself; the background does not depend on order.
  auto direct = render::make_environment_lighting((*world)->scene(), 4);
  ASSERT_TRUE(direct.ok()) << direct.message();
  for (std::size_t c = 0; c < 3; ++c) EXPECT_TRUE(same_bytes((*four)->lighting.channels[c], direct->lighting.channels[c])) << c;
  EXPECT_TRUE(same_bytes((*four)->background.pixels, (*six)->background.pixels));
  EXPECT_FALSE((*world)->environment(0).ok());
  EXPECT_FALSE((*world)->environment(9).ok());
}

}  // namespace
}  // namespace proxygi::world
