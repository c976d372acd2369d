#include "sh/sender_light.h"

#include <algorithm>

#include "base/check.h"
#include "sh/basis.h"
#include "sh/convolution.h"
#include "sh/quadrature.h"
#include "sh/rotation.h"

namespace proxygi::sh {
namespace {

constexpr int kSenderOrder = 3;  // the indirect pass's order (gpu_layout::kIndirectOrder)

}  // namespace

std::vector<double> project_above_plane(int order, std::span<const double> lighting, const glm::dvec3& normal,
                                        int out_order) {
  const std::size_t count = std::size_t(coefficient_count(order));
  const std::size_t out_count = std::size_t(coefficient_count(out_order));
  PROXYGI_CHECK(order >= kMinOrder && order <= kMaxOrder && out_order >= kMinOrder && out_order <= kMaxOrder &&
                    lighting.size() >= count,
                "project_above_plane: bad lighting or order");
  // Degree ≤ (order − 1) + (out_order − 1): exact with max(order, out_order) nodes in cos θ and
  // twice as many φ samples (sh/quadrature.h).
  const int nodes = std::max(order, out_order);
  static thread_local SphereQuadrature upper;
  static thread_local int upper_nodes = -1;
  if (upper_nodes != nodes) {
    upper = make_cap_quadrature(0.0, nodes, 2 * nodes);
    upper_nodes = nodes;
  }
  const glm::dmat3 to_normal = rotation_between({0.0, 0.0, 1.0}, normal);
  const std::size_t basis_count = std::max(count, out_count);
  std::vector<double> result(out_count, 0.0), basis(basis_count);
  const int basis_order = std::max(order, out_order);
  for (std::size_t q = 0; q < upper.size(); ++q) {
    evaluate_basis(basis_order, to_normal * upper.directions[q], basis);
    double radiance = 0.0;
    for (std::size_t i = 0; i < count; ++i) radiance += lighting[i] * basis[i];
    const double weight = upper.weights[q] * radiance;
    for (std::size_t i = 0; i < out_count; ++i) result[i] += weight * basis[i];
  }
  return result;
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
