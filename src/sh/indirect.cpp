#include "sh/indirect.h"

#include <algorithm>
#include <cmath>

#include "base/check.h"
#include "sh/basis.h"
#include "sh/quadrature.h"
#include "sh/rotation.h"

namespace proxygi::sh {
namespace {

// Visits (weight, s, qhat) over the cap s_z >= cos(theta) of the canonical proxy. The
// substitution t = sqrt(s_z^2 - cos^2 theta) removes the square-root behaviour at the rim, so
// Gauss-Legendre in t converges fast.
template <class Visit>
void integrate_over_proxy(int order, double s, Visit&& visit) {
  PROXYGI_CHECK(s > 0.0 && s < 1.0, "proxy sine must be in (0, 1)");
  const double cos_theta = std::sqrt(1.0 - s * s);
  const GaussLegendreRule rule = gauss_legendre(48);
  const int phi_count = 4 * order + 4;
  for (std::size_t k = 0; k < rule.nodes.size(); ++k) {
    const double t = 0.5 * s * (rule.nodes[k] + 1.0);
    const double z = std::sqrt(t * t + cos_theta * cos_theta);
    const double weight = rule.weights[k] * 0.5 * s * (t / z) * 2.0 * kPi / phi_count;
    const double sin_polar = std::sqrt(std::max(0.0, 1.0 - z * z));
    for (int p = 0; p < phi_count; ++p) {
      const double phi = (p + 0.5) * 2.0 * kPi / phi_count;
      const glm::dvec3 dir(sin_polar * std::cos(phi), sin_polar * std::sin(phi), z);
      const glm::dvec3 hit = dir * (z - t);  // first hit q_theta(s) (paper)
      const glm::dvec3 normal = glm::normalize((hit - glm::dvec3(0.0, 0.0, 1.0)) / s);
      visit(weight, dir, normal);
    }
  }
}

Eigen::VectorXd zonal_to_full(int order, std::span<const double> zonal) {
  Eigen::VectorXd full = Eigen::VectorXd::Zero(order * order);
  for (int l = 0; l < order; ++l) full(coefficient_index(l, 0)) = zonal[std::size_t(l)];
  return full;
}

// rot(K, +z) as a full vector: the l,0 entries are K_l (sqrt(4pi/(2l+1)) y_l0(z) = 1).
Eigen::VectorXd canonical_kernel(int order, std::span<const double> zonal) { return zonal_to_full(order, zonal); }

}  // namespace

std::array<double, 3> averaged_indirect_closed_form(double s) {
  PROXYGI_CHECK(s > 0.0 && s < 1.0, "proxy sine must be in (0, 1)");
  const double d = 1.0 / s, dc = std::sqrt(d * d - 1.0), sqrt_pi = std::sqrt(kPi);
  return {1.0 / (2.0 * sqrt_pi),
          -std::sqrt(3.0) * (2 * d * d * d - 2 * dc * d * d - dc + 1) / (6.0 * sqrt_pi * d * (d - dc)),
          std::sqrt(5.0) * (6 * std::pow(d, 5) - 6 * dc * std::pow(d, 4) - 3 * dc * d * d - dc + 4) / (20.0 * sqrt_pi * d * d * (d - dc))};
}

std::array<double, 3> averaged_indirect_polynomial(double s) {
  return {0.28209, 0.08432 * s * s - 0.25073 * s - 0.32494, -0.22230 * s * s * s + 0.22502 * s * s + 0.47398 * s + 0.15950};
}

std::vector<double> averaged_indirect_zonal(int order, double s) {
  std::vector<double> sum(static_cast<std::size_t>(order), 0.0), basis(static_cast<std::size_t>(order * order));
  double solid_angle = 0.0;
  integrate_over_proxy(order, s, [&](double weight, const glm::dvec3&, const glm::dvec3& normal) {
    evaluate_basis(order, normal, basis);
    solid_angle += weight;
    for (int l = 0; l < order; ++l) sum[std::size_t(l)] += weight * basis[std::size_t(coefficient_index(l, 0))];
  });
  for (double& value : sum) value /= solid_angle;
  return sum;
}

std::vector<double> point_indirect_zonal(int order) {
  std::vector<double> zonal(static_cast<std::size_t>(order));
  for (int l = 0; l < order; ++l) zonal[std::size_t(l)] = (l % 2 == 0 ? 1.0 : -1.0) * std::sqrt((2.0 * l + 1.0) / (4.0 * kPi));
  return zonal;
}

ZonalTable make_averaged_indirect_table(int order, int rows) {
  PROXYGI_CHECK(rows >= 2, "a table needs at least two rows");
  ZonalTable table{order, rows, {}};
  for (int i = 0; i < rows; ++i) {
    // Keep s inside (0, 1): row 0 and the last row use the nearby limits.
    const double s = std::clamp(double(i) / double(rows - 1), 1e-4, 1.0 - 1e-6);
    for (double value : averaged_indirect_zonal(order, s)) table.values.push_back(float(value));
  }
  return table;
}

Eigen::MatrixXd exact_indirect_operator(int order, double s) {
  const int count = order * order;
  Eigen::MatrixXd m = Eigen::MatrixXd::Zero(count, count);
  std::vector<double> at_dir(static_cast<std::size_t>(count)), at_normal(static_cast<std::size_t>(count));
  integrate_over_proxy(order, s, [&](double weight, const glm::dvec3& dir, const glm::dvec3& normal) {
    evaluate_basis(order, dir, at_dir);
    evaluate_basis(order, normal, at_normal);
    const Eigen::Map<const Eigen::VectorXd> a(at_dir.data(), count), b(at_normal.data(), count);
    m.noalias() += weight * a * b.transpose();
  });
  return m;
}

ExactIndirectTable make_exact_indirect_table(int order, int rows) {
  PROXYGI_CHECK(rows >= 2, "a table needs at least two rows");
  ExactIndirectTable table{order, rows, {}};
  const int count = order * order;
  table.values.reserve(std::size_t(rows) * std::size_t(count) * std::size_t(count));
  for (int i = 0; i < rows; ++i) {
    const Eigen::MatrixXd m = exact_indirect_operator(order, std::clamp(double(i) / double(rows - 1), 1e-4, 1.0 - 1e-6));
    for (int j = 0; j < count; ++j)
      for (int k = 0; k < count; ++k) table.values.push_back(float(m(j, k)));
  }
  return table;
}

void apply_influence_fade(ExactIndirectTable& table, float eta, int fade_rows) {
  const std::size_t count = std::size_t(table.order) * std::size_t(table.order), row_size = count * count;
  for (int i = 0; i < table.rows; ++i) {
    const float weight = influence_fade_weight(float(i) / float(table.rows - 1), eta, table.rows, fade_rows);
    for (std::size_t k = 0; k < row_size; ++k) table.values[std::size_t(i) * row_size + k] *= weight;
  }
}

Eigen::MatrixXd point_indirect_operator(int order, double s) {
  const Eigen::VectorXd visibility = zonal_to_full(order, proxy_visibility_zonal(order, s));
  return visibility * canonical_kernel(order, point_indirect_zonal(order)).transpose();
}

Eigen::MatrixXd averaged_indirect_operator(int order, double s) {
  const Eigen::VectorXd visibility = zonal_to_full(order, proxy_visibility_zonal(order, s));
  return visibility * canonical_kernel(order, averaged_indirect_zonal(order, s)).transpose();
}

std::vector<double> apply_exact_indirect(int order, double s, const glm::dvec3& direction, std::span<const double> lighting_convolved) {
  const int count = order * order;
  PROXYGI_CHECK(lighting_convolved.size() >= std::size_t(count), "lighting span too small");
  // R rotates dhat to +z; R^-1 = R^T rotates the canonical result back.
  const Eigen::MatrixXd rotation = rotation_matrix(order, rotation_between(direction, {0.0, 0.0, 1.0}));
  const Eigen::Map<const Eigen::VectorXd> lighting(lighting_convolved.data(), count);
  const Eigen::VectorXd result = rotation.transpose() * (exact_indirect_operator(order, s) * (rotation * lighting));
  return std::vector<double>(result.data(), result.data() + count);
}

IndirectOperatorErrors indirect_operator_errors(int order, double s) {
  const Eigen::MatrixXd exact = exact_indirect_operator(order, s);
  const double norm = exact.norm();
  IndirectOperatorErrors errors;
  errors.point = (point_indirect_operator(order, s) - exact).norm() / norm;
  errors.averaged = (averaged_indirect_operator(order, s) - exact).norm() / norm;
  if (order == 3) {
    const std::array<double, 3> fit = averaged_indirect_polynomial(s);
    const Eigen::VectorXd visibility = zonal_to_full(order, proxy_visibility_zonal(order, s));
    const Eigen::MatrixXd fitted = visibility * canonical_kernel(order, fit).transpose();
    errors.averaged_polynomial = (fitted - exact).norm() / norm;
  }
  return errors;
}

}  // namespace proxygi::sh
