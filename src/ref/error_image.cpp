#include "ref/error_image.h"

#include <array>
#include <cmath>

namespace proxygi::ref {
namespace {

// Nine sRGB anchor colors sampled by eye along a magma-like ramp, interpolated linearly in sRGB.
constexpr std::array<std::array<float, 3>, 9> kAnchors = {{{0, 0, 4},
                                                           {28, 16, 68},
                                                           {79, 18, 123},
                                                           {129, 37, 129},
                                                           {181, 54, 122},
                                                           {229, 80, 100},
                                                           {251, 135, 97},
                                                           {254, 194, 135},
                                                           {252, 253, 191}}};

}  // namespace

glm::vec4 error_ramp(float t) {
  if (!(t >= 0.0f)) t = std::isnan(t) ? 1.0f : 0.0f;
  t = std::min(t, 1.0f);
  const float position = t * float(kAnchors.size() - 1);
  const std::size_t i = std::min(std::size_t(position), kAnchors.size() - 2);
  const float f = position - float(i);
  glm::vec4 color(0.0f, 0.0f, 0.0f, 1.0f);
  for (int c = 0; c < 3; ++c) {
    const float encoded = ((1.0f - f) * kAnchors[i][std::size_t(c)] + f * kAnchors[i + 1][std::size_t(c)]) / 255.0f;
    color[c] = image::srgb_to_linear(encoded);
  }
  return color;
}

image::ImageF false_color(const Plane& map, float max_value, const std::vector<std::uint8_t>* mask) {
  image::ImageF image(map.width, map.height);
  const glm::vec4 ignored(image::srgb_to_linear(0.5f), image::srgb_to_linear(0.5f), image::srgb_to_linear(0.5f), 1.0f);
  for (std::size_t i = 0; i < map.values.size(); ++i)
    image.pixels[i] = (mask != nullptr && (*mask)[i] == 0) ? ignored : error_ramp(map.values[i] / max_value);
  return image;
}

Status write_error_image(const std::filesystem::path& path, const Plane& map, float max_value,
                         const std::vector<std::uint8_t>* mask) {
  if (!(max_value > 0.0f)) return make_error(path.string() + ": error image scale must be positive");
  return image::write_png(path, false_color(map, max_value, mask));
}

}  // namespace proxygi::ref
