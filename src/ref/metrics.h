#pragma once
// Image error metrics against a reference, averaged over "receiver pixels".
//
// Conventions shared by every metric in ref/ (metrics.h, ssim.h, flip.h):
// - `test` is the image being judged, `reference` the ground truth; both linear RGB (ImageF),
//   same size, else the call fails. Alpha is ignored.
// - A ReceiverMask selects the pixels the mean is taken over; no mask means every pixel.
//   Pixels outside the mask get 0 in the per-pixel map and do not enter the mean.
// - MetricResult::mean is the metric itself (for RMSE: the root of the mean square error over
//   receiver pixels and RGB); MetricResult::map is the per-pixel quantity each header describes.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "base/result.h"
#include "image/image.h"
#include "ref/metrics_plane.h"

namespace proxygi::ref {

struct ReceiverMask {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> receiver;  // 1 = receiver pixel, 0 = ignored; index y * width + x

  bool contains(std::size_t index) const { return receiver[index] != 0; }
  std::size_t count() const;
};

// Receiver where the mask image is "white": max(r, g, b) * a > 0.5 (a PNG painted white on
// black, or a render's coverage). Values are linear (read_image decodes sRGB).
ReceiverMask mask_from_image(const image::ImageF& mask);
// Receiver where alpha > threshold (e.g. the receiver/coverage alpha of a render).
ReceiverMask mask_from_alpha(const image::ImageF& image, float threshold = 0.5f);
// Receiver where predicate(x, y) is true.
ReceiverMask mask_where(int width, int height, const std::function<bool(int x, int y)>& predicate);

struct MetricResult {
  double mean = 0.0;        // the metric over receiver pixels
  Plane map;                // per-pixel value (0 outside the mask)
  std::size_t pixels = 0;   // receiver pixels that entered the mean
};

// Checks sizes (test, reference and mask agree; not empty) and that at least one receiver
// remains. Errors read "size mismatch: test is 4x4, reference is 4x5".
Status check_comparable(const image::ImageF& test, const image::ImageF& reference, const ReceiverMask* mask);

// Root-mean-square error over receiver pixels and the R, G, B channels, in the images' linear
// units: sqrt(mean_{p, c} (x - r)^2). map = per-pixel sqrt(mean_c (x - r)^2).
Result<MetricResult> rmse(const image::ImageF& test, const image::ImageF& reference, const ReceiverMask* mask = nullptr);

// Relative MSE: mean over receiver pixels and R, G, B of (x - r)^2 / (r^2 + epsilon), with
// epsilon = 1e-2 by default (the common choice, e.g. Müller's interactive-viewer tests), which
// keeps near-black reference pixels from dominating. map = per-pixel mean over R, G, B.
inline constexpr double kRelativeMseEpsilon = 1e-2;
Result<MetricResult> relative_mse(const image::ImageF& test, const image::ImageF& reference,
                                  const ReceiverMask* mask = nullptr, double epsilon = kRelativeMseEpsilon);

// Mean Rec. 709 luminance 0.2126 R + 0.7152 G + 0.0722 B over the mask's pixels (every pixel
// without a mask; 0 when the mask is empty). Linear units of the image. The ratio of a test's to
// its reference's over a region (the character) shows a missing light path that the whole-image
// errors hide.
double mean_luminance(const image::ImageF& image, const ReceiverMask* mask = nullptr);

// Mean of map over the mask (pixels where `valid` is non-null and false are skipped too).
MetricResult pool_mean(Plane map, const ReceiverMask* mask, const std::vector<std::uint8_t>* valid = nullptr);

}  // namespace proxygi::ref
