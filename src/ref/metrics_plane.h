#pragma once
// Single-channel float images and the two filters the metrics and the guided filter are built
// from: separable convolution with replicated borders (FLIP, SSIM) and box means over windows
// truncated at the image border (guided filter). Row-major, top row first, like ImageF.
#include <cstddef>
#include <span>
#include <vector>

#include "image/image.h"

namespace proxygi::ref {

struct Plane {
  int width = 0;
  int height = 0;
  std::vector<float> values;  // width * height, index y * width + x

  Plane() = default;
  Plane(int w, int h, float fill = 0.0f) : width(w), height(h), values(std::size_t(w) * std::size_t(h), fill) {}
  float& at(int x, int y) { return values[std::size_t(y) * std::size_t(width) + std::size_t(x)]; }
  float at(int x, int y) const { return values[std::size_t(y) * std::size_t(width) + std::size_t(x)]; }
};

// One channel (0 = r .. 3 = a) of an image.
Plane channel_plane(const image::ImageF& image, int channel);

// out(x, y) = sum_{i,j} kernel_x[i] kernel_y[j] in(x + i - rx, y + j - ry), with rx = |kernel_x|/2
// (kernels have odd length, centered) and coordinates outside the image clamped to the edge
// (replicated border, as OpenCV's BORDER_REPLICATE). Weights and sums are double: FLIP's feature
// detectors have weights summing to 0 and take a square root of the response, so float rounding
// on a flat image (~1e-8) would otherwise show up as a 1e-4 error.
Plane convolve_separable(const Plane& in, std::span<const double> kernel_x, std::span<const double> kernel_y);
// The same on a double-precision width x height grid (SSIM's moments: E[x^2] - E[x]^2 cancels).
std::vector<double> convolve_separable(std::span<const double> in, int width, int height,
                                       std::span<const double> kernel_x, std::span<const double> kernel_y);

// Mean of `in` over the (2r+1)^2 window around each pixel, the window cut to the image (the mean
// is over the pixels inside). O(width * height) whatever r: summed-area table in double.
Plane box_mean(const Plane& in, int radius);

}  // namespace proxygi::ref
