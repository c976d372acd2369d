#include "run/golden.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "image/image.h"

namespace proxygi::run {
namespace {

image::ImageF ldr_to_image(std::span<const std::uint8_t> ldr, int width, int height) {
  image::ImageF image(width, height);
  for (std::size_t i = 0; i < image.pixels.size(); ++i)
    image.pixels[i] = glm::vec4(image::srgb8_to_linear(ldr[i * 4]), image::srgb8_to_linear(ldr[i * 4 + 1]),
                                image::srgb8_to_linear(ldr[i * 4 + 2]), 1.0f);
  return image;
}

}  // namespace

Result<GoldenComparison> compare_with_golden(std::span<const std::uint8_t> rgba8, int width, int height,
                                             const std::filesystem::path& golden, const GoldenTolerance& tolerance) {
  if (rgba8.size() < std::size_t(width) * std::size_t(height) * 4)
    return make_error("golden " + golden.string() + ": the frame holds fewer than " + std::to_string(width) + "x" +
                      std::to_string(height) + " pixels");
  auto expected = image::read_image(golden);
  if (!expected) return make_error("golden " + golden.string() + ": " + expected.message());
  if (expected->width != width || expected->height != height)
    return make_error("golden " + golden.string() + ": " + std::to_string(expected->width) + "x" +
                      std::to_string(expected->height) + ", the frame is " + std::to_string(width) + "x" +
                      std::to_string(height));
  GoldenComparison result;
  result.pixels = width * height;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const std::size_t i = std::size_t(y * width + x) * 4;
      int largest = 0;
      for (int c = 0; c < 3; ++c) {
        const int expected_code = int(image::linear_to_srgb(expected->at(x, y)[c]) * 255.0f + 0.5f);
        largest = std::max(largest, std::abs(int(rgba8[i + std::size_t(c)]) - expected_code));
      }
      result.largest_difference = std::max(result.largest_difference, largest);
      if (largest > 0) ++result.differing_pixels;
      if (largest > tolerance.channel_threshold) ++result.failing_pixels;
    }
  result.passed = double(result.failing_pixels) <= tolerance.max_failing_fraction * double(result.pixels);
  return result;
}

Status write_golden(std::span<const std::uint8_t> rgba8, int width, int height, const std::filesystem::path& golden) {
  return image::write_png(golden, ldr_to_image(rgba8, width, height));
}

}  // namespace proxygi::run
