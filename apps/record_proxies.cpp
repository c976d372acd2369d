#include "apps/record_proxies.h"

#include "anim/gltf_import.h"
#include "anim/posed_character.h"
#include "proxies/rig_file.h"
#include "proxies/tracking.h"
#include "scene/character_motion.h"

namespace proxygi::app {

struct SceneProxies::Character {
  std::size_t scene_index = 0;
  anim::Character model;
  int clip = -1;
  proxies::TrackingRig tracking;
  anim::PoseBuffers pose;
  std::vector<proxies::WorldSphere> spheres;
};

SceneProxies::~SceneProxies() = default;

Result<std::unique_ptr<SceneProxies>> SceneProxies::create(const scene::Scene& scene,
                                                           const std::filesystem::path& assets_dir) {
  std::unique_ptr<SceneProxies> out(new SceneProxies());
  out->scene_ = scene;
  for (std::size_t index = 0; index < scene.characters.size(); ++index) {
    const scene::Character& entry = scene.characters[index];
    const std::string where = "characters[" + std::to_string(index) + "]: ";
    auto character = std::make_unique<Character>();
    character->scene_index = index;
    auto model = anim::import_gltf(scene::resolve_model_path(scene, entry.model, assets_dir));
    if (!model) return make_error(where + model.message());
    character->model = std::move(*model);
    auto rig = proxies::read_rig(scene::resolve_proxy_path(scene, entry, assets_dir), character->model);
    if (!rig) return make_error(where + rig.message());
    auto tracking = proxies::compile_tracking(*rig, character->model, rig->binding);
    if (!tracking) return make_error(where + tracking.message());
    character->tracking = std::move(*tracking);
    if (!character->model.clips.empty()) {
      // As the renderer resolves ClipRef: an index, or a name for anim::find_clip.
      Result<int> clip = std::holds_alternative<int>(entry.clip)
                             ? Result<int>(std::get<int>(entry.clip))
                             : anim::find_clip(character->model, std::get<std::string>(entry.clip));
      if (!clip) return make_error(where + clip.message());
      character->clip = *clip;
    }
    character->spheres.resize(character->tracking.spheres.size());
    out->characters_.push_back(std::move(character));
  }
  return out;
}

Result<std::vector<render::Sphere>> SceneProxies::spheres(int frame) {
  const double t = scene::frame_time_s(scene_.output, frame);
  std::vector<render::Sphere> out;
  for (auto& character : characters_) {
    const scene::Character& entry = scene_.characters[character->scene_index];
    if (Status posed = anim::evaluate_pose(character->model, character->clip, float(scene::clip_time_s(entry, t)),
                                           anim::WrapMode::loop, character->pose,
                                           scene::character_world_matrix(entry, t));
        !posed)
      return posed.error();
    proxies::TrackProxiesJob track{&character->tracking, character->pose.world, character->spheres};
    if (Status tracked = track.run(); !tracked) return tracked.error();
    for (const auto& sphere : character->spheres) out.push_back({sphere.center, sphere.radius, sphere.albedo});
  }
  return out;
}

}  // namespace proxygi::app
