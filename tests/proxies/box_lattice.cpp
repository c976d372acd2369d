#include "proxies/box_lattice.h"

#include <algorithm>

namespace proxygi::proxies::testing {

float box_sdf(const glm::vec3& p, const glm::vec3& lo, const glm::vec3& hi) {
  const glm::vec3 c = 0.5f * (lo + hi), h = 0.5f * (hi - lo);
  const glm::vec3 q = glm::abs(p - c) - h;
  return glm::length(glm::max(q, glm::vec3(0.0f))) + std::min(std::max({q.x, q.y, q.z}), 0.0f);
}

std::vector<std::uint32_t> add_box_lattice(std::vector<glm::vec3>& points, const AxisBox& box, float spacing) {
  std::vector<std::uint32_t> members;
  for (float x = box.lo.x; x <= box.hi.x + 1e-4f; x += spacing)
    for (float y = box.lo.y; y <= box.hi.y + 1e-4f; y += spacing)
      for (float z = box.lo.z; z <= box.hi.z + 1e-4f; z += spacing) {
        members.push_back(std::uint32_t(points.size()));
        points.emplace_back(x, y, z);
      }
  return members;
}

void add_to_soup(TriangleSoup& soup, const anim::Primitive& primitive) {
  const std::uint32_t base = std::uint32_t(soup.positions.size());
  soup.positions.insert(soup.positions.end(), primitive.positions.begin(), primitive.positions.end());
  for (std::size_t i = 0; i + 2 < primitive.indices.size(); i += 3)
    soup.triangles.emplace_back(base + primitive.indices[i], base + primitive.indices[i + 1],
                                base + primitive.indices[i + 2]);
}

float union_outside_volume(std::span<const ClusterSphere> spheres, std::span<const AxisBox> boxes, float spacing) {
  glm::vec3 lo(1e9f), hi(-1e9f);
  for (const ClusterSphere& s : spheres) lo = glm::min(lo, s.center - s.radius), hi = glm::max(hi, s.center + s.radius);
  const float h = spacing;
  int outside = 0;
  for (float x = lo.x + 0.5f * h; x < hi.x; x += h)
    for (float y = lo.y + 0.5f * h; y < hi.y; y += h)
      for (float z = lo.z + 0.5f * h; z < hi.z; z += h) {
        const glm::vec3 p(x, y, z);
        bool in = false;
        for (const ClusterSphere& s : spheres) in = in || glm::length(p - s.center) <= s.radius;
        bool out_of_boxes = true;
        for (const AxisBox& box : boxes) out_of_boxes = out_of_boxes && box_sdf(p, box.lo, box.hi) > 0.0f;
        outside += in && out_of_boxes ? 1 : 0;
      }
  return float(outside) * h * h * h;
}

}  // namespace proxygi::proxies::testing
