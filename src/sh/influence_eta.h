#pragma once
// η chosen from the lighting (notes/stability.md §1): cutting a sphere's shadow at distance η·r
// costs a receiver about ΔE/E ≈ c_L/η² of its unshadowed irradiance, where
//   c_L = π L_max / E(ω_max)
// is how concentrated the lighting is: L_max its largest radiance (over directions), ω_max where
// it is, E(ω_max) = ∫ L max(ω_max·ω, 0) dω the irradiance of a receiver facing it. c_L = 1 for a
// uniform light and grows toward a delta light (an order-4 delta windowed with h = 8: 3.49).
// η = √(c_L/ε) keeps that cut-off error at ε.
#include <span>

namespace proxygi::sh {

// c_L of a lighting given by its order-`order` SH vector (one channel, or the luminance; radiance
// in any unit). Lighting with no positive radiance gives 1 (no concentration to account for).
double lighting_concentration(int order, std::span<const double> lighting);

// η = √(c_L/ε), ε the accepted cut-off error as a fraction of the unshadowed irradiance (c_L ≥ 1
// for any light, since E ≤ π L_max: η ≥ √(1/ε)).
float eta_for_cutoff(double concentration, double epsilon);

}  // namespace proxygi::sh
