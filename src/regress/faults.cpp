#include "regress/faults.h"

#include <glm/gtc/quaternion.hpp>

#include "scene/character_motion.h"

namespace proxygi::regress {

std::string_view Fault::name() const {
  switch (kind) {
    case FaultKind::none: return "none";
    case FaultKind::joint_rotation: return "joint_0.5deg";
    case FaultKind::proxy_radius: return "proxy_radius_5pct";
    case FaultKind::clip_time: return "clip_time_1frame";
    case FaultKind::sh_band: return "sh_band_less";
    case FaultKind::receivers: return "receivers_2k";
  }
  return "?";
}

std::vector<Fault> sensitivity_faults() {
  return {{FaultKind::joint_rotation}, {FaultKind::proxy_radius}, {FaultKind::clip_time}, {FaultKind::sh_band},
          {FaultKind::receivers}};
}

void apply_fault(const Fault& fault, settings::RenderSettings& settings) {
  if (fault.kind == FaultKind::sh_band) settings.sh_order = settings.sh_order > 3 ? settings.sh_order - 1 : settings.sh_order + 1;
  if (fault.kind == FaultKind::receivers) settings.receiver_scale = settings.receiver_scale < 8 ? settings.receiver_scale * 2 : 4;
}

double fault_character_time(const Fault& fault, double t, double fps) {
  return fault.kind == FaultKind::clip_time ? t + 1.0 / fps : t;
}

Status apply_fault(const Fault& fault, const world::World& world, double t, world::WorldState& state) {
  if (state.instances.empty() || world.instances().empty()) return {};
  const world::CharacterInstance& instance = world.instances()[0];
  world::InstanceState& first = state.instances[0];
  if (fault.kind == FaultKind::joint_rotation) {
    const anim::Character& character = instance.model->character;
    if (character.skins.empty() || character.skins[0].joints.empty()) return {};
    const auto& joints = character.skins[0].joints;
    const int node = joints[joints.size() / 2];
    anim::Transform& local = first.pose.locals[std::size_t(node)];
    local.rotation = local.rotation * glm::angleAxis(glm::radians(0.5f), glm::vec3(1.0f, 0.0f, 0.0f));
    const scene::Character& entry = world.scene().characters[instance.scene_character];
    if (Status s = anim::pose_from_locals(character, first.pose, scene::character_world_matrix(entry, t)); !s) return s;
    proxies::TrackProxiesJob track{&instance.model->tracking, first.pose.world, first.spheres};
    if (Status s = track.run(); !s) return s;
  } else if (fault.kind == FaultKind::proxy_radius) {
    if (first.spheres.empty()) return {};
    first.spheres[0].radius *= 1.05f;
  } else {
    return {};
  }
  state.spheres.clear();
  for (const auto& instance_state : state.instances)
    for (const auto& sphere : instance_state.spheres) state.spheres.push_back({sphere.center, sphere.radius, sphere.albedo});
  return {};
}

}  // namespace proxygi::regress
