#include "regress/image_compare.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "ref/flip.h"

namespace proxygi::regress {
namespace {

float channel_difference(const CodeImage& a, std::size_t ia, const CodeImage& b, std::size_t ib) {
  float largest = 0.0f;
  for (std::size_t c = 0; c < 3; ++c) largest = std::max(largest, std::abs(a.codes[ia * 3 + c] - b.codes[ib * 3 + c]));
  return largest;
}

}  // namespace

image::ImageF to_linear(const Rgba8& image) {
  image::ImageF out(image.width, image.height);
  for (std::size_t i = 0; i < out.pixels.size(); ++i)
    out.pixels[i] = glm::vec4(image::srgb8_to_linear(image.pixels[i * 4]), image::srgb8_to_linear(image.pixels[i * 4 + 1]),
                              image::srgb8_to_linear(image.pixels[i * 4 + 2]), 1.0f);
  return out;
}

CodeImage codes_of(const Rgba8& image) {
  CodeImage out{image.width, image.height, std::vector<float>(std::size_t(image.width) * std::size_t(image.height) * 3)};
  for (std::size_t i = 0; i < out.codes.size() / 3; ++i)
    for (std::size_t c = 0; c < 3; ++c) out.codes[i * 3 + c] = float(image.pixels[i * 4 + c]);
  return out;
}

CodeImage codes_of(const image::ImageF& linear) {
  CodeImage out{linear.width, linear.height, std::vector<float>(linear.pixels.size() * 3)};
  for (std::size_t i = 0; i < linear.pixels.size(); ++i)
    for (std::size_t c = 0; c < 3; ++c) {
      const float v = linear.pixels[i][int(c)];
      out.codes[i * 3 + c] = std::isfinite(v) && v > 0.0f ? image::linear_to_srgb(v) * 255.0f : 0.0f;
    }
  return out;
}

image::ImageF to_linear(const CodeImage& image) {
  image::ImageF out(image.width, image.height);
  for (std::size_t i = 0; i < out.pixels.size(); ++i) {
    glm::vec4 p(0.0f, 0.0f, 0.0f, 1.0f);
    for (std::size_t c = 0; c < 3; ++c) p[int(c)] = image::srgb_to_linear(std::clamp(image.codes[i * 3 + c] / 255.0f, 0.0f, 1.0f));
    out.pixels[i] = p;
  }
  return out;
}

Result<ImageComparison> compare_images(const Rgba8& actual, const Rgba8& golden, const std::vector<std::uint8_t>& mask,
                                       const ImageTolerance& tolerance, double scale) {
  return compare_images(codes_of(actual), codes_of(golden), mask, tolerance, scale);
}

Rgba8 from_png(const image::ImageF& linear) {
  Rgba8 out{linear.width, linear.height, std::vector<std::uint8_t>(linear.pixels.size() * 4, 255)};
  for (std::size_t i = 0; i < linear.pixels.size(); ++i)
    for (std::size_t c = 0; c < 3; ++c)
      out.pixels[i * 4 + c] = std::uint8_t(image::linear_to_srgb(std::clamp(linear.pixels[i][int(c)], 0.0f, 1.0f)) * 255.0f + 0.5f);
  return out;
}

Result<ImageComparison> compare_images(const CodeImage& actual, const CodeImage& golden, const std::vector<std::uint8_t>& mask,
                                       const ImageTolerance& tolerance, double scale) {
  if (actual.width != golden.width || actual.height != golden.height)
    return make_error("size mismatch: new " + std::to_string(actual.width) + "x" + std::to_string(actual.height) + ", golden " +
                      std::to_string(golden.width) + "x" + std::to_string(golden.height));
  const int w = actual.width, h = actual.height;
  const int threshold = int(std::floor(tolerance.pixel_threshold * scale));
  const int radius = tolerance.shift_radius;
  ImageComparison out;
  out.diff = image::ImageF(w, h, glm::vec4(0, 0, 0, 1));
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const std::size_t i = std::size_t(y) * std::size_t(w) + std::size_t(x);
      const float d = channel_difference(actual, i, golden, i);
      const float shown = std::min(1.0f, d * 4.0f / 255.0f);
      out.diff.pixels[i] = glm::vec4(shown, shown, shown, 1.0f);
      if (!mask[i]) continue;
      ++out.pixels;
      out.largest = std::max(out.largest, double(d));
      bool fails = d > float(threshold);
      for (int dy = -radius; fails && dy <= radius; ++dy)
        for (int dx = -radius; fails && dx <= radius; ++dx) {
          const int sx = x + dx, sy = y + dy;
          if (sx < 0 || sy < 0 || sx >= w || sy >= h) continue;
          if (channel_difference(actual, i, golden, std::size_t(sy) * std::size_t(w) + std::size_t(sx)) <= float(threshold)) fails = false;
        }
      if (fails) {
        ++out.failing;
        out.diff.pixels[i] = glm::vec4(1.0f, 0.1f, 0.1f, 1.0f);
      }
    }
  out.failing_fraction = out.pixels ? double(out.failing) / double(out.pixels) : 0.0;
  out.passed = out.failing_fraction <= tolerance.max_failing_fraction * scale;
  char line[200];
  std::snprintf(line, sizeof(line), "%zu of %zu pixels beyond %d codes (%.3f %%, allowed %.3f %%), largest %.4g", out.failing,
                out.pixels, threshold, 100.0 * out.failing_fraction, 100.0 * tolerance.max_failing_fraction * scale, out.largest);
  out.summary = line;
  if ((tolerance.flip_mean || tolerance.flip_percentile) && out.pixels > 0) {
    ref::ReceiverMask receivers{w, h, mask};
    auto flip = ref::flip_ldr(to_linear(actual), to_linear(golden), &receivers);
    if (!flip) return flip.error();
    out.flip_mean = flip->mean;
    out.flip = image::ImageF(w, h, glm::vec4(0, 0, 0, 1));
    std::vector<float> values;
    for (std::size_t i = 0; i < flip->map.values.size(); ++i) {
      const float v = flip->map.values[i];
      out.flip.pixels[i] = glm::vec4(v, v, v, 1.0f);
      if (mask[i]) values.push_back(v);
    }
    if (tolerance.flip_mean && out.flip_mean > *tolerance.flip_mean * scale) out.passed = false;
    if (tolerance.flip_percentile) {
      std::sort(values.begin(), values.end());
      const std::size_t at = std::min(values.size() - 1, std::size_t(std::ceil(*tolerance.flip_percentile * double(values.size()))) - 1);
      out.flip_percentile = values[at];
      if (out.flip_percentile > *tolerance.flip_percentile_max * scale) out.passed = false;
    }
    std::snprintf(line, sizeof(line), "; FLIP mean %.4f, p%.0f %.4f", out.flip_mean, 100.0 * tolerance.flip_percentile.value_or(0.99),
                  out.flip_percentile);
    out.summary += line;
  }
  return out;
}

}  // namespace proxygi::regress
