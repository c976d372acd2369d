#include "sh/influence_eta.h"

#include <algorithm>
#include <cmath>

#include <glm/glm.hpp>

#include "sh/basis.h"
#include "sh/environment.h"
#include "sh/quadrature.h"

namespace proxygi::sh {
namespace {

glm::dvec3 direction_at(double theta, double phi) {
  return {std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi)};
}

}  // namespace

double lighting_concentration(int order, std::span<const double> lighting) {
  // The brightest direction: a 64 × 128 (θ, φ) grid, then a local search at shrinking steps
  // (the radiance is a polynomial of degree < 6: smooth at the grid's 2.8°).
  const int rows = 64, columns = 128;
  double best = -1e300, best_theta = 0.0, best_phi = 0.0;
  for (int i = 0; i < rows; ++i)
    for (int j = 0; j < columns; ++j) {
      const double theta = kPi * (i + 0.5) / rows, phi = 2.0 * kPi * j / columns;
      const double value = evaluate_expansion(order, lighting, direction_at(theta, phi));
      if (value > best) best = value, best_theta = theta, best_phi = phi;
    }
  for (double step = kPi / rows; step > 1e-6; step *= 0.5)
    for (bool moved = true; moved;) {
      moved = false;
      for (const auto& [dt, dp] : {std::pair{1.0, 0.0}, {-1.0, 0.0}, {0.0, 1.0}, {0.0, -1.0}}) {
        const double theta = std::clamp(best_theta + dt * step, 0.0, kPi), phi = best_phi + dp * step;
        const double value = evaluate_expansion(order, lighting, direction_at(theta, phi));
        if (value > best) best = value, best_theta = theta, best_phi = phi, moved = true;
      }
    }
  const std::vector<double> lh = lighting_times_clamped_cosine(order, lighting, direction_at(best_theta, best_phi));
  const double irradiance = std::sqrt(4.0 * kPi) * lh[0];
  if (!(best > 0.0) || !(irradiance > 0.0)) return 1.0;
  return kPi * best / irradiance;
}

float eta_for_cutoff(double concentration, double epsilon) {
  return float(std::sqrt(std::max(concentration, 0.0) / epsilon));
}

}  // namespace proxygi::sh
