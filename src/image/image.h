#pragma once
// Float images and their files. ImageF holds linear RGBA radiance (or any float data), row-major,
// top row first. PNG files are sRGB 8-bit: read_image converts them to linear, write_png
// converts linear to sRGB after clamping to [0, 1]. Writes are atomic (temporary file + rename).
#include <filesystem>
#include <vector>

#include <glm/glm.hpp>

#include "base/result.h"

namespace proxygi::image {

struct ImageF {
  int width = 0;
  int height = 0;
  std::vector<glm::vec4> pixels;  // width * height, index y * width + x

  ImageF() = default;
  ImageF(int w, int h, glm::vec4 fill = glm::vec4(0.0f)) : width(w), height(h), pixels(std::size_t(w) * std::size_t(h), fill) {}
  glm::vec4& at(int x, int y) { return pixels[std::size_t(y) * std::size_t(width) + std::size_t(x)]; }
  const glm::vec4& at(int x, int y) const { return pixels[std::size_t(y) * std::size_t(width) + std::size_t(x)]; }
};

// Reads .hdr (Radiance RGBE), .exr (OpenEXR, RGB(A) float/half) and .png (sRGB -> linear).
// Refuses images larger than max_pixels. Errors name the file.
Result<ImageF> read_image(const std::filesystem::path& path, std::size_t max_pixels = std::size_t(1) << 26);

// 8-bit sRGB PNG of linear values (clamped to [0, 1], alpha written as is).
Status write_png(const std::filesystem::path& path, const ImageF& image);
// Linear float OpenEXR (RGBA, 32-bit float channels).
Status write_exr(const std::filesystem::path& path, const ImageF& image);

// sRGB transfer functions (IEC 61966-2-1).
float srgb_to_linear(float encoded);
float linear_to_srgb(float linear);

}  // namespace proxygi::image
