#pragma once
// FLIP, reimplemented from its papers (no code taken from NVIDIA's release):
//   LDR-FLIP: Andersson, Nilsson, Akenine-Möller, Oskarsson, Åström, Fairchild,
//             "FLIP: A Difference Evaluator for Alternating Images", HPG 2020.
//   HDR-FLIP: Andersson, Nilsson, Shirley, Akenine-Möller,
//             "Visualizing Errors in Rendered High Dynamic Range Images", EG 2021.
//
// LDR-FLIP, per pixel, in [0, 1] (0 = no visible difference):
//   color:   linear RGB -> YCxCz; spatial CSF filters in degrees of visual angle (achromatic
//            a1=1, b1=0.0047; red-green a1=1, b1=0.0053; blue-yellow a1=34.1, b1=0.04, a2=13.5,
//            b2=0.025; kernel s(r) = sum a sqrt(pi/b) exp(-pi^2 r^2 / b), radius
//            ceil(3 sqrt(b_max / (2 pi^2)) ppd), normalized to 1); back to linear RGB, clamp to
//            [0, 1]; CIELAB with Hunt adjustment (a, b scaled by 0.01 L); HyAB distance raised to
//            qc = 0.7 and remapped with pc = 0.4, pt = 0.95 against cmax = HyAB(green, blue)^qc.
//   feature: on Y/Yn of the unfiltered images, edge (1st derivative of Gaussian) and point (2nd
//            derivative) detectors with sigma = 0.5 w ppd, w = 0.082 degrees, radius ceil(3 sigma),
//            positive weights normalized to 1 and negative to -1; feature difference
//            max(|‖edge_r‖ − ‖edge_t‖|, |‖point_r‖ − ‖point_t‖|), scaled (x / sqrt 2)^qf, qf = 0.5.
//   error:   color^(1 − feature).
// Filters replicate border pixels. D65 white, the sRGB primaries' exact XYZ matrix.
//
// HDR-FLIP: max over exposures of LDR-FLIP on images tone mapped with the ACES fit
// (exposure 2^e, negatives clipped to 0, result clamped to [0, 1]). Exposures run from
// start = log2(x_max / Y_max) to stop = log2(x_min / Y_median) of the *reference* luminance
// (x_max, x_min: where the tone curve reaches 0.85), in max(2, ceil(stop − start)) steps. A median
// of 0 is floored at 1e-6 Y_max so an image that is mostly black still gets finite exposures.
//
// Inputs are linear RGB (ImageF; PNGs are decoded from sRGB by read_image). LDR-FLIP clamps them
// to [0, 1]; HDR-FLIP takes any non-negative values. See metrics.h for masks and pooling.
#include "ref/metrics.h"

namespace proxygi::ref {

// 0.7 m wide 4K monitor seen from 0.7 m: (0.7 * 3840 / 0.7) * pi / 180 = 67.02 pixels per degree.
inline constexpr double kDefaultPixelsPerDegree = 0.7 * 3840.0 / 0.7 * 3.14159265358979323846 / 180.0;

struct FlipOptions {
  double pixels_per_degree = kDefaultPixelsPerDegree;
};

struct HdrFlipOptions {
  double pixels_per_degree = kDefaultPixelsPerDegree;
  bool automatic_exposures = true;  // else use the three fields below
  double start_exposure = 0.0;
  double stop_exposure = 0.0;
  int exposure_count = 2;
};

// LDR-FLIP. map = per-pixel FLIP in [0, 1]; mean over receiver pixels.
Result<MetricResult> flip_ldr(const image::ImageF& test, const image::ImageF& reference,
                              const ReceiverMask* mask = nullptr, const FlipOptions& options = {});

struct HdrFlipResult {
  MetricResult flip;             // per-pixel max over exposures
  double start_exposure = 0.0;   // the exposure range actually used
  double stop_exposure = 0.0;
  int exposure_count = 0;
};
Result<HdrFlipResult> flip_hdr(const image::ImageF& test, const image::ImageF& reference,
                               const ReceiverMask* mask = nullptr, const HdrFlipOptions& options = {});

// The ACES filmic fit HDR-FLIP assumes (Narkowicz), with exposure 2^exposure, for one channel.
float flip_tone_map_aces(float linear, double exposure);

}  // namespace proxygi::ref
