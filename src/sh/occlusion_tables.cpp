#include "sh/occlusion_tables.h"

#include <algorithm>
#include <cmath>

#include "base/check.h"
#include "sh/basis.h"
#include "sh/product.h"

namespace proxygi::sh {
namespace {

std::vector<double> zonal_to_full(int order, std::span<const double> zonal) {
  std::vector<double> full(static_cast<std::size_t>(order * order), 0.0);
  for (int l = 0; l < order; ++l) full[std::size_t(coefficient_index(l, 0))] = zonal[std::size_t(l)];
  return full;
}

std::vector<double> full_to_zonal(int order, std::span<const double> full) {
  std::vector<double> zonal(static_cast<std::size_t>(order));
  for (int l = 0; l < order; ++l) zonal[std::size_t(l)] = full[std::size_t(coefficient_index(l, 0))];
  return zonal;
}

ZonalTable make_table(int order, int rows, std::vector<double> (*zonal)(int, double)) {
  PROXYGI_CHECK(rows >= 2, "a table needs at least two rows");
  ZonalTable table{order, rows, {}};
  table.values.reserve(std::size_t(rows) * std::size_t(order));
  for (int i = 0; i < rows; ++i) {
    const std::vector<double> row = zonal(order, double(i) / double(rows - 1));
    for (double value : row) table.values.push_back(float(value));
  }
  return table;
}

std::vector<double> log_occlusion_default(int order, double s) { return log_occlusion_zonal(order, s); }

}  // namespace

std::vector<double> proxy_visibility_zonal(int order, double s) {
  PROXYGI_CHECK(order >= 1 && order <= kMaxOrder, "SH order must be 1..8");
  const double c = std::sqrt(std::max(0.0, 1.0 - std::min(s * s, 1.0)));  // cos(alpha)
  std::vector<double> zonal(static_cast<std::size_t>(order));
  zonal[0] = std::sqrt(kPi) * (1.0 - c);
  for (int l = 1; l < order; ++l)
    zonal[std::size_t(l)] = 2.0 * kPi * std::sqrt((2.0 * l + 1.0) / (4.0 * kPi)) * (legendre(l - 1, c) - legendre(l + 1, c)) / (2.0 * l + 1.0);
  return zonal;
}

std::vector<double> occlusion_zonal(int order, double s) {
  std::vector<double> zonal = proxy_visibility_zonal(order, s);
  for (double& value : zonal) value = -value;
  zonal[0] += kSqrtFourPi;
  return zonal;
}

std::vector<double> log_occlusion_zonal(int order, double s, double epsilon_ratio) {
  const std::vector<double> occlusion = occlusion_zonal(order, s);
  return full_to_zonal(order, log_exact(order, zonal_to_full(order, occlusion), epsilon_ratio));
}

void ZonalTable::lookup(float s, std::span<float> out) const {
  const float position = std::clamp(s, 0.0f, 1.0f) * float(rows - 1);
  const int index = std::min(int(position), rows - 2);
  const float t = position - float(index);
  const std::span<const float> lower = row(index), upper = row(index + 1);
  for (int l = 0; l < order; ++l) out[std::size_t(l)] = lower[std::size_t(l)] + t * (upper[std::size_t(l)] - lower[std::size_t(l)]);
}

ZonalTable make_proxy_visibility_table(int order, int rows) { return make_table(order, rows, proxy_visibility_zonal); }

ZonalTable make_log_occlusion_table(int order, int rows) {
  PROXYGI_CHECK(has_product(order), "log-occlusion tables exist for orders 3..6");
  return make_table(order, rows, log_occlusion_default);
}

float influence_fade_weight(float s, float eta, int rows, int fade_rows) {
  PROXYGI_CHECK(eta > 1.0f && rows >= 2 && fade_rows >= 1, "bad influence fade parameters");
  const float start = 1.0f / eta;
  const float width = float(fade_rows) / float(rows - 1);
  const float t = std::clamp((s - start) / width, 0.0f, 1.0f);
  return t * t * (3.0f - 2.0f * t);
}

void apply_influence_fade(ZonalTable& table, float eta, int fade_rows) {
  for (int i = 0; i < table.rows; ++i) {
    const float weight = influence_fade_weight(float(i) / float(table.rows - 1), eta, table.rows, fade_rows);
    for (int l = 0; l < table.order; ++l) table.values[std::size_t(i) * std::size_t(table.order) + std::size_t(l)] *= weight;
  }
}

OptimalLinearTable make_optimal_linear_table(int order, int rows, float max_norm) {
  PROXYGI_CHECK(has_product(order) && rows >= 2, "OL tables exist for orders 3..6 with >= 2 rows");
  // Sample the single-sphere family densely in alpha and keep the branch where |fhat| increases.
  struct Sample {
    double norm, a, b;
  };
  std::vector<Sample> branch = {{0.0, 1.0, 1.0}};
  constexpr int kSamples = 1024;
  for (int k = 1; k <= kSamples; ++k) {
    const double alpha = 0.5 * kPi * double(k) / double(kSamples);
    std::vector<double> fhat = zonal_to_full(order, log_occlusion_zonal(order, std::sin(alpha)));
    fhat[0] = 0.0;
    double norm_squared = 0.0;
    for (double v : fhat) norm_squared += v * v;
    const double norm = std::sqrt(norm_squared);
    if (norm <= branch.back().norm) break;
    const std::vector<double> g = exp_exact(order, fhat);
    double inner = 0.0;
    for (std::size_t i = 1; i < g.size(); ++i) inner += g[i] * fhat[i];
    branch.push_back({norm, g[0] / kSqrtFourPi, inner / norm_squared});
  }
  OptimalLinearTable table;
  table.order = order;
  table.max_norm = max_norm > 0.0f ? max_norm : float(branch.back().norm);
  std::size_t segment = 0;
  for (int r = 0; r < rows; ++r) {
    const double norm = double(table.max_norm) * r / (rows - 1);
    while (segment + 2 < branch.size() && branch[segment + 1].norm < norm) ++segment;
    const Sample& lo = branch[segment];
    const Sample& hi = branch[std::min(segment + 1, branch.size() - 1)];
    const double t = hi.norm > lo.norm ? std::clamp((norm - lo.norm) / (hi.norm - lo.norm), 0.0, 1.0) : 0.0;
    table.a.push_back(float(lo.a + t * (hi.a - lo.a)));
    table.b.push_back(float(lo.b + t * (hi.b - lo.b)));
  }
  return table;
}

}  // namespace proxygi::sh
