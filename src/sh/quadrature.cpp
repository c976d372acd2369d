#include "sh/quadrature.h"

#include <cmath>

#include <Eigen/Eigenvalues>

#include "base/check.h"
#include "sh/basis.h"

namespace proxygi::sh {

GaussLegendreRule gauss_legendre(int point_count) {
  PROXYGI_CHECK(point_count >= 1, "Gauss-Legendre needs at least one node");
  // Jacobi matrix of the Legendre recurrence: zero diagonal, off-diagonal k / sqrt(4k^2 - 1).
  Eigen::MatrixXd jacobi = Eigen::MatrixXd::Zero(point_count, point_count);
  for (int k = 1; k < point_count; ++k) {
    const double beta = k / std::sqrt(4.0 * k * k - 1.0);
    jacobi(k, k - 1) = beta;
    jacobi(k - 1, k) = beta;
  }
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver(jacobi);
  GaussLegendreRule rule;
  for (int k = 0; k < point_count; ++k) {
    rule.nodes.push_back(solver.eigenvalues()(k));
    const double first = solver.eigenvectors()(0, k);
    rule.weights.push_back(2.0 * first * first);
  }
  return rule;
}

SphereQuadrature make_cap_quadrature(double z_min, int z_count, int phi_count) {
  PROXYGI_CHECK(z_min >= -1.0 && z_min < 1.0 && phi_count >= 1, "bad cap quadrature");
  const GaussLegendreRule rule = gauss_legendre(z_count);
  const double half_length = 0.5 * (1.0 - z_min);
  SphereQuadrature quadrature;
  quadrature.directions.reserve(std::size_t(z_count) * std::size_t(phi_count));
  for (int iz = 0; iz < z_count; ++iz) {
    const double z = z_min + half_length * (rule.nodes[std::size_t(iz)] + 1.0);
    const double sin_theta = std::sqrt(std::max(0.0, 1.0 - z * z));
    const double weight = rule.weights[std::size_t(iz)] * half_length * 2.0 * kPi / phi_count;
    for (int ip = 0; ip < phi_count; ++ip) {
      const double phi = (ip + 0.5) * 2.0 * kPi / phi_count;
      quadrature.directions.emplace_back(sin_theta * std::cos(phi), sin_theta * std::sin(phi), z);
      quadrature.weights.push_back(weight);
    }
  }
  return quadrature;
}

SphereQuadrature make_sphere_quadrature(int z_count, int phi_count) { return make_cap_quadrature(-1.0, z_count, phi_count); }

std::vector<double> project_function(int order, const SphereQuadrature& quadrature,
                                     const std::function<double(const glm::dvec3&)>& function) {
  const int count = coefficient_count(order);
  std::vector<double> result(std::size_t(count), 0.0);
  std::vector<double> basis(static_cast<std::size_t>(count));
  for (std::size_t q = 0; q < quadrature.size(); ++q) {
    const double value = function(quadrature.directions[q]) * quadrature.weights[q];
    if (value == 0.0) continue;
    evaluate_basis(order, quadrature.directions[q], basis);
    for (int i = 0; i < count; ++i) result[std::size_t(i)] += value * basis[std::size_t(i)];
  }
  return result;
}

double evaluate_expansion(int order, std::span<const double> coefficients, const glm::dvec3& dir) {
  const int count = coefficient_count(order);
  PROXYGI_CHECK(coefficients.size() >= std::size_t(count), "coefficient span too small");
  std::vector<double> basis(static_cast<std::size_t>(count));
  evaluate_basis(order, dir, basis);
  double sum = 0.0;
  for (int i = 0; i < count; ++i) sum += coefficients[std::size_t(i)] * basis[std::size_t(i)];
  return sum;
}

}  // namespace proxygi::sh
