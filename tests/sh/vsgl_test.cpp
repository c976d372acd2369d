// VSGL (papers/vsgl-tokuyoshi.md, notes/prt-vsgl.md §3): one test per corrected erratum of the
// seed, each showing the corrected formula matches quadrature (or the direct moments) and the
// seed's reading does not; and K = number of VPLs against brute-force unshadowed gathering.
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "sh/quadrature.h"
#include "sh/spherical_gaussian.h"
#include "tests/sh/vsgl_lobe_bound.h"
#include "sh/vsgl.h"

namespace proxygi::sh {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kShrink = kDiffuseLobeSharpness / (kDiffuseLobeSharpness + 1.0);

std::vector<VirtualPointLight> random_lights(int count, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0), positive(0.1, 1.0);
  std::vector<VirtualPointLight> out;
  for (int i = 0; i < count; ++i) {
    VirtualPointLight v;
    v.position = glm::dvec3(3.0 + 0.4 * u(rng), 1.0 + 0.8 * u(rng), -2.0 + 0.3 * u(rng));
    v.normal = glm::normalize(glm::dvec3(u(rng), u(rng), u(rng)) + glm::dvec3(0.0, 0.3, 0.0));
    v.flux = glm::dvec3(positive(rng), positive(rng), positive(rng));
    out.push_back(v);
  }
  return out;
}

VsglSums sums_of(const std::vector<VirtualPointLight>& lights, const glm::dvec3& origin) {
  VsglSums sums;
  for (const VirtualPointLight& v : lights) add_light(sums, v, origin);
  return sums;
}

double integrate(const SphereQuadrature& q, const auto& f) {
  double sum = 0.0;
  for (std::size_t i = 0; i < q.size(); ++i) sum += q.weights[i] * f(q.directions[i]);
  return sum;
}

TEST(VsglErrata, PositionSumsAreWeightedPositionsNotAxes) {
  // Erratum 1: §2.2 lists Σ w ξ̄ three times; the mean and variance need Σ w x and Σ w ‖x‖².
  const auto lights = random_lights(40, 1);
  const glm::dvec3 origin(3.0, 1.0, -2.0);
  const auto fitted = fit_vsgl(sums_of(lights, origin), origin);
  ASSERT_TRUE(fitted);
  double weight = 0.0;
  glm::dvec3 mean(0.0), axis_mean(0.0);
  for (const auto& v : lights) weight += luminance(v.flux), mean += luminance(v.flux) * v.position;
  mean /= weight;
  double variance = 0.0;
  for (const auto& v : lights) {
    variance += luminance(v.flux) * glm::dot(v.position - mean, v.position - mean) / weight;  // two-pass moments
    axis_mean += luminance(v.flux) * kShrink * v.normal / weight;
  }
  EXPECT_NEAR(glm::length(fitted->mean - mean), 0.0, 1e-12);
  EXPECT_NEAR(fitted->variance, variance, 1e-12);
  // The seed's literal list: the "mean" from Σ w ξ̄ is a direction, metres away from the VPLs.
  EXPECT_GT(glm::length(axis_mean - mean), 1.0);
}

TEST(VsglErrata, AxisIsTheNormalizedBarredAverage) {
  // Erratum 2: ξ_v = ξ̄_v/‖ξ̄_v‖, λ_v = ‖ξ̄_v‖/(1 − ‖ξ̄_v‖) with ξ̄_v the *weighted average* (the
  // seed's hat). Checks: one VPL gives back its own lobe (λ_v = λ_d, ξ_v = n); the fitted lobe
  // carries the VPLs' total flux (quadrature of c_v G = Σ Φ R); scaling every flux changes nothing
  // but c_v. Reading the hat as the unnormalized sum Σ w ξ̄ breaks the last.
  const SphereQuadrature q = make_sphere_quadrature(128, 256);
  VirtualPointLight one{glm::dvec3(1, 2, 3), glm::normalize(glm::dvec3(0.2, 1.0, 0.1)), glm::dvec3(0.3, 0.5, 0.2)};
  const auto single = fit_vsgl(sums_of({one}, glm::dvec3(0.0)), glm::dvec3(0.0));
  ASSERT_TRUE(single);
  EXPECT_NEAR(single->sharpness, kDiffuseLobeSharpness, 1e-12);
  EXPECT_NEAR(glm::length(single->axis - one.normal), 0.0, 1e-12);

  auto lights = random_lights(30, 2);
  const auto fitted = fit_vsgl(sums_of(lights, glm::dvec3(0.0)), glm::dvec3(0.0));
  ASSERT_TRUE(fitted);
  glm::dvec3 total(0.0);
  for (const auto& v : lights) total += v.flux;
  for (int c = 0; c < 3; ++c) {
    const SphericalGaussian g{fitted->axis, fitted->sharpness, fitted->amplitude[c]};
    EXPECT_NEAR(integrate(q, [&](const glm::dvec3& w) { return sg_evaluate(g, w); }), total[c], 1e-9 * total[c]);
  }
  for (auto& v : lights) v.flux *= 3.0;
  const VsglSums tripled = sums_of(lights, glm::dvec3(0.0));
  const auto scaled = fit_vsgl(tripled, glm::dvec3(0.0));
  ASSERT_TRUE(scaled);
  EXPECT_NEAR(scaled->sharpness, fitted->sharpness, 1e-12);
  EXPECT_NEAR(glm::length(scaled->axis - fitted->axis), 0.0, 1e-12);
  const double hat = glm::length(tripled.weighted_axis);  // the unnormalized reading
  const double hat_before = glm::length(sums_of(random_lights(30, 2), glm::dvec3(0.0)).weighted_axis);
  EXPECT_GT(std::abs(hat / (1.0 - hat) - hat_before / (1.0 - hat_before)), 0.1);
}

TEST(VsglErrata, GaussianSphereRadiusIsTheDistanceToTheMean) {
  // Erratum 3: eq. 6 holds on the sphere of radius ‖μ_v − x_p‖ around x_p (the seed writes μ_r):
  // g(‖x_r − μ_v‖, σ²) = G(ω; ξ_μ, λ_σ) exactly there, and not on another radius.
  const SphereQuadrature q = make_sphere_quadrature(32, 64);
  const glm::dvec3 mean(0.5, 1.2, -0.4), receiver(0.0, 0.0, 0.3);
  const double variance = 0.09, radius = glm::length(mean - receiver);
  const SphericalGaussian g{(mean - receiver) / radius, radius * radius / variance, 1.0};
  auto gaussian = [&](double r, const glm::dvec3& w) {
    const glm::dvec3 x = receiver + r * w;
    return std::exp(-glm::dot(x - mean, x - mean) / (2.0 * variance));
  };
  double worst = 0.0, worst_other = 0.0;
  for (const glm::dvec3& w : q.directions) {
    worst = std::max(worst, std::abs(gaussian(radius, w) - sg_evaluate(g, w)));
    worst_other = std::max(worst_other, std::abs(gaussian(1.3 * radius, w) - sg_evaluate(g, w)));
  }
  EXPECT_LT(worst, 1e-12);
  EXPECT_GT(worst_other, 0.1);
}

TEST(VsglErrata, AverageOfNormalizedLobesIsPositive) {
  // Erratum 4: the weighted average of normalized SGs (§2.1) integrates to +1 (quadrature), as
  // the fitted normalized SG does; the seed's leading minus makes it −1.
  const SphereQuadrature q = make_sphere_quadrature(128, 256);
  const auto lights = random_lights(25, 3);
  const auto fitted = fit_vsgl(sums_of(lights, glm::dvec3(0.0)), glm::dvec3(0.0));
  ASSERT_TRUE(fitted);
  double weight = 0.0;
  for (const auto& v : lights) weight += luminance(v.flux);
  const double average = integrate(q, [&](const glm::dvec3& w) {
    double sum = 0.0;
    for (const auto& v : lights)
      sum += luminance(v.flux) * sg_evaluate({v.normal, kDiffuseLobeSharpness, 1.0}, w) / sg_area(kDiffuseLobeSharpness);
    return sum / weight;
  });
  const double fitted_integral =
      integrate(q, [&](const glm::dvec3& w) { return sg_evaluate({fitted->axis, fitted->sharpness, 1.0}, w); }) /
      sg_area(fitted->sharpness);
  EXPECT_NEAR(average, 1.0, 1e-9);
  EXPECT_NEAR(fitted_integral, average, 1e-9);
  EXPECT_GT(std::abs(fitted_integral - -average), 1.9);
}

TEST(Vsgl, OneLightPerVplEqualsBruteForceGathering) {
  // K = number of VPLs: each VSGL is one VPL (σ² = 0, floored at kVsglMinRelativeVariance r²),
  // so the only approximations are the two clamped cosines replaced by eq. 1's lobe. Per VPL the
  // irradiance is π Φ/r² · (g_i g_p) instead of π Φ/r² · (c_i c_p) with c = max(cos, 0)/π and
  // g = G/A(λ_d); |g_i g_p − c_i c_p| ≤ e (1/A(λ_d) + 1/π), e = max |g − c| over the angle. The
  // floor adds O(λ_d/λ_σ) = 2e-6 relative (1e-5 allowed).
  const double pair_bound = testing::diffuse_lobe_pair_bound();
  const auto lights = random_lights(60, 4);
  std::vector<Vsgl> vsgls;
  for (const auto& v : lights) vsgls.push_back(*fit_vsgl(sums_of({v}, v.position), v.position));
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int checked = 0;
  for (int r = 0; r < 50; ++r) {
    const glm::dvec3 p(u(rng) * 2.0, 0.5 + u(rng), u(rng) * 2.0);
    const glm::dvec3 n = glm::normalize(glm::dvec3(u(rng), 1.0 + u(rng), u(rng)));
    const glm::dvec3 brute = gather_vpl_irradiance(lights, p, n);
    glm::dvec3 summed(0.0), bound(0.0);
    for (std::size_t i = 0; i < lights.size(); ++i) {
      summed += vsgl_irradiance(vsgls[i], p, n);
      const glm::dvec3 offset = lights[i].position - p;
      bound += kPi * lights[i].flux / glm::dot(offset, offset) * pair_bound;
    }
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(summed[c], brute[c], bound[c] + 1e-5 * brute[c]) << "receiver " << r << " channel " << c;
      ++checked;
    }
  }
  EXPECT_EQ(checked, 150);
}

TEST(Vsgl, IncomingLobeCarriesTheIrradianceOfAFarCluster) {
  // Seen from far away (σ ≪ r), eq. 7's lobe integrated with the exact clamped cosine gives the
  // VSGL's intensity toward the receiver / r², the irradiance of a point source: ∫ L_in cos dω →
  // c_v G(−ξ_μ; ξ_v, λ_v) cos / r². Checked by quadrature at growing distance.
  const SphereQuadrature q = make_sphere_quadrature(512, 1024);
  Vsgl light;
  light.axis = glm::normalize(glm::dvec3(0.0, -1.0, 0.3));
  light.sharpness = 1.5;
  light.amplitude = glm::dvec3(2.0);
  light.mean = glm::dvec3(0.0, 0.0, 0.0);
  light.variance = 0.01;
  const glm::dvec3 n(0.0, 1.0, 0.0);
  double previous = 1.0;
  for (double distance : {1.0, 3.0, 10.0}) {
    const glm::dvec3 p(0.2 * distance, -distance, 0.1 * distance);
    const auto lobe = vsgl_incoming(light, p);
    ASSERT_TRUE(lobe);
    const double numeric = integrate(q, [&](const glm::dvec3& w) {
      return lobe->amplitude.x * sg_evaluate({lobe->axis, lobe->sharpness, 1.0}, w) * std::max(glm::dot(w, n), 0.0);
    });
    const glm::dvec3 to = light.mean - p;
    const double r2 = glm::dot(to, to);
    const glm::dvec3 w = to / std::sqrt(r2);
    const double point = light.amplitude.x * sg_evaluate({light.axis, light.sharpness, 1.0}, -w) * glm::dot(w, n) / r2;
    const double relative = std::abs(numeric - point) / point;
    EXPECT_LT(relative, previous) << "distance " << distance;
    previous = relative;
  }
  EXPECT_LT(previous, 1e-3);
}

}  // namespace
}  // namespace proxygi::sh
