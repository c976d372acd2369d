#include "image/resample.h"

#include <algorithm>
#include <cmath>

#include "image/image.h"

namespace proxygi::image {

std::vector<std::uint8_t> resample_rgba8(std::span<const std::uint8_t> source, int source_width, int source_height,
                                         int target_width, int target_height, bool decode) {
  if (source_width == target_width && source_height == target_height) return {source.begin(), source.end()};
  std::vector<std::uint8_t> out(std::size_t(target_width) * target_height * 4);
  const auto value = [&](int x, int y, int c) {
    const std::uint8_t code = source[(std::size_t(y) * source_width + x) * 4 + c];
    return decode && c < 3 ? srgb8_to_linear(code) : code / 255.0f;
  };
  const float scale_x = float(source_width) / float(target_width), scale_y = float(source_height) / float(target_height);
  for (int y = 0; y < target_height; ++y)
    for (int x = 0; x < target_width; ++x) {
      const float sx = std::max((x + 0.5f) * scale_x - 0.5f, 0.0f), sy = std::max((y + 0.5f) * scale_y - 0.5f, 0.0f);
      const int ax = std::min(int(sx), source_width - 1), ay = std::min(int(sy), source_height - 1);
      const int bx = std::min(ax + 1, source_width - 1), by = std::min(ay + 1, source_height - 1);
      const float fx = sx - float(ax), fy = sy - float(ay);
      for (int c = 0; c < 4; ++c) {
        const float top = value(ax, ay, c) + (value(bx, ay, c) - value(ax, ay, c)) * fx;
        const float bottom = value(ax, by, c) + (value(bx, by, c) - value(ax, by, c)) * fx;
        float v = top + (bottom - top) * fy;
        if (decode && c < 3) v = linear_to_srgb(std::clamp(v, 0.0f, 1.0f));
        out[(std::size_t(y) * target_width + x) * 4 + c] = std::uint8_t(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f));
      }
    }
  return out;
}

}  // namespace proxygi::image
