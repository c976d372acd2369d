// Rigs as the world obtains them (world::obtain_rig, proxies/rig_cache.h): skeletons with unnamed
// and duplicate-named bones render the same from a fresh fit and from the cache file (spheres bound
// by node index), a rig the scene names is used as it is, and a read-only model folder caches the
// rig in the user cache folder.
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <functional>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "anim/gltf_import.h"
#include "anim/gltf_writer.h"
#include "anim/mannequin.h"
#include "proxies/rig_cache.h"
#include "proxies/rig_file.h"
#include "scene/scene_defaults.h"
#include "world/model_stage.h"
#include "world/world.h"
#include "scene/camera.h"

namespace proxygi::world {
namespace {

std::filesystem::path fresh_folder(const std::string& name) {
  const std::filesystem::path folder = std::filesystem::path(PROXYGI_TEST_OUTPUT_DIR) / name;
  std::error_code ignored;
  std::filesystem::permissions(folder, std::filesystem::perms::owner_all, std::filesystem::perm_options::add, ignored);
  std::filesystem::remove_all(folder, ignored);
  std::filesystem::create_directories(folder);
  return folder;
}

int node_named(const anim::Character& ch, const std::string& name) {
  for (std::size_t n = 0; n < ch.nodes.size(); ++n)
    if (ch.nodes[n].name == name) return int(n);
  return -1;
}

// The default scene (mannequin walking) with its model replaced by `model`.
scene::Scene scene_with(const std::filesystem::path& model) {
  scene::Scene scene = scene::default_scene();
  scene.characters[0].model = model.string();
  return scene;
}

WorldOptions options(bool write = true) { return {.assets_dir = PROXYGI_SOURCE_DIR "/assets", .write_rig_cache = write}; }

// Sphere world centers of the only character at time t.
std::vector<render::Sphere> spheres_at(const World& world, double t) {
  WorldState state;
  EXPECT_TRUE(world.evaluate(t, std::nullopt, state).ok());
  return state.spheres;
}

// The feet's spheres follow the feet: every sphere on a foot node sits within 0.25 m of that
// foot joint, and the lowest sphere of the body is on a foot or toe node.
void expect_spheres_on_the_feet(const World& world, const std::vector<int>& feet, double t) {
  WorldState state;
  ASSERT_TRUE(world.evaluate(t, std::nullopt, state).ok());
  const proxies::ProxyRig& rig = world.models()[0]->rig;
  ASSERT_EQ(state.spheres.size(), rig.spheres.size());
  int lowest = 0, on_feet = 0;
  for (std::size_t i = 0; i < rig.spheres.size(); ++i) {
    if (state.spheres[i].center.y < state.spheres[std::size_t(lowest)].center.y) lowest = int(i);
    const int node = rig.spheres[i].node;
    if (std::find(feet.begin(), feet.end(), node) == feet.end()) continue;
    ++on_feet;
    const glm::vec3 joint = glm::vec3(state.instances[0].pose.world[std::size_t(node)][3]);
    EXPECT_LT(glm::distance(state.spheres[i].center, joint), 0.25f) << "sphere " << i << " at t=" << t;
  }
  EXPECT_GE(on_feet, 2);
  const int lowest_node = rig.spheres[std::size_t(lowest)].node;
  EXPECT_NE(std::find(feet.begin(), feet.end(), lowest_node), feet.end()) << "lowest sphere on node " << lowest_node;
}

// Renames the mannequin's nodes with `rename`, writes it as a GLB, and checks that the rig fitted
// to it (first load, written to the cache) and the rig read back from the cache file (second
// load) track like the named mannequin's, with the feet's spheres under the feet.
void check_renamed_mannequin(const std::string& label, const std::function<std::string(const std::string&)>& rename) {
  const anim::Character named = anim::build_mannequin();
  std::vector<int> feet;
  for (const char* foot : {"left_foot", "left_toes", "right_foot", "right_toes"}) feet.push_back(node_named(named, foot));
  anim::Character renamed = named;
  for (anim::Node& node : renamed.nodes) node.name = rename(node.name);
  const std::filesystem::path folder = fresh_folder("world-rig-" + label);
  const std::filesystem::path model = folder / "figure.glb";
  ASSERT_TRUE(anim::write_glb(renamed, model).ok());
  EXPECT_FALSE(proxies::node_name_warnings(*anim::import_gltf(model)).empty()) << label;

  auto reference = World::load(scene::default_scene(), options(false));  // the named mannequin
  ASSERT_TRUE(reference.ok()) << reference.message();
  auto fitted = World::load(scene_with(model), options());
  ASSERT_TRUE(fitted.ok()) << fitted.message();
  ASSERT_TRUE(std::filesystem::exists(folder / "figure.proxies.json"));
  auto cached = World::load(scene_with(model), options());
  ASSERT_TRUE(cached.ok()) << cached.message();
  const proxies::ProxyRig& from_file = (*cached)->models()[0]->rig;
  ASSERT_EQ(from_file.spheres.size(), (*fitted)->models()[0]->rig.spheres.size());
  for (std::size_t i = 0; i < from_file.spheres.size(); ++i) {
    EXPECT_EQ(from_file.spheres[i].node, (*fitted)->models()[0]->rig.spheres[i].node) << "sphere " << i;
    EXPECT_EQ(from_file.spheres[i].weight_nodes, (*fitted)->models()[0]->rig.spheres[i].weight_nodes) << "sphere " << i;
  }
  for (double t : {0.0, 0.3, 0.7, 1.1}) {
    const auto a = spheres_at(**reference, t), b = spheres_at(**fitted, t), c = spheres_at(**cached, t);
    ASSERT_EQ(a.size(), b.size());
    ASSERT_EQ(a.size(), c.size());
    float fit_vs_named = 0.0f, cache_vs_fit = 0.0f;
    for (std::size_t i = 0; i < a.size(); ++i) {
      fit_vs_named = std::max(fit_vs_named, glm::distance(a[i].center, b[i].center));
      cache_vs_fit = std::max(cache_vs_fit, glm::distance(b[i].center, c[i].center));
    }
    EXPECT_LT(fit_vs_named, 1e-3f) << label << " t=" << t;   // names do not change the fit
    EXPECT_LT(cache_vs_fit, 1e-4f) << label << " t=" << t;   // the file keeps 7 digits
    expect_spheres_on_the_feet(**fitted, feet, t);
    expect_spheres_on_the_feet(**cached, feet, t);
  }
}

TEST(WorldRig, UnnamedBonesTrackTheSameFromTheFitAndFromTheCacheFile) {
  check_renamed_mannequin("unnamed", [](const std::string&) { return std::string(); });
}

TEST(WorldRig, DuplicateBoneNamesTrackTheSameFromTheFitAndFromTheCacheFile) {
  // left_foot and right_foot both become "foot", and so on; the rest become "bone".
  check_renamed_mannequin("duplicate", [](const std::string& name) {
    for (const char* side : {"left_", "right_"})
      if (name.rfind(side, 0) == 0) return name.substr(std::string(side).size());
    return std::string("bone");
  });
}

// A rig fitted by the user with a non-default tolerance, named in the scene, survives loading.
TEST(WorldRig, AUserRigWithItsOwnToleranceIsUsedAsItIs) {
  const std::filesystem::path folder = fresh_folder("world-rig-user");
  const std::filesystem::path model = folder / "figure.glb";
  ASSERT_TRUE(anim::write_glb(anim::build_mannequin(), model).ok());
  const std::filesystem::path rig_file = folder / "my.proxies.json";
  proxies::RigRequest request;
  request.rig_file = rig_file;
  request.user_file = true;
  request.model_name = "figure.glb";
  request.model_hash = *proxies::hash_file(model);
  request.options.tolerance = 0.02f;
  auto made = proxies::load_or_fit_rig(anim::build_mannequin(), request);
  ASSERT_TRUE(made.ok()) << made.message();
  const auto before = std::filesystem::last_write_time(rig_file);

  scene::Scene scene = scene_with(model);
  scene.characters[0].proxies = rig_file.string();
  auto world = World::load(scene, options());
  ASSERT_TRUE(world.ok()) << world.message();
  EXPECT_EQ((*world)->models()[0]->rig.tolerance, 0.02f);
  EXPECT_EQ((*world)->models()[0]->rig.spheres.size(), made->rig.spheres.size());
  EXPECT_EQ(std::filesystem::last_write_time(rig_file), before);
  EXPECT_FALSE(std::filesystem::exists(folder / "figure.proxies.json"));

  // The model changes: the user's rig is refitted in memory and the file is left alone...
  anim::Character moved = anim::build_mannequin();
  moved.nodes[0].rest.translation.x += 0.01f;
  ASSERT_TRUE(anim::write_glb(moved, model).ok());
  world = World::load(scene, options());
  ASSERT_TRUE(world.ok()) << world.message();
  EXPECT_EQ(std::filesystem::last_write_time(rig_file), before);
  // ...unless --refit.
  auto refit_options = options();
  refit_options.refit = true;
  world = World::load(scene, refit_options);
  ASSERT_TRUE(world.ok()) << world.message();
  EXPECT_EQ(proxies::read_rig(rig_file, moved)->model_hash, *proxies::hash_file(model));
}

// The scene's proxy_tolerance and proxy_max_spheres decide the cached rig.
TEST(WorldRig, SceneFitSettingsDecideTheCachedRig) {
  const std::filesystem::path folder = fresh_folder("world-rig-settings");
  const std::filesystem::path model = folder / "figure.glb";
  ASSERT_TRUE(anim::write_glb(anim::build_mannequin(), model).ok());
  scene::Scene scene = scene_with(model);
  scene.characters[0].proxy_tolerance = 0.1f;
  scene.characters[0].proxy_max_spheres = 24;
  auto world = World::load(scene, options());
  ASSERT_TRUE(world.ok()) << world.message();
  EXPECT_EQ((*world)->models()[0]->rig.tolerance, 0.1f);
  EXPECT_EQ((*world)->models()[0]->rig.max_spheres, 24);
  EXPECT_LE((*world)->models()[0]->rig.spheres.size(), 24u);
  auto cached = proxies::read_rig(folder / "figure.proxies.json", anim::build_mannequin());
  ASSERT_TRUE(cached.ok()) << cached.message();
  EXPECT_EQ(cached->max_spheres, 24);
}

// A model in a folder the process cannot write: the rig goes to $XDG_CACHE_HOME/proxygi. Needs a
// folder that is really read-only for this process (as root, permissions do not stop writes).
TEST(WorldRig, AReadOnlyModelFolderCachesTheRigInTheUserCache) {
  const std::filesystem::path folder = fresh_folder("world-rig-readonly");
  const std::filesystem::path models = folder / "models";
  const std::filesystem::path cache = folder / "cache";
  std::filesystem::create_directories(models);
  const std::filesystem::path model = models / "figure.glb";
  ASSERT_TRUE(anim::write_glb(anim::build_mannequin(), model).ok());
  std::filesystem::permissions(models, std::filesystem::perms::owner_read | std::filesystem::perms::owner_exec);
  if (::access(models.c_str(), W_OK) == 0) {
    std::filesystem::permissions(models, std::filesystem::perms::owner_all);
    GTEST_SKIP() << "running as root: a mode-0500 folder is still writable (tests/cli covers this as a non-root user)";
  }
  ::setenv("XDG_CACHE_HOME", cache.c_str(), 1);
  auto world = World::load(scene_with(model), options());
  ::unsetenv("XDG_CACHE_HOME");
  std::filesystem::permissions(models, std::filesystem::perms::owner_all);
  ASSERT_TRUE(world.ok()) << world.message();
  EXPECT_FALSE(std::filesystem::exists(models / "figure.proxies.json"));
  int cached = 0;
  for (const auto& entry : std::filesystem::directory_iterator(cache / "proxygi")) cached += entry.path().string().ends_with(".proxies.json");
  EXPECT_EQ(cached, 1);
}

// `record MODEL.glb`: the model stands on the ground at its own size, and the camera sees its
// whole motion over the clip; the ground reaches the horizon.
TEST(ModelStage, PlacesTheModelOnTheGroundAndFramesItsClip) {
  const std::filesystem::path folder = fresh_folder("world-stage");
  anim::Character big = anim::build_mannequin();
  for (anim::Node& node : big.nodes)
    if (node.parent < 0) node.rest.scale *= 3.0f;  // a 5.4 m figure: framing follows its size
  ASSERT_TRUE(anim::write_glb(big, folder / "giant.glb").ok());
  for (const std::string& model : {std::string("builtin:mannequin"), (folder / "giant.glb").string()}) {
    auto scene = stage_scene(model, PROXYGI_SOURCE_DIR "/assets", {.clip = std::string("walk")});
    ASSERT_TRUE(scene.ok()) << scene.message();
    EXPECT_EQ(scene->characters[0].transform.scale, glm::vec3(1.0f)) << "own size";
    EXPECT_GE(scene->ground.size, 1000.0f);
    EXPECT_GT(scene->output.frame_count, 1);
    auto world = World::load(*scene, options(false));
    ASSERT_TRUE(world.ok()) << world.message();
    auto bounds = bounds_over_time(**world, 0.0, scene::frame_time_s(scene->output, scene->output.frame_count - 1), 12);
    ASSERT_TRUE(bounds.ok()) << bounds.message();
    EXPECT_NEAR(bounds->first.y, 0.0f, 1e-3f) << model << ": the lowest point over the clip is on the ground";
    const float height = bounds->second.y - bounds->first.y;
    EXPECT_GT(height, model.ends_with("giant.glb") ? 5.0f : 1.6f) << model;
    // Every corner of the motion's bounds projects inside the picture.
    WorldState state;
    ASSERT_TRUE((*world)->evaluate(0.0, std::nullopt, state).ok());
    const scene::CameraState& camera = state.camera;
    const float aspect = float(scene->output.width) / float(scene->output.height);
    const glm::mat4 view_projection = scene::projection_matrix(camera, aspect) * scene::view_matrix(camera);
    for (int corner = 0; corner < 8; ++corner) {
      const glm::vec3 p(corner & 1 ? bounds->second.x : bounds->first.x, corner & 2 ? bounds->second.y : bounds->first.y,
                        corner & 4 ? bounds->second.z : bounds->first.z);
      const glm::vec4 clip = view_projection * glm::vec4(p, 1.0f);
      ASSERT_GT(clip.w, 0.0f);
      EXPECT_LE(std::abs(clip.x / clip.w), 1.0f) << model << " corner " << corner;
      EXPECT_LE(std::abs(clip.y / clip.w), 1.0f) << model << " corner " << corner;
    }
  }
}

}  // namespace
}  // namespace proxygi::world
