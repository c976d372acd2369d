#pragma once
// The calibration constants of render.quality's error model (quality/predictors.h), each fitted on
// the committed chart docs/bench-chart.csv (192² pixels, 3 frames, 1024-spp one-bounce references
// under the default stage's sky and sun band-limited to SH order 6; proxy rows with the averaged
// operator; scenes default, CesiumMan, Fox, RiggedSimple) by scripts/quality_fit.py:
//
//   log E(scene, n, k, up) = log F(scene) + log R(n) + log K(log2 k_eff, up),
//   k_eff = k × kReferenceRadiusPx / (the scene's projected character radius)   (k > 1; K = 1 at k = 1)
//
// least squares over the 4 scenes × orders 3..6 × (k 1, and k 2/4/8 × bilinear/bilateral) = 112
// rows, R(5) = 1, K piecewise linear in log2 k_eff with knots 0..4. Residual: rms 5.9 % in log,
// worst 17 % (without the size term, one K per k: rms 8.4 %, worst 27 %: the default scene's
// character is half as large on screen and pays twice the others' k 8 excess).
#include <array>

namespace proxygi::quality::calibration {

// R(n): the error of order n relative to order 5, under the chart's lighting, n = 3..6.
inline constexpr std::array<double, 4> kOrderRatio = {1.3162, 1.2385, 1.0, 1.0065};

// e(n): the chart lighting's share of SH energy (luminance, unwindowed, bands 0..5) in bands
// >= n, n = 3..6: energy_above of the default stage's sky and sun projected at order 6
// (tests/quality recomputes it from scene::default_scene(); the same sky without its sun: 0.035,
// 0.012, 0.011). The part of R(n) − 1 due to the lighting scales with a shot's e(n) / this.
inline constexpr std::array<double, 4> kChartEnergyAbove = {0.685369, 0.500437, 0.274224, 0.0};
// A lighting with more energy above band n than the chart's extrapolates R(n) − 1 at most this far.
inline constexpr double kMaxEnergyScale = 4.0;

// The chart scenes' characters' projected radius (their tracked spheres' bounding sphere, pixels
// at 192², mean of the 3 chart frames; tests/quality recomputes them): default 25.93,
// CesiumMan 49.47, Fox 43.71, RiggedSimple 39.21. The reference radius of k_eff is the shared
// characters' mean.
inline constexpr double kDefaultSceneRadiusPx = 25.93;
inline constexpr double kReferenceRadiusPx = 44.0;

// K at log2 k_eff = 0, 1, 2, 3, 4 for each upsampler (linear in between, extrapolated past 4
// with the 3 → 4 slope; 1 below 0).
inline constexpr std::array<double, 5> kScaleRatioBilinear = {1.0, 0.9630, 0.9521, 1.0369, 1.6212};
inline constexpr std::array<double, 5> kScaleRatioBilateral = {1.0, 1.0089, 1.0556, 1.0614, 1.5620};

// F: the scene's error at order 5, k = 1, from its characters' fit (proxies FitQuality): the
// 4 scenes' fitted F (default 0.00573, CesiumMan 0.01381, Fox 0.01546, RiggedSimple 0.01480)
// against their rigs' outside_volume_ratio (0.1593, 0.2036, 0.2403, 0.2122; the fit_version 2
// rigs of main 2dfce6a, proxygi fit defaults) give F = kFloorIntercept + kFloorSlope × ratio
// (least squares; residual 0.0014 rms, the default scene predicted 0.0068). Four points: a weak
// fit, clamped to [kMinFloor, kMaxFloor].
inline constexpr double kFloorIntercept = -0.013362;
inline constexpr double kFloorSlope = 0.126622;
inline constexpr double kMinFloor = 0.004;
inline constexpr double kMaxFloor = 0.03;
// A rig without fit quality (an old rig file) gets the 4 scenes' mean F.
inline constexpr double kUnknownFloor = 0.01245;

// Frame time of each setting, ms at 192² on the chart's machine (scene "all", averaged operator):
// [order 3..6][k 1, 2, 4, 8][bilinear, bilateral] (k 1 has one value). Only the ranking is used.
inline constexpr double kChartMs[4][4][2] = {
    {{29.68, 29.68}, {10.72, 10.53}, {5.99, 5.89}, {4.18, 4.40}},
    {{35.61, 35.61}, {12.70, 13.61}, {6.74, 7.24}, {4.00, 4.97}},
    {{46.00, 46.00}, {15.03, 15.00}, {6.95, 7.15}, {4.40, 4.71}},
    {{71.30, 71.30}, {22.23, 20.24}, {8.36, 9.22}, {4.69, 5.27}},
};

}  // namespace proxygi::quality::calibration
