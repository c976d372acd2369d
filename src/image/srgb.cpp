#include <array>
#include <cmath>

#include "image/image.h"

namespace proxygi::image {

// IEC 61966-2-1: a linear segment near black, a 2.4 power curve above it.
float srgb_to_linear(float encoded) {
  if (encoded <= 0.04045f) return encoded / 12.92f;
  return std::pow((encoded + 0.055f) / 1.055f, 2.4f);
}

float linear_to_srgb(float linear) {
  if (linear <= 0.0031308f) return linear * 12.92f;
  return 1.055f * std::pow(linear, 1.0f / 2.4f) - 0.055f;
}

float srgb8_to_linear(std::uint8_t code) {
  static const std::array<float, 256> table = [] {
    std::array<float, 256> decoded{};
    for (int i = 0; i < 256; ++i) decoded[std::size_t(i)] = srgb_to_linear(float(i) / 255.0f);
    return decoded;
  }();
  return table[code];
}

}  // namespace proxygi::image
