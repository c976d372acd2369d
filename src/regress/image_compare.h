#pragma once
// Image comparison for image and differential checks: per-pixel threshold (any channel, 8-bit
// codes) with an optional shift radius (a pixel passes when some golden pixel within the radius
// matches: moving silhouettes), the failing fraction over a region, LDR-FLIP mean and
// percentile over the region (src/ref/flip.h), and difference / FLIP images for reports.
#include <cstdint>
#include <vector>

#include "base/result.h"
#include "image/image.h"
#include "regress/scenario.h"
#include "regress/scenario_run.h"

namespace proxygi::regress {

struct ImageComparison {
  std::size_t pixels = 0;         // in the region
  std::size_t failing = 0;        // beyond the threshold (after the shift search)
  int largest = 0;                // codes, without shift
  double failing_fraction = 0.0;
  double flip_mean = 0.0;         // computed when the tolerance asks for FLIP
  double flip_percentile = 0.0;
  bool passed = false;
  std::string summary;            // "12 of 9216 pixels beyond 5 codes (0.13 %), largest 40"
  image::ImageF diff;             // |new - golden| × 4, failing pixels red
  image::ImageF flip;             // per-pixel FLIP (gray), when computed
};

// `scale` loosens every threshold (fallback tier). Sizes must agree (else an error naming both).
Result<ImageComparison> compare_images(const Rgba8& actual, const Rgba8& golden, const std::vector<std::uint8_t>& mask,
                                       const ImageTolerance& tolerance, double scale = 1.0);

image::ImageF to_linear(const Rgba8& image);
Rgba8 from_png(const image::ImageF& linear);  // sRGB-encode a PNG read as linear (exact for 8-bit PNGs)

}  // namespace proxygi::regress
