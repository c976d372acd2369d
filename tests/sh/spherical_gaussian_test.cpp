// Spherical Gaussians: integral, product and inner product against numerical quadrature; the
// seed's diffuse lobe (eq. 1, λ_d ≈ 2) and its diffuse convolution.
#include <cmath>
#include <cstdio>
#include <numbers>

#include <gtest/gtest.h>

#include "sh/quadrature.h"
#include "sh/spherical_gaussian.h"

namespace proxygi::sh {
namespace {

constexpr double kPi = std::numbers::pi;

double integrate(const SphereQuadrature& q, const auto& f) {
  double sum = 0.0;
  for (std::size_t i = 0; i < q.size(); ++i) sum += q.weights[i] * f(q.directions[i]);
  return sum;
}

// max(ω·n, 0)/π − G(ω; n, λ)/A(λ) over the angle, sampled densely: the lobe fit's worst error.
double worst_lobe_error(double sharpness) {
  double worst = 0.0;
  for (int k = 0; k <= 20000; ++k) {
    const double c = std::cos(kPi * k / 20000.0);
    worst = std::max(worst, std::abs(std::max(c, 0.0) / kPi - std::exp(sharpness * (c - 1.0)) / sg_area(sharpness)));
  }
  return worst;
}

TEST(SphericalGaussian, IntegralMatchesQuadrature) {
  const SphereQuadrature q = make_sphere_quadrature(256, 512);
  for (double sharpness : {0.0, 1e-9, 0.05, 0.5, 2.0, 8.0, 40.0}) {
    const SphericalGaussian g{glm::normalize(glm::dvec3(0.3, -0.5, 0.8)), sharpness, 1.7};
    const double numeric = integrate(q, [&](const glm::dvec3& w) { return sg_evaluate(g, w); });
    EXPECT_NEAR(sg_integral(g), numeric, 1e-9 * numeric) << "λ=" << sharpness;
  }
  EXPECT_DOUBLE_EQ(sg_area(0.0), 4.0 * kPi);
}

TEST(SphericalGaussian, ProductIsAnSgAndIntegratesLikeQuadrature) {
  const SphereQuadrature q = make_sphere_quadrature(256, 512);
  const SphericalGaussian pairs[][2] = {
      {{glm::dvec3(0, 0, 1), 3.0, 2.0}, {glm::normalize(glm::dvec3(1, 0, 1)), 5.0, 0.5}},
      {{glm::dvec3(0, 1, 0), 12.0, 1.0}, {glm::dvec3(0, -1, 0), 2.0, 3.0}},  // opposite axes
      {{glm::normalize(glm::dvec3(1, 2, 3)), 0.3, 1.0}, {glm::normalize(glm::dvec3(-2, 1, 0.5)), 20.0, 1.0}},
      {{glm::dvec3(1, 0, 0), 4.0, 1.0}, {glm::dvec3(-1, 0, 0), 4.0, 1.0}},  // the product is a constant
  };
  for (const auto& [a, b] : pairs) {
    const SphericalGaussian p = sg_product(a, b);
    for (std::size_t i = 0; i < q.size(); i += 997) {
      const glm::dvec3& w = q.directions[i];
      EXPECT_NEAR(sg_evaluate(p, w), sg_evaluate(a, w) * sg_evaluate(b, w), 1e-12 * (1.0 + sg_evaluate(p, w)));
    }
    const double numeric = integrate(q, [&](const glm::dvec3& w) { return sg_evaluate(a, w) * sg_evaluate(b, w); });
    EXPECT_NEAR(sg_inner_product(a, b), numeric, 1e-9 * numeric);
  }
}

TEST(SphericalGaussian, IwasakiApproximationBecomesExactForSharpLobes) {
  // The approximation the seed's diffuse result uses: its relative error falls as one lobe sharpens.
  const SphericalGaussian wide{glm::dvec3(0, 0, 1), kDiffuseLobeSharpness, 1.0};
  double previous = 1.0;
  for (double sharpness : {4.0, 16.0, 64.0, 256.0, 1024.0}) {
    const SphericalGaussian sharp{glm::normalize(glm::dvec3(0.4, 0.1, 0.9)), sharpness, 1.0};
    const double exact = sg_inner_product(sharp, wide);
    const double relative = std::abs(sg_inner_product_approx(sharp, wide) - exact) / exact;
    EXPECT_LT(relative, previous) << "λ=" << sharpness;
    previous = relative;
  }
  EXPECT_LT(previous, 2e-3);
}

TEST(SphericalGaussian, DiffuseLobeSharpnessIsNearTheLeastSquaresFit) {
  // Eq. 1: max(ω·n, 0)/π ≈ G(ω; n, λ_d)/A(λ_d), "λ_d ≈ 2 by least squares". Measured here: the
  // L² fit over the sphere is λ ≈ 2.29, and the seed's λ_d = 2 has 1.23× its squared error. The
  // project keeps the seed's 2 (the lobe bound in the tests below is computed for it).
  const SphereQuadrature q = make_sphere_quadrature(256, 8);
  auto squared_error = [&](double sharpness) {
    return integrate(q, [&](const glm::dvec3& w) {
      const double d = std::max(w.z, 0.0) / kPi - std::exp(sharpness * (w.z - 1.0)) / sg_area(sharpness);
      return d * d;
    });
  };
  double best = 0.0, best_error = 1e300;
  for (int k = 100; k <= 400; ++k) {
    const double e = squared_error(k / 100.0);
    if (e < best_error) best_error = e, best = k / 100.0;
  }
  std::printf("least-squares λ = %.2f, squared error of λ_d = 2 / of it: %.3f\n", best,
              squared_error(kDiffuseLobeSharpness) / best_error);
  EXPECT_GT(best, kDiffuseLobeSharpness);
  EXPECT_LT(best, 2.5);
  EXPECT_LT(squared_error(kDiffuseLobeSharpness), 1.3 * best_error);
}

TEST(SphericalGaussian, DiffuseConvolutionMatchesQuadratureWithinTheLobeError) {
  // |∫ G (max(ω·n,0) − π G_d/A_d)| ≤ π e ∫ G, e the lobe fit's worst error: a bound from eq. 1
  // for the exact product integral; the approximate one (the seed's) adds Iwasaki's error.
  const SphereQuadrature q = make_sphere_quadrature(256, 512);
  const double e = worst_lobe_error(kDiffuseLobeSharpness);
  const glm::dvec3 normal = glm::normalize(glm::dvec3(0.2, 0.9, -0.3));
  const SphericalGaussian cosine{normal, kDiffuseLobeSharpness, kPi / sg_area(kDiffuseLobeSharpness)};
  for (double sharpness : {0.5, 3.0, 30.0, 300.0}) {
    for (double tilt : {0.0, 0.7, 1.4, 2.2}) {
      const glm::dvec3 axis = glm::normalize(std::cos(tilt) * normal + std::sin(tilt) * glm::dvec3(1, 0, 0));
      const SphericalGaussian g{axis, sharpness, 2.0};
      const double numeric =
          integrate(q, [&](const glm::dvec3& w) { return sg_evaluate(g, w) * std::max(glm::dot(w, normal), 0.0); });
      EXPECT_NEAR(sg_inner_product(g, cosine), numeric, kPi * e * sg_integral(g)) << "λ=" << sharpness << " tilt=" << tilt;
      EXPECT_GE(sg_diffuse_irradiance(g, normal), 0.0);
    }
  }
}

}  // namespace
}  // namespace proxygi::sh
