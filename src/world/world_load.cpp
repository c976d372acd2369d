// World::load: every model imported once, rigs obtained, clips resolved, static meshes posed.
// The rules are the GPU renderer's (they define the goldens) plus the reference's mannequin
// fallback; world.h lists them.
#include <map>
#include <string>
#include <utility>
#include <variant>

#include "anim/gltf_import.h"
#include "anim/gltf_writer.h"
#include "anim/mannequin.h"
#include "base/log.h"
#include "proxies/rig_cache.h"
#include "proxies/rig_file.h"
#include "world/world.h"

namespace proxygi::world {
namespace {

struct LoadedCharacter {
  std::filesystem::path file;
  bool built_in_code = false;
  anim::Character character;
};

// The model named by a scene entry: the glTF file, or for "builtin:mannequin" without its asset
// file the same figure built in code (the file is anim::encode_glb of it, byte for byte).
Result<LoadedCharacter> load_model(const scene::Scene& scene, const std::string& model,
                                   const std::filesystem::path& assets_dir) {
  LoadedCharacter out;
  out.file = scene::resolve_model_path(scene, model, assets_dir);
  std::error_code error;
  if (scene::is_builtin_mannequin(model) && !std::filesystem::exists(out.file, error)) {
    out.built_in_code = true;
    out.character = anim::build_mannequin();
    return out;
  }
  auto character = anim::import_gltf(out.file);
  if (!character) return character.error();
  out.character = std::move(*character);
  return out;
}

// The content hash the rig cache keys on: the file's bytes, or the built mannequin's encoding.
Result<std::string> model_hash(const Model& model) {
  if (!model.built_in_code) return proxies::hash_file(model.file);
  auto bytes = anim::encode_glb(model.character);
  if (!bytes) return make_error("mannequin: " + bytes.message());
  return proxies::content_hash(*bytes);
}

// Index in range, else an error; a name through anim::find_clip; -1 when there are no clips.
Result<int> resolve_clip(const anim::Character& character, const scene::ClipRef& clip) {
  if (character.clips.empty()) return -1;  // rest pose
  if (const auto* index = std::get_if<int>(&clip)) {
    if (*index < 0 || std::size_t(*index) >= character.clips.size())
      return make_error(character.source + ": clip index " + std::to_string(*index) + " out of range (" +
                        std::to_string(character.clips.size()) + " clips)");
    return *index;
  }
  return anim::find_clip(character, std::get<std::string>(clip));
}

Result<std::unique_ptr<Model>> make_model(const scene::Scene& scene, const scene::Character& entry,
                                          LoadedCharacter loaded, const WorldOptions& options) {
  auto model = std::make_unique<Model>();
  model->file = std::move(loaded.file);
  model->built_in_code = loaded.built_in_code;
  model->character = std::move(loaded.character);
  if (!options.load_rigs) return model;
  const auto rig_file = scene::resolve_proxy_path(scene, entry, options.assets_dir);
  auto hash = model_hash(*model);
  if (!hash) return hash.error();
  auto rig = obtain_rig(model->file, *hash, rig_file, model->character, options.write_rig_cache);
  if (!rig) return rig.error();
  auto tracking = proxies::compile_tracking(*rig, model->character, rig->binding);
  if (!tracking) return make_error(rig_file.string() + ": " + tracking.message());
  model->rig = std::move(*rig);
  model->tracking = std::move(*tracking);
  return model;
}

Result<StaticModel> make_static_model(const scene::Scene& scene, std::size_t index, const std::filesystem::path& assets_dir) {
  const scene::StaticMesh& entry = scene.static_meshes[index];
  auto loaded = load_model(scene, entry.model, assets_dir);
  if (!loaded) return loaded.error();
  StaticModel out;
  out.scene_static_mesh = index;
  out.file = std::move(loaded->file);
  out.character = std::move(loaded->character);
  out.albedo = entry.albedo;
  anim::PoseBuffers pose;
  if (Status posed = anim::evaluate_pose(out.character, -1, 0.0f, anim::WrapMode::clamp, pose, entry.transform.to_matrix());
      !posed)
    return posed.error();
  auto primitives = anim::pose_meshes(out.character, pose);
  if (!primitives) return primitives.error();
  out.primitives = std::move(*primitives);
  return out;
}

}  // namespace

Result<proxies::ProxyRig> obtain_rig(const std::filesystem::path& model_file, const std::string& model_hash,
                                     const std::filesystem::path& rig_file, const anim::Character& character,
                                     bool write_cache) {
  proxies::RigRequest request;
  request.rig_file = rig_file;
  request.model_name = model_file.filename().string();
  request.model_hash = model_hash;
  request.write_cache = write_cache;
  auto obtained = proxies::load_or_fit_rig(character, request);
  if (!obtained) return make_error(rig_file.string() + ": " + obtained.message());
  if (!obtained->cache_hit)
    log_info("proxies: fitted " + std::to_string(obtained->rig.spheres.size()) + " spheres to " + model_file.string());
  return std::move(obtained->rig);
}

Result<proxies::ProxyRig> obtain_rig(const std::filesystem::path& model_file, const std::filesystem::path& rig_file,
                                     const anim::Character& character, bool write_cache) {
  auto hash = proxies::hash_file(model_file);
  if (!hash) return hash.error();
  return obtain_rig(model_file, *hash, rig_file, character, write_cache);
}

Result<std::unique_ptr<World>> World::load(const scene::Scene& scene, const WorldOptions& options) {
  std::unique_ptr<World> world(new World());
  world->scene_ = scene;
  world->rigs_loaded_ = options.load_rigs;

  std::map<std::filesystem::path, std::size_t> model_by_file;
  for (std::size_t index = 0; index < scene.characters.size(); ++index) {
    const scene::Character& entry = scene.characters[index];
    const std::string where = "characters[" + std::to_string(index) + "]";
    const std::filesystem::path file = scene::resolve_model_path(scene, entry.model, options.assets_dir);
    auto found = model_by_file.find(file);
    if (found == model_by_file.end()) {
      auto loaded = load_model(scene, entry.model, options.assets_dir);
      if (!loaded) return make_error(where + ": " + loaded.message());
      auto model = make_model(scene, entry, std::move(*loaded), options);
      if (!model) return make_error(where + ": " + model.message());
      found = model_by_file.emplace(file, world->models_.size()).first;
      world->models_.push_back(std::move(*model));
    }
    CharacterInstance instance;
    instance.model_index = found->second;
    instance.model = world->models_[found->second].get();
    instance.scene_character = index;
    auto clip = resolve_clip(instance.model->character, entry.clip);
    if (!clip) return make_error(where + ".clip: " + clip.message());
    instance.clip = *clip;
    auto timeline = resolve_timeline(instance.model->character, entry.timeline, where + ".timeline");
    if (!timeline) return make_error(timeline.message());
    instance.timeline = std::move(*timeline);
    world->instances_.push_back(instance);
  }

  for (std::size_t index = 0; index < scene.static_meshes.size(); ++index) {
    auto model = make_static_model(scene, index, options.assets_dir);
    if (!model) return make_error("static_meshes[" + std::to_string(index) + "]: " + model.message());
    world->static_models_.push_back(std::move(*model));
  }
  return world;
}

}  // namespace proxygi::world
