#pragma once
// render.quality's predictors (issue 18 item 3): from cheap inputs of one shot (the lighting's SH,
// the characters' projected size and fit) they predict the relative MSE against the path-traced
// reference of each (SH order n, receiver scale k, upsampler) the frame offers, with the model
//
//   E(n, k, up) = F · R(n) · K(k_eff, up)
//
// calibrated on the committed chart (quality/calibration.h has the constants and where they
// came from):
//   F      the scene's floor at n = 5, k = 1, from its rigs' outside volume (floor_from_fit);
//   R(n)   the order's excess over order 5, its lighting part scaled by the lighting's SH energy
//          above band n against the chart's (order_ratio): a sky without a sun, whose energy
//          sits in the low bands, needs fewer bands than the same sky with a sun;
//   K      the receivers' excess at 1/k with an upsampler, at the effective scale
//          k_eff = k × (the reference projected radius / this shot's): a smaller character on
//          screen gets a coarser effective k, so the same error asks for a finer k (scale_ratio).
// No GPU, no world: plain numbers in, numbers out (quality/choose.h gathers them from a world).
#include <array>
#include <optional>
#include <span>

#include "settings/render_settings.h"

namespace proxygi::quality {

// e(n), n = 3..6 (index n − 3): the share of the SH energy Σ_m c_lm² of bands 0..5 that lies in
// bands l >= n, from an SH vector of at least order 6 (36 coefficients; one channel or the
// luminance; bands above 5 ignored, as the chart's references are band-limited to order 6). A
// lighting with no energy gives zeros.
std::array<double, 4> energy_above(std::span<const double> lighting);

// R(n) for a lighting with energy shares `energy` (energy_above): 1 + (R_chart(n) − 1) × s with
// s = min(e(n) / e_chart(n), kMaxEnergyScale) for n < 6 (s = 1 where the chart's share is 0).
// n in kMinShOrder..kMaxShOrder.
double order_ratio(int order, const std::array<double, 4>& energy);

// K(k_eff, up), k one of kReceiverScales, radius_px > 0 the characters' projected radius (pixels).
// k = 1 gives 1; else k_eff = k × kReferenceRadiusPx / radius_px and K is the calibration's
// table, linear in log2 k_eff between its knots 0..4 (k_eff 1..16), extrapolated past 16 with the
// last slope, 1 below k_eff 1.
double scale_ratio(int k, settings::Upsampling upsampling, double radius_px);

// F from a rig's outside_volume_ratio (proxies::FitQuality), clamped to [kMinFloor, kMaxFloor];
// kUnknownFloor without one.
double floor_from_fit(std::optional<double> outside_volume_ratio);

// The predicted relative MSE of one setting: floor × order_ratio × scale_ratio.
double predict_error(double floor, const std::array<double, 4>& energy, int order, int k,
                     settings::Upsampling upsampling, double radius_px);
// The chart's frame time of that setting (calibration::kChartMs), ms at 192²: for ranking only.
double predicted_ms(int order, int k, settings::Upsampling upsampling);

}  // namespace proxygi::quality
