#pragma once
// Indirect radiance from a sphere proxy lit by the environment (paper section 5; conventions in
// sh/basis.h). Ltilde is the irradiance-convolved lighting (L convolved with the clamped cosine,
// sh/convolution.h), so Ltilde(q) is the unshadowed outgoing radiance x pi / albedo at a point of
// the proxy with normal q. A proxy subtends the half-angle theta, s = sin(theta) = r / d.
//
// Canonical frame: proxy centre along +z, receiver at the origin. There every operator maps
// Ltilde (n*n) to the proxy's radiance vector I (n*n):
//   exact (eq. 16)    M_jk = integral over the cap of y_j(s) y_k(qhat(s)) ds
//   point (eq. 13)    I = (Ltilde . y(-dhat)) V      -> P = V y(-z)^T
//   averaged (eq. 15) I = kappa V, kappa = rot(D, dhat) . Ltilde -> A = V rot(D, z)^T
// where V is the proxy's cap (sh/occlusion_tables.h) and D (eq. 14) the zonal average of
// y(qhat) over the cap. For the GPU both approximations are zonal kernels K rotated to the
// proxy direction: kappa = rot(K, dhat) . Ltilde with K = point_indirect_zonal or D(s).
#include <array>
#include <span>
#include <vector>

#include <Eigen/Core>
#include <glm/glm.hpp>

#include "sh/occlusion_tables.h"

namespace proxygi::sh {

// D for order 3 in closed form (paper, d = csc theta, dcheck = sqrt(d^2 - 1)); 0 < s < 1.
std::array<double, 3> averaged_indirect_closed_form(double s);
// The paper's polynomial fit of D (order 3): D0 = 0.28209, D1 quadratic, D2 cubic in s.
std::array<double, 3> averaged_indirect_polynomial(double s);
// D for any order 1..8 by numerical integration (zonal, plain m = 0 coefficients); 0 < s < 1.
std::vector<double> averaged_indirect_zonal(int order, double s);
// Zonal kernel of the point-sampled operator: rot(K, dhat) = y(-dhat), K_l = (-1)^l sqrt((2l+1)/(4pi)).
std::vector<double> point_indirect_zonal(int order);
// D tabulated over s like the occlusion tables (row i <-> s = i/(rows-1); row 0 is the s -> 0 limit).
ZonalTable make_averaged_indirect_table(int order, int rows = 256);

// Canonical operators (n*n x n*n), 0 < s < 1.
Eigen::MatrixXd exact_indirect_operator(int order, double s);
Eigen::MatrixXd point_indirect_operator(int order, double s);
Eigen::MatrixXd averaged_indirect_operator(int order, double s);  // numerical D

// M(s) tabulated for the GPU or a CPU cache: rows over s like ZonalTable (row i <-> s = i/(rows-1),
// the ends clamped into (0, 1)); each row is the n*n x n*n matrix in row-major order (M_jk at
// j * n*n + k), floats: values[(i * n*n + j) * n*n + k].
struct ExactIndirectTable {
  int order = 0;
  int rows = 0;
  std::vector<float> values;
};
ExactIndirectTable make_exact_indirect_table(int order, int rows = 64);
// Multiplies row i by influence_fade_weight(s_i, eta, rows, fade_rows) (sh/occlusion_tables.h),
// the sphere-of-influence fade the visibility table gets: the proxy's contribution goes to 0
// smoothly at s = 1/eta.
void apply_influence_fade(ExactIndirectTable& table, float eta, int fade_rows = 4);

// Eq. 17: the exact operator for a proxy in direction dhat (unit): R^-1 M(theta) R Ltilde.
std::vector<double> apply_exact_indirect(int order, double s, const glm::dvec3& direction, std::span<const double> lighting_convolved);

// Relative Frobenius errors ||X - M||_F / ||M||_F of the approximations (paper Figure 5).
struct IndirectOperatorErrors {
  double point = 0.0;
  double averaged = 0.0;             // numerical D
  double averaged_polynomial = -1.0;  // order 3 only (the paper's fit); -1 otherwise
};
IndirectOperatorErrors indirect_operator_errors(int order, double s);

}  // namespace proxygi::sh
