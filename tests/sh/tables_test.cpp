// Occlusion tables against the reference rows of the notes (sh-math.md section 4, order 4).
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "sh/basis.h"
#include "sh/occlusion_tables.h"
#include "sh/quadrature.h"

namespace proxygi::sh {
namespace {

TEST(ShTables, ProxyVisibilityMatchesQuadratureOfTheCap) {
  for (double s : {0.1, 0.5, 0.9, 1.0}) {
    // Integrating the basis over the cap alone is exact (polynomial integrand).
    const SphereQuadrature cap = make_cap_quadrature(std::sqrt(1 - s * s), 8, 16);
    const std::vector<double> projected = project_function(8, cap, [](const glm::dvec3&) { return 1.0; });
    const std::vector<double> zonal = proxy_visibility_zonal(8, s);
    for (int l = 0; l < 8; ++l) EXPECT_NEAR(zonal[std::size_t(l)], projected[std::size_t(coefficient_index(l, 0))], 1e-12) << "l=" << l;
  }
}

TEST(ShTables, LogOcclusionMatchesTheNotesReferenceRows) {
  struct Row {
    double s, f0, f1, f2, f3, norm;
  };
  const Row rows[] = {{0.05, -0.0022, -0.0039, -0.0050, -0.0059, 0.009}, {0.10, -0.0091, -0.0156, -0.0200, -0.0234, 0.034},
                      {0.20, -0.0387, -0.0652, -0.0818, -0.0926, 0.140}, {0.30, -0.0964, -0.1582, -0.1916, -0.2055, 0.322},
                      {0.40, -0.1964, -0.3129, -0.3622, -0.3605, 0.599}, {0.50, -0.3642, -0.5647, -0.6190, -0.5615, 1.009},
                      {0.60, -0.6539, -0.9904, -1.0221, -0.8337, 1.649}, {0.70, -1.2443, -1.8492, -1.7972, -1.3211, 2.897},
                      {0.80, -2.3410, -3.4327, -3.1383, -2.0910, 5.099}, {0.90, -2.9414, -4.0786, -3.2056, -1.6007, 5.429},
                      {0.99, -4.6946, -5.3005, -2.4416, 0.1409, 5.838}};
  for (const Row& row : rows) {
    const std::vector<double> f = log_occlusion_zonal(4, row.s);
    EXPECT_NEAR(f[0], row.f0, 1e-4) << "s=" << row.s;
    EXPECT_NEAR(f[1], row.f1, 1e-4) << "s=" << row.s;
    EXPECT_NEAR(f[2], row.f2, 1e-4) << "s=" << row.s;
    EXPECT_NEAR(f[3], row.f3, 1e-4) << "s=" << row.s;
    // |fhat| of the full (rotated) vector = sqrt(sum_l f_l^2) for l >= 1 (zonal, one entry per band).
    EXPECT_NEAR(std::sqrt(f[1] * f[1] + f[2] * f[2] + f[3] * f[3]), row.norm, 1.5e-3) << "s=" << row.s;
  }
  // The 111116 lut4 row at alpha = 88.06 deg (notes).
  const std::vector<double> f = log_occlusion_zonal(4, std::sin(88.06 * kPi / 180));
  EXPECT_NEAR(f[0], -5.82158, 2e-3);
  EXPECT_NEAR(f[3], 1.10846, 2e-3);
}

TEST(ShTables, OptimalLinearTableMatchesTheNotes) {
  const OptimalLinearTable table = make_optimal_linear_table(4, 1024);
  // |fhat(alpha)| keeps increasing slowly up to 90 deg; the notes see its peak, 6.43, near 89.5 deg.
  EXPECT_NEAR(table.max_norm, 6.43, 0.06);
  struct Row {
    float norm, a, b;
  };
  for (const Row& row : {Row{0.14f, 1.0008f, 0.964f}, Row{0.32f, 1.0039f, 0.919f}, Row{0.60f, 1.0129f, 0.855f},
                         Row{1.01f, 1.0340f, 0.772f}, Row{1.65f, 1.0823f, 0.671f}, Row{2.90f, 1.2175f, 0.546f}}) {
    const glm::vec2 ab = table.lookup(row.norm);
    EXPECT_NEAR(ab.x, row.a, 2e-3) << "norm " << row.norm;
    EXPECT_NEAR(ab.y, row.b, 4e-3) << "norm " << row.norm;
  }
  const glm::vec2 at_zero = table.lookup(0.0f);
  EXPECT_FLOAT_EQ(at_zero.x, 1.0f);
  EXPECT_FLOAT_EQ(at_zero.y, 1.0f);
}

TEST(ShTables, TableLookupInterpolatesTheZonalFunctions) {
  const ZonalTable table = make_log_occlusion_table(4, 256);
  ASSERT_EQ(table.values.size(), 256u * 4u);
  std::vector<float> got(4);
  for (double s : {0.0, 0.123, 0.5, 0.77}) {
    table.lookup(float(s), got);
    const std::vector<double> expected = log_occlusion_zonal(4, s);
    for (int l = 0; l < 4; ++l) EXPECT_NEAR(got[std::size_t(l)], expected[std::size_t(l)], 2e-3 * (1 + std::abs(expected[std::size_t(l)])));
  }
  const ZonalTable visibility = make_proxy_visibility_table(4, 256);
  visibility.lookup(1.0f, got);
  EXPECT_NEAR(got[0], std::sqrt(kPi), 1e-6);  // the full hemisphere
}

TEST(ShTables, InfluenceFadeIsZeroInsideAndOneOutsideAndContinuous) {
  const float eta = 15.0f;
  const int rows = 256;
  EXPECT_EQ(influence_fade_weight(1.0f / eta, eta, rows), 0.0f);
  EXPECT_EQ(influence_fade_weight(0.01f, eta, rows), 0.0f);
  EXPECT_EQ(influence_fade_weight(1.0f / eta + 4.0f / 255.0f, eta, rows), 1.0f);
  float previous = 0.0f;
  for (int k = 0; k <= 1000; ++k) {
    const float s = 1.0f / eta - 0.01f + 0.04f * float(k) / 1000.0f;
    const float weight = influence_fade_weight(s, eta, rows);
    EXPECT_GE(weight, previous);
    EXPECT_LT(weight - previous, 0.02f);  // no jumps
    previous = weight;
  }
  ZonalTable table = make_log_occlusion_table(4, rows);
  apply_influence_fade(table, eta);
  std::vector<float> got(4);
  table.lookup(1.0f / eta, got);
  for (float v : got) EXPECT_EQ(v, 0.0f);
  table.lookup(0.5f, got);
  EXPECT_NEAR(got[0], -0.3642f, 2e-3f);
}

}  // namespace
}  // namespace proxygi::sh
