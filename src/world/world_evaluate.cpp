// World at one time: poses, proxies and camera (the GPU renderer's per-frame arithmetic, so its
// goldens stay bit-identical when it reads the world), posed meshes, the cached environment.
#include <string>

#include "scene/character_motion.h"
#include "sh/basis.h"
#include "world/world.h"

namespace proxygi::world {

std::size_t World::proxy_count() const {
  std::size_t count = 0;
  for (const CharacterInstance& instance : instances_) count += instance.model->tracking.spheres.size();
  return count;
}

Status World::evaluate(double scene_time_s, const std::optional<scene::CameraState>& camera, WorldState& state) const {
  const double t = scene_time_s;
  state.time_s = t;
  state.instances.resize(instances_.size());
  state.spheres.clear();
  for (std::size_t index = 0; index < instances_.size(); ++index) {
    const CharacterInstance& instance = instances_[index];
    const scene::Character& entry = scene_.characters[instance.scene_character];
    InstanceState& out = state.instances[index];
    const float clip_time = float(scene::clip_time_s(entry, t));
    const glm::mat4 root = scene::character_world_matrix(entry, t);
    if (Status posed = instance.timeline.empty()
                           ? anim::evaluate_pose(instance.model->character, instance.clip, clip_time, anim::WrapMode::loop,
                                                 out.pose, root)
                           : evaluate_timeline_pose(instance.model->character, sample_timeline(instance.timeline, t),
                                                    out.pose, root);
        !posed)
      return make_error("characters[" + std::to_string(instance.scene_character) + "]: " + posed.message());
    out.spheres.resize(instance.model->tracking.spheres.size());
    if (!rigs_loaded_) continue;
    proxies::TrackProxiesJob track{&instance.model->tracking, out.pose.world, out.spheres};
    if (Status tracked = track.run(); !tracked)
      return make_error("characters[" + std::to_string(instance.scene_character) + "]: " + tracked.message());
    for (const auto& sphere : out.spheres) state.spheres.push_back({sphere.center, sphere.radius, sphere.albedo});
  }
  state.camera = camera ? *camera : scene::evaluate_scene_camera(scene_, t);
  return {};
}

Result<std::vector<anim::PosedPrimitive>> World::pose_instance(const WorldState& state, std::size_t instance) const {
  if (instance >= instances_.size())
    return make_error("pose_instance: instance " + std::to_string(instance) + " out of range (" +
                      std::to_string(instances_.size()) + " instances)");
  if (state.instances.size() != instances_.size())
    return make_error("pose_instance: the state holds " + std::to_string(state.instances.size()) +
                      " instances, the world " + std::to_string(instances_.size()) + " (evaluate this world first)");
  const CharacterInstance& character = instances_[instance];
  auto primitives = anim::pose_meshes(character.model->character, state.instances[instance].pose);
  if (!primitives) return make_error("characters[" + std::to_string(character.scene_character) + "]: " + primitives.message());
  return primitives;
}

Result<const render::EnvironmentLighting*> World::environment(int order) const {
  if (order < sh::kMinOrder || order > sh::kMaxOrder)
    return make_error("environment: SH order " + std::to_string(order) + " out of range (" +
                      std::to_string(sh::kMinOrder) + ".." + std::to_string(sh::kMaxOrder) + ")");
  const std::lock_guard<std::mutex> lock(environment_mutex_);
  if (const auto found = environments_.find(order); found != environments_.end()) return found->second.get();
  auto lighting = render::make_environment_lighting(scene_, order);
  if (!lighting) return make_error("environment: " + lighting.message());
  auto& kept = environments_[order];
  kept = std::make_unique<render::EnvironmentLighting>(std::move(*lighting));
  return kept.get();
}

}  // namespace proxygi::world
