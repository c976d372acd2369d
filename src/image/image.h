#pragma once
// Float images and their files. ImageF holds linear RGBA radiance (or any float data), row-major,
// top row first. PNG files are sRGB 8-bit: read_image converts them to linear, write_png
// converts linear to sRGB after clamping to [0, 1]. Writes are atomic (temporary file + rename).
#include <cstdint>
#include <filesystem>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "base/result.h"
#include "settings/limits.h"

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

// Rec. 709 luminance 0.2126 R + 0.7152 G + 0.0722 B of linear RGB (any vector with r, g, b),
// computed in T.
template <class T = double, class Rgb>
constexpr T rec709_luminance(const Rgb& c) {
  return T(0.2126) * T(c.r) + T(0.7152) * T(c.g) + T(0.0722) * T(c.b);
}

// Reads .hdr (Radiance RGBE), .exr (OpenEXR, RGB(A) float/half) and .png (sRGB -> linear).
// Refuses images larger than max_pixels. Errors name the file.
// - The format is chosen by the file's magic bytes, not its extension.
// - .hdr: linear RGB, alpha 1.
// - .png: 8- or 16-bit, gray/RGB with or without alpha; color decoded from sRGB to linear,
//   alpha is coverage (code / max, not sRGB-decoded); missing alpha is 1.
// - .exr: single-part scanline files, any compression tinyexr knows; channels R, G, B (or Y for
//   gray) and optional A, each half, float or uint (converted to float); missing alpha is 1.
//   Tiled, multi-part and deep files are refused.
Result<ImageF> read_image(const std::filesystem::path& path, std::size_t max_pixels = settings::kMaxImagePixels);

// 8-bit sRGB RGBA PNG of linear values (clamped to [0, 1], NaN -> 0, rounded to the nearest
// code; alpha clamped and written without sRGB encoding). Deterministic bytes.
Status write_png(const std::filesystem::path& path, const ImageF& image);
// sRGB-encoded RGBA8 bytes (width × height, top row first) written as they are: the bytes
// write_png gives for their linear decoding, without the decode and re-encode.
// Encoded with libpng: zlib at `kPngZlibLevel`, one fixed row filter (PNG "Up"). libpng writes no
// timestamps, so equal pixels give equal bytes for a given zlib build.
Status write_png_rgba8(const std::filesystem::path& path, std::span<const std::uint8_t> rgba8, int width, int height);

// How the PNG bytes are made. `libpng` is the encoder write_png/write_png_rgba8 use; `stb` is
// stb_image_write at its defaults (zlib level 8, five filters tried per row), the encoder used
// until 2026-12 (kept for `proxygi bench record`, which measures the two against each other).
enum class PngEncoder { libpng, stb };
inline constexpr int kPngZlibLevel = 2;  // chosen by `proxygi bench record` (README)
Result<std::vector<std::uint8_t>> encode_png_rgba8(std::span<const std::uint8_t> rgba8, int width, int height,
                                                   PngEncoder encoder = PngEncoder::libpng,
                                                   int zlib_level = kPngZlibLevel);
// Linear float OpenEXR (RGBA, 32-bit float channels, ZIP compression: lossless, bit-exact).
Status write_exr(const std::filesystem::path& path, const ImageF& image);

// sRGB transfer functions (IEC 61966-2-1), for values in [0, 1] (outside: the same formulas,
// extended; the caller clamps where it must).
float srgb_to_linear(float encoded);
float linear_to_srgb(float linear);
// srgb_to_linear(code / 255) for an 8-bit code, from a table built once.
float srgb8_to_linear(std::uint8_t code);

}  // namespace proxygi::image
