#pragma once
// Image comparison for image and differential checks: per-pixel threshold (any channel, sRGB
// codes on the 0..255 scale) with an optional shift radius (a pixel passes when some golden pixel within the radius
// matches: moving silhouettes), the failing fraction over a region, LDR-FLIP mean and
// percentile over the region (src/ref/flip.h), and difference / FLIP images for reports.
#include <cstdint>
#include <vector>

#include "base/result.h"
#include "image/image.h"
#include "regress/scenario.h"
#include "regress/scenario_run.h"

namespace proxygi::regress {

// RGB pixels as sRGB codes on the 0..255 scale, in float: an 8-bit frame exactly, a linear AOV
// (EXR golden) without rounding; above 1 the sRGB curve is extended, so bright AOVs do not clip.
struct CodeImage {
  int width = 0, height = 0;
  std::vector<float> codes;  // 3 per pixel, row 0 on top
};
CodeImage codes_of(const Rgba8& image);
CodeImage codes_of(const image::ImageF& linear);  // NaN/Inf and negatives count as 0

struct ImageComparison {
  std::size_t pixels = 0;         // in the region
  std::size_t failing = 0;        // beyond the threshold (after the shift search)
  double largest = 0.0;           // codes, without shift (whole codes for 8-bit images)
  double failing_fraction = 0.0;
  double flip_mean = 0.0;         // computed when the tolerance asks for FLIP
  double flip_percentile = 0.0;
  bool passed = false;
  std::string summary;            // "12 of 9216 pixels beyond 5 codes (0.13 %), largest 40"
  image::ImageF diff;             // |new - golden| × 4, failing pixels red
  image::ImageF flip;             // per-pixel FLIP (gray), when computed
};

// `scale` loosens every threshold (fallback tier). Sizes must agree (else an error naming both).
Result<ImageComparison> compare_images(const CodeImage& actual, const CodeImage& golden, const std::vector<std::uint8_t>& mask,
                                       const ImageTolerance& tolerance, double scale = 1.0);
Result<ImageComparison> compare_images(const Rgba8& actual, const Rgba8& golden, const std::vector<std::uint8_t>& mask,
                                       const ImageTolerance& tolerance, double scale = 1.0);

image::ImageF to_linear(const Rgba8& image);
image::ImageF to_linear(const CodeImage& image);  // clamped to [0, 1] (LDR: FLIP, report PNGs)
Rgba8 from_png(const image::ImageF& linear);  // sRGB-encode a PNG read as linear (exact for 8-bit PNGs)

}  // namespace proxygi::regress
