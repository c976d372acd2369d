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

}  // namespace proxygi::image
