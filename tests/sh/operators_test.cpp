// Zonal rotation, clamped cosine, H(N), windowing, and the closed-form shading of one sphere.
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "sh/basis.h"
#include "sh/convolution.h"
#include "sh/exponential.h"
#include "sh/occlusion_tables.h"
#include "sh/quadrature.h"
#include "sh/rotation.h"

namespace proxygi::sh {
namespace {

double dot(std::span<const double> a, std::span<const double> b) {
  double sum = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) sum += a[i] * b[i];
  return sum;
}

TEST(ShOperators, ZonalRotationMatchesDirectProjectionOfARotatedCap) {
  const int order = 6;
  const glm::dvec3 dir = glm::normalize(glm::dvec3(0.4, -0.7, 0.3));
  const double s = std::sin(25.0 * kPi / 180.0);
  std::vector<double> rotated(36);
  rotate_zonal(order, proxy_visibility_zonal(order, s), dir, rotated);
  // Direct projection of the cap about dir: integrate the basis over the cap with a cap rule
  // about +z carried to dir (exact: polynomial integrand).
  const SphereQuadrature cap = make_cap_quadrature(std::sqrt(1 - s * s), 10, 24);
  const glm::dmat3 to_dir = rotation_between({0, 0, 1}, dir);
  std::vector<double> projected(36, 0.0), basis(36);
  for (std::size_t q = 0; q < cap.size(); ++q) {
    evaluate_basis(order, to_dir * cap.directions[q], basis);
    for (int i = 0; i < 36; ++i) projected[std::size_t(i)] += cap.weights[q] * basis[std::size_t(i)];
  }
  for (int i = 0; i < 36; ++i) EXPECT_NEAR(rotated[std::size_t(i)], projected[std::size_t(i)], 1e-12) << "index " << i;
  // The float fast path agrees.
  std::vector<float> zonal_float(6), fast(36);
  const std::vector<double> zonal = proxy_visibility_zonal(order, s);
  for (int l = 0; l < 6; ++l) zonal_float[std::size_t(l)] = float(zonal[std::size_t(l)]);
  rotate_zonal<6>(zonal_float.data(), glm::vec3(dir), fast.data());
  for (int i = 0; i < 36; ++i) EXPECT_NEAR(fast[std::size_t(i)], projected[std::size_t(i)], 1e-5);
}

TEST(ShOperators, GeneralRotationMatrixAgreesWithZonalRotation) {
  const int order = 5;
  const glm::dvec3 dir = glm::normalize(glm::dvec3(-0.2, 0.5, 0.8));
  std::vector<double> along_z(25), along_dir(25);
  const std::vector<double> zonal = log_occlusion_zonal(order, 0.4);
  rotate_zonal(order, zonal, glm::dvec3(0, 0, 1), along_z);
  rotate_zonal(order, zonal, dir, along_dir);
  const Eigen::MatrixXd r = rotation_matrix(order, rotation_between({0, 0, 1}, dir));
  const Eigen::VectorXd turned = r * Eigen::Map<const Eigen::VectorXd>(along_z.data(), 25);
  for (int i = 0; i < 25; ++i) EXPECT_NEAR(turned(i), along_dir[std::size_t(i)], 1e-12);
  EXPECT_LT((r * r.transpose() - Eigen::MatrixXd::Identity(25, 25)).norm(), 1e-12);
}

TEST(ShOperators, ClampedCosineMatchesTheNotes) {
  const std::vector<double> h = clamped_cosine_zonal(8);
  const double expected[8] = {0.886226925, 1.023326708, 0.495415912, 0.0, -0.110778366, 0.0, 0.049927135, 0.0};
  for (int l = 0; l < 8; ++l) EXPECT_NEAR(h[std::size_t(l)], expected[l], 1e-9) << "l=" << l;
  // Against quadrature of max(z, 0) (exact on the upper cap).
  const std::vector<double> projected = project_function(8, make_cap_quadrature(0.0, 8, 18), [](const glm::dvec3& d) { return d.z; });
  for (int l = 0; l < 8; ++l) EXPECT_NEAR(h[std::size_t(l)], projected[std::size_t(coefficient_index(l, 0))], 1e-12);
  // Convolution factors A_l = pi, 2pi/3, pi/4, 0, -pi/24.
  EXPECT_NEAR(zonal_rotation_scale(0) * h[0], kPi, 1e-12);
  EXPECT_NEAR(zonal_rotation_scale(1) * h[1], 2 * kPi / 3, 1e-12);
  EXPECT_NEAR(zonal_rotation_scale(4) * h[4], -kPi / 24, 1e-12);
}

TEST(ShOperators, IrradianceOfAConstantSkyIsPi) {
  for (int order = 1; order <= 8; ++order) {
    std::vector<double> lighting(std::size_t(order * order), 0.0);
    lighting[0] = kSqrtFourPi;
    const std::vector<double> h = clamped_cosine_about(order, glm::normalize(glm::dvec3(1, 2, 3)));
    EXPECT_NEAR(dot(h, lighting), kPi, 1e-12);
    convolve_zonal(order, clamped_cosine_zonal(order), lighting);
    EXPECT_NEAR(lighting[0], kPi * kSqrtFourPi, 1e-12);
  }
}

TEST(ShOperators, RingingWindow) {
  const std::vector<double> w = ringing_window(4);  // h = 8
  EXPECT_DOUBLE_EQ(w[0], 1.0);
  EXPECT_NEAR(w[1], std::cos(kPi / 16), 1e-15);
  EXPECT_NEAR(w[3], std::cos(3 * kPi / 16), 1e-15);
  std::vector<double> sh(16, 1.0);
  apply_ringing_window(4, sh);
  EXPECT_NEAR(sh[9], std::cos(3 * kPi / 16), 1e-15);
  EXPECT_EQ(ringing_window(4, 2.0)[3], 0.0);  // bands at or beyond h vanish
}

TEST(ShOperators, SphereAboveTheHorizonUnderAWhiteSkyLosesPiS2CosBeta) {
  // Closed form: a sphere entirely above the tangent plane, seen at half-angle alpha (s = sin
  // alpha) and angle beta from the normal, removes pi s^2 cos(beta) of the irradiance pi.
  // SH shading: lost = pi - O . H(N) with O = exp*(sum of one rotated log occlusion). The SH
  // truncation misses sum_{l >= n} c_l h_l P_l(cos beta); the bound below is those terms up to
  // band 7 (beyond, |c_l h_l| < 1e-3 for these caps) plus the exp(log) round-trip error.
  const glm::dvec3 normal(0, 0, 1);
  for (int order = 4; order <= 6; ++order) {
    for (double s : {0.15, 0.3, 0.45}) {
      if (std::asin(s) > (order == 6 ? 0.55 : 0.75)) continue;  // stay below the critical angle
      for (double beta_degrees : {0.0, 30.0, 55.0}) {
        const double beta = beta_degrees * kPi / 180.0;
        if (beta + std::asin(s) >= kPi / 2) continue;
        const glm::dvec3 dir(std::sin(beta), 0.0, std::cos(beta));
        std::vector<double> log_vector(std::size_t(order * order));
        rotate_zonal(order, log_occlusion_zonal(order, s), dir, log_vector);
        const std::vector<double> occlusion = exp_exact(order, log_vector);
        const double lost = kPi - dot(occlusion, clamped_cosine_about(order, normal));
        const double expected = kPi * s * s * std::cos(beta);
        const std::vector<double> c = proxy_visibility_zonal(8, s), h = clamped_cosine_zonal(8);
        double truncation = 0.0;
        for (int l = order; l < 8; ++l) truncation += std::abs(c[std::size_t(l)] * h[std::size_t(l)]);
        EXPECT_NEAR(lost, expected, truncation + 2e-3 * expected) << "order " << order << " s " << s << " beta " << beta_degrees;
      }
    }
  }
}

}  // namespace
}  // namespace proxygi::sh
