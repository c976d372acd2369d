#include "sh/sender_light.h"

#include <algorithm>

#include "base/check.h"
#include "sh/basis.h"
#include "sh/convolution.h"

namespace proxygi::sh {
namespace {

constexpr int kSenderOrder = 3;  // the indirect pass's order (gpu_layout::kIndirectOrder)

}  // namespace

std::vector<double> project_above_plane(int order, std::span<const double> lighting, const glm::dvec3& normal,
                                        int out_order) {
  PROXYGI_CHECK(order >= kMinOrder && order <= kMaxOrder && out_order >= kMinOrder && out_order <= kMaxOrder &&
                    lighting.size() >= std::size_t(coefficient_count(order)),
                "project_above_plane: bad lighting or order");
  // Degree ≤ (order − 1) + (out_order − 1): exact with max(order, out_order) nodes in cos θ and
  // twice as many φ samples (sh/quadrature.h).
  const int nodes = std::max(order, out_order);
  return project_over_hemisphere(order, lighting, normal, out_order, false, nodes, 2 * nodes);
}

LightingCubeMap make_sender_light_cube(int order, std::span<const double> lighting, int face_size) {
  PROXYGI_CHECK(face_size >= 1, "cube map faces need at least one texel");
  const std::vector<double> cosine = clamped_cosine_zonal(kSenderOrder);
  LightingCubeMap map{kSenderOrder, face_size, {}};
  map.values.reserve(6 * std::size_t(face_size) * std::size_t(face_size) * std::size_t(kSenderOrder * kSenderOrder));
  for (int face = 0; face < 6; ++face)
    for (int y = 0; y < face_size; ++y)
      for (int x = 0; x < face_size; ++x) {
        std::vector<double> light = project_above_plane(order, lighting, cube_map_direction(face, x, y, face_size), kSenderOrder);
        convolve_zonal(kSenderOrder, cosine, light);
        for (double value : light) map.values.push_back(float(value));
      }
  return map;
}

}  // namespace proxygi::sh
