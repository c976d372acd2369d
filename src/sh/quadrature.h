#pragma once
// Numerical integration over the unit sphere, used to project functions to SH and to build the
// reference operators and tables. A product rule: Gauss-Legendre in z = cos theta times uniform
// phi. With t z-nodes and p phi samples it integrates polynomials of degree <= min(2t-1, p-1)
// exactly (so products of three order-n basis functions need t >= ceil((3n-2)/2), p >= 3n-2).
#include <functional>
#include <span>
#include <vector>

#include <glm/glm.hpp>

namespace proxygi::sh {

struct GaussLegendreRule {
  std::vector<double> nodes;    // in (-1, 1), increasing
  std::vector<double> weights;  // sum to 2
};
// n-point Gauss-Legendre rule on [-1, 1] (Golub-Welsch: eigenvalues of the Jacobi matrix, Eigen).
GaussLegendreRule gauss_legendre(int point_count);

struct SphereQuadrature {
  std::vector<glm::dvec3> directions;  // unit vectors
  std::vector<double> weights;         // steradians, sum to 4 pi
  std::size_t size() const { return weights.size(); }
};
// Product rule over the whole sphere with z_count Gauss nodes in z and phi_count phi samples.
SphereQuadrature make_sphere_quadrature(int z_count, int phi_count);
// The same rule over the polar cap z in [z_min, 1] only (for integrands supported on a cap).
SphereQuadrature make_cap_quadrature(double z_min, int z_count, int phi_count);

// SH projection f_i = sum_q w_q f(dir_q) y_i(dir_q) to order `order` (double precision).
std::vector<double> project_function(int order, const SphereQuadrature& quadrature,
                                     const std::function<double(const glm::dvec3&)>& function);

// Evaluates the SH expansion sum_i f_i y_i(dir).
double evaluate_expansion(int order, std::span<const double> coefficients, const glm::dvec3& dir);

}  // namespace proxygi::sh
