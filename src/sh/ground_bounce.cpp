#include "sh/ground_bounce.h"

#include "base/check.h"
#include "sh/basis.h"
#include "sh/convolution.h"
#include "sh/quadrature.h"

namespace proxygi::sh {
namespace {

// The upper hemisphere s_y ≥ 0 as a cap about +z turned onto +Y: (x, y, z) → (x, z, −y).
glm::dvec3 to_world_up(const glm::dvec3& cap_direction) { return {cap_direction.x, cap_direction.z, -cap_direction.y}; }

}  // namespace

double ground_irradiance(int order, std::span<const double> lighting) {
  const std::size_t count = std::size_t(coefficient_count(order));
  PROXYGI_CHECK(order >= kMinOrder && order <= kMaxOrder && lighting.size() >= count, "ground irradiance: bad lighting");
  std::vector<double> irradiance(lighting.begin(), lighting.begin() + std::ptrdiff_t(count));
  convolve_zonal(order, clamped_cosine_zonal(order), irradiance);
  return evaluate_expansion(order, irradiance, {0.0, 1.0, 0.0});
}

std::vector<double> replace_below_horizon(int order, std::span<const double> lighting, double ground_radiance) {
  const std::size_t count = std::size_t(coefficient_count(order));
  PROXYGI_CHECK(order >= kMinOrder && order <= kMaxOrder && lighting.size() >= count, "replace_below_horizon: bad lighting");
  // L'_i = Σ_q w_q (L(s_q) − g) y_i(s_q) over the upper hemisphere, plus g √(4π) δ_i0.
  const SphereQuadrature upper = make_cap_quadrature(0.0, order, 2 * order);
  std::vector<double> result(count, 0.0), basis(count);
  for (std::size_t q = 0; q < upper.size(); ++q) {
    evaluate_basis(order, to_world_up(upper.directions[q]), basis);
    double radiance = 0.0;
    for (std::size_t i = 0; i < count; ++i) radiance += lighting[i] * basis[i];
    const double weight = upper.weights[q] * (radiance - ground_radiance);
    for (std::size_t i = 0; i < count; ++i) result[i] += weight * basis[i];
  }
  result[0] += ground_radiance * kSqrtFourPi;
  return result;
}

}  // namespace proxygi::sh
