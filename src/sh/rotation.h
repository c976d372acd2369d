#pragma once
// Rotations of SH vectors (conventions in sh/basis.h).
//
// Zonal rotation (paper eq. 8): a function symmetric about +z with zonal coefficients z_l (the
// m = 0 coefficients, one per band, NOT pre-scaled) turned to point along the unit vector d is
//   rot(z, d)_lm = sqrt(4 pi / (2l + 1)) z_l y_lm(d).
// Cost: one basis evaluation and n*n multiplies.
#include <span>
#include <vector>

#include <Eigen/Core>
#include <glm/glm.hpp>

#include "sh/basis.h"

namespace proxygi::sh {

// sqrt(4 pi / (2l + 1)): 3.5449, 2.0467, 1.5853, 1.3398, 1.1816, 1.0689, ...
double zonal_rotation_scale(int l);

// Fixed-order fast path: zonal has Order values, out has Order*Order; dir must be unit.
template <int Order>
inline void rotate_zonal(const float* zonal, const glm::vec3& dir, float* out) {
  evaluate_basis<Order>(dir, out);
  // sqrt(4 pi / (2l + 1)) for l = 0..7, in float.
  constexpr float kScale[8] = {3.5449077f, 2.0466534f, 1.5853309f, 1.3398491f,
                               1.1816359f, 1.0688853f, 0.9831921f, 0.9152912f};
  for (int l = 0; l < Order; ++l) {
    const float scaled = kScale[l] * zonal[l];
    for (int i = l * l; i < (l + 1) * (l + 1); ++i) out[i] *= scaled;
  }
}

// Runtime order: zonal.size() >= order, out.size() >= order*order.
void rotate_zonal(int order, std::span<const float> zonal, const glm::vec3& dir, std::span<float> out);
void rotate_zonal(int order, std::span<const double> zonal, const glm::dvec3& dir, std::span<double> out);

// The n*n x n*n matrix R that rotates SH functions: (R f)(s) = f(rotation^T s) for a rotation
// matrix `rotation` (orthonormal, det +1), computed by exact quadrature (setup/reference code,
// not a hot path). Block diagonal by band; R^-1 = R^T.
Eigen::MatrixXd rotation_matrix(int order, const glm::dmat3& rotation);

// A rotation taking the unit vector `from` to `to` (the shortest arc; any one when opposite).
glm::dmat3 rotation_between(const glm::dvec3& from, const glm::dvec3& to);

}  // namespace proxygi::sh
