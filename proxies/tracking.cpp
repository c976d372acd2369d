#include "proxies/tracking.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "proxies/bind_surface.h"

namespace proxygi::proxies {
namespace {

float max_axis_scale(const glm::mat4& m) {
  const float a = glm::dot(glm::vec3(m[0]), glm::vec3(m[0]));
  const float b = glm::dot(glm::vec3(m[1]), glm::vec3(m[1]));
  const float c = glm::dot(glm::vec3(m[2]), glm::vec3(m[2]));
  return std::sqrt(std::max({a, b, c}));
}

}  // namespace

Result<TrackingRig> compile_tracking(const ProxyRig& rig, const anim::Character& character, Binding binding) {
  TrackingRig out;
  out.binding = binding;
  out.node_count = int(character.nodes.size());
  const std::vector<glm::mat4> bind_to_bone = bind_to_bone_matrices(character, rest_world_matrices(character));
  for (std::size_t i = 0; i < rig.spheres.size(); ++i) {
    const ProxySphere& s = rig.spheres[i];
    const std::string where = "sphere " + std::to_string(i);
    if (s.node < 0 || s.node >= out.node_count)
      return make_error(where + ": bone node " + std::to_string(s.node) + " out of range (" + std::to_string(out.node_count) + " nodes)");
    TrackedSphere t;
    t.albedo = s.albedo;
    const bool blended = binding == Binding::blended && s.weight_nodes[0] >= 0;
    if (!blended) {
      t.count = 1;
      t.nodes[0] = s.node;
      t.weights[0] = 1.0f;
      t.centers[0] = glm::vec4(s.center, s.radius);
    } else {
      // Back to bind space through the bone, then into each influence's bone space.
      const glm::mat4 bone_to_bind = glm::inverse(bind_to_bone[std::size_t(s.node)]);
      const glm::vec3 bind_center = glm::vec3(bone_to_bind * glm::vec4(s.center, 1.0f));
      const float bind_radius = s.radius * max_axis_scale(bone_to_bind);
      float total = 0.0f;
      for (int k = 0; k < kSphereWeights && s.weight_nodes[std::size_t(k)] >= 0; ++k) {
        const int node = s.weight_nodes[std::size_t(k)];
        if (node >= out.node_count)
          return make_error(where + ": weight node " + std::to_string(node) + " out of range (" + std::to_string(out.node_count) + " nodes)");
        const glm::mat4& to_bone = bind_to_bone[std::size_t(node)];
        t.nodes[std::size_t(k)] = node;
        t.weights[std::size_t(k)] = s.weights[std::size_t(k)];
        t.centers[std::size_t(k)] = glm::vec4(glm::vec3(to_bone * glm::vec4(bind_center, 1.0f)), bind_radius * max_axis_scale(to_bone));
        total += s.weights[std::size_t(k)];
        t.count = k + 1;
      }
      if (!(total > 0.0f)) return make_error(where + ": weights sum to zero");
      for (int k = 0; k < t.count; ++k) t.weights[std::size_t(k)] /= total;
    }
    out.spheres.push_back(t);
  }
  return out;
}

Status TrackProxiesJob::validate() const {
  if (rig == nullptr) return make_error("track: rig is null");
  if (node_world.size() != std::size_t(rig->node_count))
    return make_error("track: node_world holds " + std::to_string(node_world.size()) + " matrices, rig needs " +
                      std::to_string(rig->node_count));
  if (spheres.size() != rig->spheres.size())
    return make_error("track: output holds " + std::to_string(spheres.size()) + " spheres, rig has " +
                      std::to_string(rig->spheres.size()));
  return {};
}

Status TrackProxiesJob::run() const {
  if (Status s = validate(); !s) return s;
  const std::size_t n = rig->spheres.size();
  for (std::size_t i = 0; i < n; ++i) {
    const TrackedSphere& t = rig->spheres[i];
    glm::vec3 center(0.0f);
    float radius = 0.0f;
    for (int k = 0; k < t.count; ++k) {
      const glm::mat4& m = node_world[std::size_t(t.nodes[std::size_t(k)])];
      const glm::vec4& c = t.centers[std::size_t(k)];
      const float w = t.weights[std::size_t(k)];
      center += w * (glm::vec3(m[0]) * c.x + glm::vec3(m[1]) * c.y + glm::vec3(m[2]) * c.z + glm::vec3(m[3]));
      radius += w * c.w * max_axis_scale(m);
    }
    spheres[i] = WorldSphere{center, radius, t.albedo, 0.0f};
  }
  return {};
}

}  // namespace proxygi::proxies
