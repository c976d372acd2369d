#pragma once
// World: a scene's assets loaded once and evaluated at any scene time (DESIGN.md src/world/).
// The GPU renderer, the reference path tracer and the regression tracks all read it, so they
// load and pose a scene by the same rules:
//  - models are shared by file: two characters naming the same glTF share one Model;
//  - "builtin:mannequin" reads assets_dir/mannequin.glb, or builds the same figure in code
//    (anim::build_mannequin) when that file does not exist;
//  - a clip is an index (0 <= i < clip count, else an error naming the field) or a name
//    (anim::find_clip); a model without clips shows its rest pose (clip -1);
//  - clip time = scene::clip_time_s, looping (anim::WrapMode::loop); root placement =
//    scene::character_world_matrix;
//  - rigs come from proxies::load_or_fit_rig (the cached *.proxies.json when it belongs to the
//    model bytes, else a fresh fit, cached when WorldOptions::write_rig_cache); the mannequin
//    built in code hashes as the bytes anim::encode_glb gives it (those of assets/mannequin.glb),
//    so both forms share one cache;
//  - static meshes are posed once at load (rest pose, clip -1, under their transform), every
//    primitive kept (a renderer that needs normals skips those without).
// No GPU and no tinygltf type here: World is plain CPU data (label `unit` tests use it).
//
//   auto world = world::World::load(scene, {.assets_dir = "assets"});
//   world::WorldState state;
//   world->evaluate(1.25, std::nullopt, state);   // scene time 1.25 s, the scene's own camera
//   for (const auto& instance : state.instances) use(instance.pose.skin_matrices, instance.spheres);
//
// Conventions: glTF space (right-handed, +Y up, meters), seconds, column-major GLM matrices.
#include <filesystem>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "anim/character.h"
#include "anim/posed_character.h"
#include "base/result.h"
#include "proxies/proxy_rig.h"
#include "proxies/tracking.h"
#include "render/environment_lighting.h"
#include "render/shading.h"
#include "scene/camera.h"
#include "scene/scene.h"
#include "world/timeline.h"

namespace proxygi::world {

struct WorldOptions {
  std::filesystem::path assets_dir;  // where assets/mannequin.glb and its rig live
  bool load_rigs = true;             // false: no proxy rigs (the path tracer needs none)
  bool write_rig_cache = true;       // write freshly fitted rigs to their cache file
};

// One model file, shared by every character instance that uses it.
struct Model {
  std::filesystem::path file;      // resolved path ("builtin:mannequin" → assets_dir/mannequin.glb)
  bool built_in_code = false;      // the mannequin built by anim::build_mannequin (file absent)
  anim::Character character;
  proxies::ProxyRig rig;           // empty when WorldOptions::load_rigs is false
  proxies::TrackingRig tracking;   // compiled from rig for rig.binding
};

// One scene character: which model and which clip.
struct CharacterInstance {
  const Model* model = nullptr;
  std::size_t model_index = 0;      // index of *model in World::models() (per-model data of users)
  std::size_t scene_character = 0;  // index into scene.characters
  int clip = -1;                     // resolved clip index, -1: rest pose
  ResolvedTimeline timeline;         // schema v2 clip segments (world/timeline.h); empty: `clip`
};

// A static mesh of the scene, posed once: world-space primitives (anim::pose_meshes) of its model.
struct StaticModel {
  std::size_t scene_static_mesh = 0;      // index into scene.static_meshes
  std::filesystem::path file;             // resolved like a character's model
  anim::Character character;              // for materials and textures
  std::vector<anim::PosedPrimitive> primitives;  // world space
  std::optional<glm::vec3> albedo;        // replaces every material's base color when set
};

// One character at one time.
struct InstanceState {
  anim::PoseBuffers pose;                       // world matrices, skin and normal palettes, morph weights
  std::vector<proxies::WorldSphere> spheres;    // its tracked proxies (empty without rigs)
};

// The whole world at one time.
struct WorldState {
  double time_s = 0.0;
  std::vector<InstanceState> instances;  // one per World::instances(), same order
  std::vector<render::Sphere> spheres;   // every instance's proxies in instance order
  scene::CameraState camera;             // the override, or the scene camera at time_s
};

class World {
 public:
  // Errors name the field ("characters[1].clip: ...", "static_meshes[0]: ...") and the file.
  static Result<std::unique_ptr<World>> load(const scene::Scene& scene, const WorldOptions& options);

  const scene::Scene& scene() const { return scene_; }
  const std::vector<std::unique_ptr<Model>>& models() const { return models_; }
  const std::vector<CharacterInstance>& instances() const { return instances_; }
  const std::vector<StaticModel>& static_models() const { return static_models_; }
  std::size_t proxy_count() const;  // spheres per evaluated frame, all instances

  // Evaluates every character at scene time t (seconds) into `state` (its buffers are reused, so
  // a caller evaluating every frame allocates once). `camera`: render this camera instead of the
  // scene's. Deterministic: the same t gives the same state whatever was evaluated before.
  // Per instance: clip time float(scene::clip_time_s(entry, t)), anim::evaluate_pose looping
  // under scene::character_world_matrix(entry, t), then proxies::TrackProxiesJob. On failure
  // `state` is left partly written.
  Status evaluate(double scene_time_s, const std::optional<scene::CameraState>& camera, WorldState& state) const;
  // World-space skinned meshes of instance `instance` in `state` (CPU skinning, anim::pose_meshes).
  // `state` must come from this world's evaluate.
  Result<std::vector<anim::PosedPrimitive>> pose_instance(const WorldState& state, std::size_t instance) const;

  // The environment's unwindowed SH projection at `order` (1..8) and its background panorama
  // (render::make_environment_lighting), computed on first use and kept for the world's life:
  // settings changed in place (SH order) reuse it. Thread-safe; the pointer stays valid.
  Result<const render::EnvironmentLighting*> environment(int order) const;

 private:
  World() = default;
  bool rigs_loaded_ = true;  // WorldOptions::load_rigs
  scene::Scene scene_;
  std::vector<std::unique_ptr<Model>> models_;
  std::vector<CharacterInstance> instances_;
  std::vector<StaticModel> static_models_;
  mutable std::mutex environment_mutex_;
  mutable std::map<int, std::unique_ptr<render::EnvironmentLighting>> environments_;
};

// The rig request the world makes for a model (hash of the model bytes, scene's rig path).
// Exposed for `proxygi fit` and tests that want the same cache rules. `model_hash`: the content
// hash of the model (proxies::hash_file of model_file, or of the mannequin's encoded bytes).
Result<proxies::ProxyRig> obtain_rig(const std::filesystem::path& model_file, const std::filesystem::path& rig_file,
                                     const anim::Character& character, bool write_cache);
Result<proxies::ProxyRig> obtain_rig(const std::filesystem::path& model_file, const std::string& model_hash,
                                     const std::filesystem::path& rig_file, const anim::Character& character,
                                     bool write_cache);

}  // namespace proxygi::world
