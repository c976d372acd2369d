#include "proxies/culling.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace proxygi::proxies {

Frustum Frustum::from_view_projection(const glm::mat4& m) {
  // Rows of the column-major matrix.
  auto row = [&](int r) { return glm::vec4(m[0][r], m[1][r], m[2][r], m[3][r]); };
  Frustum f;
  f.planes = {row(3) + row(0), row(3) - row(0), row(3) + row(1), row(3) - row(1), row(3) + row(2), row(3) - row(2)};
  for (glm::vec4& p : f.planes) p /= glm::length(glm::vec3(p));
  return f;
}

bool Frustum::touches(const glm::vec3& center, float radius) const {
  for (const glm::vec4& p : planes)
    if (glm::dot(glm::vec3(p), center) + p.w < -radius) return false;
  return true;
}

Status CullProxiesJob::validate() const {
  if (kept_count == nullptr) return make_error("cull: kept_count is null");
  if (kept.size() < spheres.size()) return make_error("cull: kept holds fewer entries than spheres");
  if (!(eta > 0.0f)) return make_error("cull: eta must be > 0");
  return {};
}

Status CullProxiesJob::run() const {
  if (Status s = validate(); !s) return s;
  int count = 0;
  for (std::size_t i = 0; i < spheres.size(); ++i)
    if (frustum.touches(spheres[i].center, eta * spheres[i].radius)) kept[std::size_t(count++)] = std::uint32_t(i);
  *kept_count = count;
  return {};
}

std::vector<int> chain_groups(const ProxyRig& rig, const anim::Character& character) {
  std::vector<int> groups;
  for (const ProxySphere& s : rig.spheres) {
    int node = s.node;
    while (node >= 0 && character.nodes[std::size_t(node)].parent >= 0 &&
           character.nodes[std::size_t(character.nodes[std::size_t(node)].parent)].children.size() < 2)
      node = character.nodes[std::size_t(node)].parent;
    groups.push_back(node);
  }
  return groups;
}

WorldSphere bounding_sphere(std::span<const WorldSphere> spheres) {
  WorldSphere out;
  double volume = 0.0;
  glm::dvec3 center(0.0), albedo(0.0);
  for (const WorldSphere& s : spheres) {
    const double v = double(s.radius) * s.radius * s.radius;
    volume += v;
    center += v * glm::dvec3(s.center);
    albedo += v * glm::dvec3(s.albedo);
  }
  if (volume <= 0.0) return spheres.empty() ? out : spheres.front();
  out.center = glm::vec3(center / volume);
  out.albedo = glm::vec3(albedo / volume);
  for (const WorldSphere& s : spheres) out.radius = std::max(out.radius, glm::length(s.center - out.center) + s.radius);
  return out;
}

Status MergeSmallProxiesJob::validate() const {
  if (out_count == nullptr) return make_error("merge: out_count is null");
  if (groups.size() != spheres.size()) return make_error("merge: groups must hold one entry per sphere");
  if (out.size() < spheres.size()) return make_error("merge: out holds fewer entries than spheres");
  if (!(focal_pixels > 0.0f) || !(pixel_threshold >= 0.0f)) return make_error("merge: focal_pixels must be > 0, threshold >= 0");
  return {};
}

Status MergeSmallProxiesJob::run() const {
  if (Status s = validate(); !s) return s;
  auto projected = [&](const WorldSphere& s) {
    const float distance = std::max(glm::length(s.center - eye) - s.radius, 1e-6f);
    return s.radius * focal_pixels / distance;
  };
  int count = 0;
  const WorldSphere whole = bounding_sphere(spheres);
  if (!spheres.empty() && projected(whole) < pixel_threshold) {
    out[0] = whole;
    *out_count = 1;
    return {};
  }
  // Groups in first-appearance order, so the output order is stable.
  std::vector<int> order;
  std::map<int, std::vector<WorldSphere>> members;
  for (std::size_t i = 0; i < spheres.size(); ++i) {
    auto [it, added] = members.try_emplace(groups[i]);
    if (added) order.push_back(groups[i]);
    it->second.push_back(spheres[i]);
  }
  for (int g : order) {
    const std::vector<WorldSphere>& group = members[g];
    const WorldSphere merged = bounding_sphere(group);
    if (group.size() > 1 && projected(merged) < pixel_threshold) {
      out[std::size_t(count++)] = merged;
    } else {
      for (const WorldSphere& s : group) out[std::size_t(count++)] = s;
    }
  }
  *out_count = count;
  return {};
}

}  // namespace proxygi::proxies
