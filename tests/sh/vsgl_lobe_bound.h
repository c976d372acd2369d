#pragma once
// The bound shared by the "K = number of VPLs equals brute-force gathering" tests: per VPL the
// irradiance is π Φ/r² · (g_i g_p) instead of π Φ/r² · (c_i c_p), with c = max(cos, 0)/π the
// clamped cosine and g = G/A(λ_d) eq. 1's lobe; |g_i g_p − c_i c_p| ≤ e (1/A(λ_d) + 1/π) with
// e = max |g − c| over the angle (sampled at 20 001 angles).
#include <algorithm>
#include <cmath>
#include <numbers>

#include "sh/spherical_gaussian.h"
#include "sh/vsgl.h"

namespace proxygi::sh::testing {

inline double diffuse_lobe_pair_bound() {
  constexpr double kPi = std::numbers::pi;
  double e = 0.0;
  for (int k = 0; k <= 20000; ++k) {
    const double c = std::cos(kPi * k / 20000.0);
    e = std::max(e, std::abs(std::max(c, 0.0) / kPi -
                             std::exp(kDiffuseLobeSharpness * (c - 1.0)) / sg_area(kDiffuseLobeSharpness)));
  }
  return e * (1.0 / sg_area(kDiffuseLobeSharpness) + 1.0 / kPi);
}

}  // namespace proxygi::sh::testing
