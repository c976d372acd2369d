// The ground-lit lighting L' = L above the horizon, the lit ground below (sh/ground_bounce.h):
// its projection against an independent quadrature, and irradiance against closed forms.
#include <cmath>
#include <functional>
#include <vector>

#include <gtest/gtest.h>

#include "sh/basis.h"
#include "sh/convolution.h"
#include "sh/environment.h"
#include "sh/ground_bounce.h"
#include "sh/quadrature.h"

namespace proxygi::sh {
namespace {

// E(N) = Σ A_l L_lm y_lm(N): the unshadowed irradiance of an order-n SH radiance.
double irradiance(int order, std::vector<double> lighting, const glm::dvec3& normal) {
  convolve_zonal(order, clamped_cosine_zonal(order), lighting);
  return evaluate_expansion(order, lighting, normal);
}

// Midpoint rule over (θ from +Y, φ) with each cell's exact solid angle; the horizon is a cell
// boundary, so the step there is integrated without smearing. Independent of the Gauss rule.
std::vector<double> project_by_midpoint_rule(int order, const std::function<double(const glm::dvec3&)>& f) {
  const int rows = 1024, columns = 2048, count = order * order;
  std::vector<double> result(std::size_t(count), 0.0), basis(result.size());
  for (int row = 0; row < rows; ++row) {
    const double top = kPi * row / rows, bottom = kPi * (row + 1) / rows, theta = 0.5 * (top + bottom);
    const double weight = (std::cos(top) - std::cos(bottom)) * 2.0 * kPi / columns;
    for (int column = 0; column < columns; ++column) {
      const double phi = 2.0 * kPi * (column + 0.5) / columns;
      const glm::dvec3 d(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
      evaluate_basis(order, d, basis);
      const double value = weight * f(d);
      for (int i = 0; i < count; ++i) result[std::size_t(i)] += value * basis[std::size_t(i)];
    }
  }
  return result;
}

TEST(GroundBounce, ProjectionMatchesQuadratureOfSkyAboveAndGroundBelow) {
  // The default analytic sky with its sun (windowed as the frame uses it), ground radiance 0.7.
  for (int order = 3; order <= 6; ++order) {
    std::vector<double> sky = project_sky(order, AnalyticSky{}).channels[1];
    apply_ringing_window(order, sky);
    const double ground = 0.7;
    const std::vector<double> projected = replace_below_horizon(order, sky, ground);
    const std::vector<double> expected = project_by_midpoint_rule(order, [&](const glm::dvec3& d) {
      return d.y > 0.0 ? evaluate_expansion(order, sky, d) : ground;
    });
    double norm = 0.0;
    for (double value : expected) norm += value * value;
    for (std::size_t i = 0; i < expected.size(); ++i)
      EXPECT_NEAR(projected[i], expected[i], 1e-4 * std::sqrt(norm)) << "order " << order << " coefficient " << i;
  }
}

TEST(GroundBounce, UniformSkyOverGroundGivesTheHemisphereClosedForm) {
  // Sky L above, ground of albedo a: E_g = π L, g = a L, and a receiver whose normal makes
  // cos θ = c with +Y gets E = π ((L + g)/2 + (L − g) c / 2) exactly (the step's odd bands ≥ 3
  // meet A_l = 0): facing down, E = a π L.
  const double sky_radiance = 1.3, albedo = 0.6;
  for (int order = 3; order <= 6; ++order) {
    std::vector<double> sky(std::size_t(order * order), 0.0);
    sky[0] = sky_radiance * kSqrtFourPi;
    const double ground_irradiance_value = ground_irradiance(order, sky);
    EXPECT_NEAR(ground_irradiance_value, kPi * sky_radiance, 1e-12);
    const double g = albedo * ground_irradiance_value / kPi;
    const std::vector<double> lit = replace_below_horizon(order, sky, g);
    EXPECT_NEAR(irradiance(order, lit, {0.0, -1.0, 0.0}), albedo * kPi * sky_radiance, 1e-9) << "order " << order;
    for (double c : {-0.8, -0.3, 0.0, 0.4, 0.9}) {
      const glm::dvec3 normal(std::sqrt(1.0 - c * c), c, 0.0);
      const double expected = kPi * (0.5 * (sky_radiance + g) + 0.5 * (sky_radiance - g) * c);
      EXPECT_NEAR(irradiance(order, lit, normal), expected, 1e-9) << "order " << order << " cos " << c;
    }
  }
}

TEST(GroundBounce, GroundIrradianceIncludesTheSunAndEqualsTheUpwardLH) {
  // E_g of the sky with its sun is the upward receiver's unshadowed irradiance (an independent
  // hemisphere quadrature, sh/environment.h). Zeroing the sun's radiance removes its disc, whose
  // irradiance on the ground is L_sun · 2π (1 − cos r) · sun_y, to the band limit's few %.
  const int order = 4;
  AnalyticSky sky;
  std::vector<double> lighting = project_sky(order, sky).channels[0];
  const double with_sun = ground_irradiance(order, lighting);
  EXPECT_NEAR(with_sun, kSqrtFourPi * lighting_times_clamped_cosine(order, lighting, {0.0, 1.0, 0.0})[0], 1e-9 * with_sun);
  const double sun_on_ground =
      sky.sun_radiance.x * 2.0 * kPi * (1.0 - std::cos(sky.sun_radius_radians)) * sky.sun_direction.y;
  sky.sun_radiance = glm::dvec3(0.0);
  const double without_sun = ground_irradiance(order, project_sky(order, sky).channels[0]);
  EXPECT_NEAR(with_sun - without_sun, sun_on_ground, 0.03 * sun_on_ground);
  EXPECT_GT(sun_on_ground, 0.2 * with_sun) << "the sun must be a sizeable part of the ground's light";
}

TEST(GroundBounce, ZeroGroundRadianceKeepsOnlyTheUpperHemisphere) {
  // g = 0: L' is L times the upper-hemisphere indicator; a constant sky's L' has DC √π·L
  // (half the sphere) and E(−Y) = 0.
  const int order = 4;
  std::vector<double> sky(16, 0.0);
  sky[0] = kSqrtFourPi;
  const std::vector<double> lit = replace_below_horizon(order, sky, 0.0);
  EXPECT_NEAR(lit[0], 0.5 * kSqrtFourPi, 1e-12);
  EXPECT_NEAR(irradiance(order, lit, {0.0, -1.0, 0.0}), 0.0, 1e-12);
  EXPECT_NEAR(irradiance(order, lit, {0.0, 1.0, 0.0}), kPi, 1e-12);
}

}  // namespace
}  // namespace proxygi::sh
