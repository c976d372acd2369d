// η from the lighting (sh/influence_eta.h): c_L = π L_max / E(ω_max) on lights whose answer is
// known in closed form or by an independent brute-force quadrature.
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "sh/basis.h"
#include "sh/convolution.h"
#include "sh/environment.h"
#include "sh/influence_eta.h"
#include "sh/quadrature.h"

namespace proxygi::sh {
namespace {

TEST(ShInfluenceEta, UniformLightHasConcentrationOne) {
  std::vector<double> lighting(16, 0.0);
  lighting[0] = 2.0 * std::sqrt(4.0 * kPi);  // L = 2 everywhere
  EXPECT_NEAR(lighting_concentration(4, lighting), 1.0, 1e-9);
  EXPECT_NEAR(eta_for_cutoff(1.0, 1.0 / 255.0), std::sqrt(255.0), 1e-4);
}

TEST(ShInfluenceEta, WindowedDeltaLightMatchesTheLegendreClosedForm) {
  // A delta light at d projected to order n and windowed: L(ω) = Σ_l (2l+1)/4π w_l P_l(d·ω), so
  // L_max = Σ (2l+1) w_l / 4π and E(d) = Σ (2l+1)/4π w_l 2π ∫₀¹ P_l(z) z dz.
  const double half_moments[] = {1.0 / 2.0, 1.0 / 3.0, 1.0 / 8.0, 0.0, -1.0 / 48.0, 0.0};
  const glm::dvec3 d = glm::normalize(glm::dvec3(0.3, 0.8, 0.4));
  for (int order : {3, 4, 6}) {
    std::vector<double> lighting(std::size_t(order * order));
    evaluate_basis(order, d, lighting);
    apply_ringing_window(order, lighting);  // h = 2n, as the frame does
    double peak = 0.0, irradiance = 0.0;
    for (int l = 0; l < order; ++l) {
      const double w = std::cos(kPi * l / (2.0 * 2.0 * order));
      peak += (2 * l + 1) * w / (4.0 * kPi);
      irradiance += (2 * l + 1) * w / (4.0 * kPi) * 2.0 * kPi * half_moments[l];
    }
    EXPECT_NEAR(lighting_concentration(order, lighting), kPi * peak / irradiance, 1e-6) << order;
  }
  // The notes' order-4 figure: c_L ≈ 3.49, so η ≈ 30 where a uniform light needs 16.
  std::vector<double> lighting(16);
  evaluate_basis(4, d, lighting);
  apply_ringing_window(4, lighting);
  EXPECT_NEAR(lighting_concentration(4, lighting), 3.49, 0.01);
  EXPECT_NEAR(eta_for_cutoff(lighting_concentration(4, lighting), 1.0 / 255.0), 29.8, 0.1);
}

TEST(ShInfluenceEta, SkyMatchesABruteForceQuadrature) {
  // The default analytic sky at order 4 (luminance): L_max over a dense grid, E by a quadrature of
  // L max(n·ω, 0) (not the hemisphere rule the function uses).
  const RgbSh sky = project_sky(4, AnalyticSky{});
  std::vector<double> lighting(16);
  for (std::size_t i = 0; i < lighting.size(); ++i)
    lighting[i] = 0.2126 * sky.channels[0][i] + 0.7152 * sky.channels[1][i] + 0.0722 * sky.channels[2][i];
  double peak = -1.0;
  glm::dvec3 peak_direction(0.0);
  const SphereQuadrature grid = make_sphere_quadrature(300, 600);
  for (const glm::dvec3& direction : grid.directions) {
    const double value = evaluate_expansion(4, lighting, direction);
    if (value > peak) peak = value, peak_direction = direction;
  }
  double irradiance = 0.0;
  for (std::size_t q = 0; q < grid.size(); ++q)
    irradiance += grid.weights[q] * evaluate_expansion(4, lighting, grid.directions[q]) *
                  std::max(glm::dot(grid.directions[q], peak_direction), 0.0);
  const double expected = kPi * peak / irradiance;
  EXPECT_GT(expected, 1.2);  // a sun: concentrated, well above the uniform 1
  EXPECT_NEAR(lighting_concentration(4, lighting), expected, 2e-3 * expected);
}

}  // namespace
}  // namespace proxygi::sh
