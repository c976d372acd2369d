#pragma once
// The lit ground as a light source for receivers above it (docs/ground-bounce.md derives this).
//
// Scene: a Lambertian ground plane y = 0 (normal +Y, albedo ρ per channel) reaching the horizon,
// under distant lighting L(s) given as an order-n SH vector (conventions in sh/basis.h; world
// +Y up). Unshadowed, the ground's irradiance is the same everywhere:
//   E_g = ∫_{s_y > 0} L(s) s_y ds = Σ_{l<n} A_l L_lm y_lm(+Y)      (exact for band-limited L)
// and it leaves with the uniform radiance g = ρ E_g / π. A receiver anywhere above the plane sees
// L above its horizon and the ground (g) below it, so its incident radiance is
//   L'(s) = L(s) U(s) + g (1 − U(s)),   U(s) = [s_y > 0],
// whose order-n projection is
//   L'_i = Σ_j (M_U)_ij L_j + g (√(4π) δ_i0 − u_i),
//   (M_U)_ij = ∫_{s_y>0} y_i y_j ds,   u_i = ∫_{s_y>0} y_i ds.
// The integrands are polynomials of degree ≤ 2(n−1) whose odd powers of sin θ (θ from +Y) cancel
// over φ, so a Gauss–Legendre rule in s_y on [0, 1] with n nodes times 2n uniform φ samples is
// exact; the functions below use that rule. Everything the lighting carries (the sun disc
// included: it is inside the SH projection) lights the ground, so E_g includes the sun.
#include <span>
#include <vector>

namespace proxygi::sh {

// E_g = ∫_{s_y>0} L(s) s_y ds for one channel (not divided by π). lighting.size() ≥ order².
double ground_irradiance(int order, std::span<const double> lighting);

// The order-n projection of L above the horizon and the constant `ground_radiance` below it
// (one channel; lighting.size() ≥ order²; returns order² values).
std::vector<double> replace_below_horizon(int order, std::span<const double> lighting, double ground_radiance);

}  // namespace proxygi::sh
