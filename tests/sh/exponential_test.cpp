// SH exponential and log: identities, exp(log(g)) = g below the critical angle, and agreement
// of the run-time approximations with the exact exponential where they should agree.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "sh/basis.h"
#include "sh/exponential.h"
#include "sh/occlusion_tables.h"
#include "sh/product.h"
#include "sh/rotation.h"

namespace proxygi::sh {
namespace {

double relative_error(std::span<const double> got, std::span<const double> expected) {
  double difference = 0.0, norm = 0.0;
  for (std::size_t i = 0; i < expected.size(); ++i) {
    difference += (got[i] - expected[i]) * (got[i] - expected[i]);
    norm += expected[i] * expected[i];
  }
  return std::sqrt(difference / norm);
}

std::vector<double> rotated_occlusion(int order, double s, const glm::dvec3& dir) {
  std::vector<double> full(static_cast<std::size_t>(order * order));
  rotate_zonal(order, occlusion_zonal(order, s), dir, full);
  return full;
}

TEST(ShExponential, ExpOfZeroIsOneAndDcIsolationIsExact) {
  for (int order = 3; order <= 6; ++order) {
    std::vector<double> zero(static_cast<std::size_t>(order * order), 0.0);
    const std::vector<double> one = exp_exact(order, zero);
    EXPECT_NEAR(one[0], kSqrtFourPi, 1e-12);
    std::mt19937 random(11);
    std::normal_distribution<double> normal(0.0, 0.4);
    std::vector<double> f(zero.size());
    for (double& v : f) v = normal(random);
    std::vector<double> fhat = f;
    fhat[0] = 0.0;
    const std::vector<double> full = exp_exact(order, f), isolated = exp_exact(order, fhat);
    for (std::size_t i = 0; i < f.size(); ++i) EXPECT_NEAR(full[i], std::exp(f[0] * kInvSqrtFourPi) * isolated[i], 1e-10);
  }
}

TEST(ShExponential, ExpOfLogReproducesCapsBelowTheCriticalAngle) {
  // Critical angles (notes section 4): 66.75, 50.5, 40.5, 33.75 degrees for orders 3..6.
  const double critical_degrees[] = {66.75, 50.5, 40.5, 33.75};
  const glm::dvec3 dir = glm::normalize(glm::dvec3(0.2, 0.7, -0.4));
  for (int order = 3; order <= 6; ++order) {
    for (double degrees : {5.0, 20.0, 0.8 * critical_degrees[order - 3]}) {
      const double s = std::sin(degrees * kPi / 180.0);
      const std::vector<double> g = rotated_occlusion(order, s, dir);
      const std::vector<double> roundtrip = exp_exact(order, log_exact(order, g));
      EXPECT_LT(relative_error(roundtrip, g), degrees <= 5.0 ? 1e-8 : 2e-3) << "order " << order << " at " << degrees << " deg";
    }
  }
  // Notes: at order 4 the round trip errs by 5e-11 at 5 deg, 2e-6 at 20 deg and 1.1e-3 at 45 deg
  // (the eps clamp starts to bite before the critical angle); above it, 4.6% at 60 deg.
  const auto roundtrip_error = [&](double degrees) {
    const std::vector<double> g = rotated_occlusion(4, std::sin(degrees * kPi / 180.0), dir);
    return relative_error(exp_exact(4, log_exact(4, g)), g);
  };
  EXPECT_LT(roundtrip_error(5.0), 1e-9);
  EXPECT_NEAR(roundtrip_error(20.0), 2e-6, 1e-6);
  EXPECT_NEAR(roundtrip_error(45.0), 1.1e-3, 1e-4);
  EXPECT_NEAR(roundtrip_error(60.0), 0.046, 0.005);
}

TEST(ShExponential, LogIsRotationEquivariantForCaps) {
  // log of a rotated cap = rotation of the zonal log (the table + rotate path).
  const int order = 4;
  const double s = 0.45;
  const glm::dvec3 dir = glm::normalize(glm::dvec3(-0.3, 0.1, 0.9));
  std::vector<double> expected(16);
  rotate_zonal(order, log_occlusion_zonal(order, s), dir, expected);
  const std::vector<double> got = log_exact(order, rotated_occlusion(order, s, dir));
  EXPECT_LT(relative_error(got, expected), 1e-9);
}

TEST(ShExponential, ApproximationsConvergeToTheExactExponential) {
  const int order = 4;
  const OptimalLinearTable table = make_optimal_linear_table(order);
  std::mt19937 random(2);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int trial = 0; trial < 20; ++trial) {
    // Sum of 3 log caps of 10..30 degrees in random directions.
    std::vector<double> f(16, 0.0);
    for (int k = 0; k < 3; ++k) {
      const double z = 2 * unit(random) - 1, phi = 2 * kPi * unit(random);
      const glm::dvec3 dir(std::sqrt(1 - z * z) * std::cos(phi), std::sqrt(1 - z * z) * std::sin(phi), z);
      std::vector<double> one(16);
      rotate_zonal(order, log_occlusion_zonal(order, std::sin((10 + 20 * unit(random)) * kPi / 180)), dir, one);
      for (int i = 0; i < 16; ++i) f[std::size_t(i)] += one[std::size_t(i)];
    }
    const std::vector<double> exact = exp_exact(order, f);
    std::vector<float> f_float(f.begin(), f.end()), out(16);
    exp_product_series(order, f_float, 12, out);
    EXPECT_LT(relative_error(std::vector<double>(out.begin(), out.end()), exact), 1e-4);
    // HYB with a tiny threshold is nearly exact (many squarings of an almost-linear exp).
    const int squarings = exp_hybrid(order, f_float, table, 0.01f, out);
    EXPECT_GE(squarings, 1);
    EXPECT_LT(relative_error(std::vector<double>(out.begin(), out.end()), exact), 2e-3);
  }
}

// HYB is continuous where its squaring count changes (|f̂| = τ 2^s): the blend toward the next
// count meets it there, where OL(f̂/2^s) then s squarings alone steps (the F7 jump).
TEST(ShExponential, HybridIsContinuousWhereTheSquaringCountChanges) {
  constexpr int kOrder = 4;
  const OptimalLinearTable table = make_optimal_linear_table(kOrder);
  const float tau = 0.25f;
  std::vector<double> zonal_dir(16);
  rotate_zonal(kOrder, log_occlusion_zonal(kOrder, std::sin(25.0 * kPi / 180)), glm::normalize(glm::dvec3(0.3, 0.5, 0.8)), zonal_dir);
  double norm = 0.0;
  for (int i = 1; i < 16; ++i) norm += zonal_dir[std::size_t(i)] * zonal_dir[std::size_t(i)];
  norm = std::sqrt(norm);
  // Unblended HYB with s squarings, as it was.
  auto stepped = [&](const std::vector<float>& f, int s, float* out) {
    std::vector<float> scaled(f);
    for (int i = 1; i < 16; ++i) scaled[std::size_t(i)] = f[std::size_t(i)] / float(1 << s);
    scaled[0] = 0.0f;
    float g[16], squared[16];
    exp_optimal_linear<kOrder>(scaled.data(), table, g);
    for (int k = 0; k < s; ++k) {
      square<kOrder>(g, squared);
      std::copy(squared, squared + 16, g);
    }
    std::copy(g, g + 16, out);
  };
  // Across the switch (|f̂| from τ 2^s (1 − ε) to τ 2^s (1 + ε)) the result may change by what
  // the same 2ε changes it within one count (|f̂| from τ 2^s (1 − 3ε) to τ 2^s (1 − ε)), not more.
  const double epsilon = 1e-4;
  for (int s = 0; s <= 4; ++s) {
    auto at = [&](double factor) {
      std::vector<float> f(16);
      for (int i = 1; i < 16; ++i) f[std::size_t(i)] = float(zonal_dir[std::size_t(i)] * tau * double(1 << s) / norm * factor);
      return f;
    };
    const std::vector<float> further = at(1.0 - 3.0 * epsilon), below = at(1.0 - epsilon), above = at(1.0 + epsilon);
    float far_out[16], lo[16], hi[16], lo_stepped[16], hi_stepped[16];
    EXPECT_EQ(exp_hybrid<kOrder>(further.data(), table, tau, far_out), s);
    EXPECT_EQ(exp_hybrid<kOrder>(below.data(), table, tau, lo), s);
    EXPECT_EQ(exp_hybrid<kOrder>(above.data(), table, tau, hi), s + 1);
    stepped(below, s, lo_stepped);
    stepped(above, s + 1, hi_stepped);
    double slope = 0.0, jump = 0.0, jump_stepped = 0.0;
    for (int i = 0; i < 16; ++i) {
      slope = std::max(slope, double(std::abs(lo[i] - far_out[i])));
      jump = std::max(jump, double(std::abs(hi[i] - lo[i])));
      jump_stepped = std::max(jump_stepped, double(std::abs(hi_stepped[i] - lo_stepped[i])));
    }
    EXPECT_LE(jump, 1.5 * slope + 1e-6) << "s = " << s;
    EXPECT_GT(jump_stepped, 10.0 * slope) << "s = " << s << ": unblended, HYB must step here for this test to mean anything";
    std::printf("s = %d: change across the switch %.2e, over as far within one count %.2e (unblended: %.2e)\n", s, jump,
                slope, jump_stepped);
  }
}

}  // namespace
}  // namespace proxygi::sh
