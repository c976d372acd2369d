#include "sh/rotation.h"

#include <cmath>

#include "base/check.h"
#include "sh/quadrature.h"

namespace proxygi::sh {
namespace {

template <class Real>
void rotate_zonal_runtime(int order, std::span<const Real> zonal, const glm::vec<3, Real>& dir, std::span<Real> out) {
  PROXYGI_CHECK(zonal.size() >= std::size_t(order), "zonal span too small");
  evaluate_basis(order, dir, out);
  for (int l = 0; l < order; ++l) {
    const Real scaled = Real(zonal_rotation_scale(l)) * zonal[std::size_t(l)];
    for (int i = l * l; i < (l + 1) * (l + 1); ++i) out[std::size_t(i)] *= scaled;
  }
}

}  // namespace

double zonal_rotation_scale(int l) { return std::sqrt(4.0 * kPi / (2.0 * l + 1.0)); }

void rotate_zonal(int order, std::span<const float> zonal, const glm::vec3& dir, std::span<float> out) {
  rotate_zonal_runtime(order, zonal, dir, out);
}
void rotate_zonal(int order, std::span<const double> zonal, const glm::dvec3& dir, std::span<double> out) {
  rotate_zonal_runtime(order, zonal, dir, out);
}

Eigen::MatrixXd rotation_matrix(int order, const glm::dmat3& rotation) {
  const int count = coefficient_count(order);
  // y_i(s) y_j(R^T s) has degree 2(n-1): n z-nodes and 2n phi samples are exact.
  const SphereQuadrature quadrature = make_sphere_quadrature(order + 1, 2 * order + 2);
  const glm::dmat3 inverse = glm::transpose(rotation);
  Eigen::MatrixXd result = Eigen::MatrixXd::Zero(count, count);
  std::vector<double> at_s(static_cast<std::size_t>(count)), at_rotated(static_cast<std::size_t>(count));
  for (std::size_t q = 0; q < quadrature.size(); ++q) {
    evaluate_basis(order, quadrature.directions[q], at_s);
    evaluate_basis(order, glm::normalize(inverse * quadrature.directions[q]), at_rotated);
    for (int i = 0; i < count; ++i)
      for (int j = band_of_index(i) * band_of_index(i); j < (band_of_index(i) + 1) * (band_of_index(i) + 1); ++j)
        result(i, j) += quadrature.weights[q] * at_s[std::size_t(i)] * at_rotated[std::size_t(j)];
  }
  return result;
}

glm::dmat3 rotation_between(const glm::dvec3& from, const glm::dvec3& to) {
  const glm::dvec3 axis = glm::cross(from, to);
  const double cosine = glm::dot(from, to);
  const double sine = glm::length(axis);
  if (sine < 1e-12) {
    if (cosine > 0.0) return glm::dmat3(1.0);
    // Opposite: a half turn about any axis perpendicular to `from`.
    glm::dvec3 perpendicular = std::abs(from.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
    perpendicular = glm::normalize(perpendicular - from * glm::dot(perpendicular, from));
    return 2.0 * glm::outerProduct(perpendicular, perpendicular) - glm::dmat3(1.0);
  }
  const glm::dvec3 k = axis / sine;
  const glm::dmat3 cross_matrix(0.0, k.z, -k.y, -k.z, 0.0, k.x, k.y, -k.x, 0.0);  // column-major
  return glm::dmat3(1.0) + sine * cross_matrix + (1.0 - cosine) * cross_matrix * cross_matrix;
}

}  // namespace proxygi::sh
