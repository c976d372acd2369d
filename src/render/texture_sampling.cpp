#include "render/texture_sampling.h"

#include <algorithm>
#include <cmath>

#include "image/image.h"

namespace proxygi::render {

glm::vec2 transform_uv(const glm::mat3& transform, const glm::vec2& uv) {
  return glm::vec2(transform * glm::vec3(uv, 1.0f));
}

int wrap_texel(int i, int n, anim::TextureWrap wrap) {
  switch (wrap) {
    case anim::TextureWrap::repeat: {
      const int r = i % n;
      return r < 0 ? r + n : r;
    }
    case anim::TextureWrap::clamp_to_edge: return std::clamp(i, 0, n - 1);
    case anim::TextureWrap::mirrored_repeat: {
      // Vulkan: (n − 1) − mirror((i mod 2n) − n), mirror(a) = a ≥ 0 ? a : −(1 + a).
      int period = i % (2 * n);
      if (period < 0) period += 2 * n;
      const int a = period - n;
      return (n - 1) - (a >= 0 ? a : -(1 + a));
    }
  }
  return 0;
}

glm::vec3 sample_texels(std::span<const glm::vec3> texels, int width, int height, const glm::vec2& uv,
                        anim::TextureWrap wrap_s, anim::TextureWrap wrap_t, anim::TextureFilter filter) {
  if (width <= 0 || height <= 0 || texels.size() < std::size_t(width) * std::size_t(height)) return glm::vec3(1.0f);
  auto at = [&](int i, int j) {
    return texels[std::size_t(wrap_texel(j, height, wrap_t)) * std::size_t(width) + std::size_t(wrap_texel(i, width, wrap_s))];
  };
  const float x = uv.x * float(width), y = uv.y * float(height);
  if (filter == anim::TextureFilter::nearest) return at(int(std::floor(x)), int(std::floor(y)));
  const float fx = std::floor(x - 0.5f), fy = std::floor(y - 0.5f);
  const float tx = x - 0.5f - fx, ty = y - 0.5f - fy;
  const int x0 = int(fx), y0 = int(fy);
  return glm::mix(glm::mix(at(x0, y0), at(x0 + 1, y0), tx), glm::mix(at(x0, y0 + 1), at(x0 + 1, y0 + 1), tx), ty);
}

glm::vec3 mean_linear_color(const anim::Image& image) {
  const std::size_t texels = std::size_t(std::max(image.width, 0)) * std::size_t(std::max(image.height, 0));
  if (texels == 0 || image.rgba.size() < texels * 4) return glm::vec3(1.0f);
  glm::dvec3 sum(0.0);
  for (std::size_t i = 0; i < texels; ++i)
    for (int c = 0; c < 3; ++c) sum[c] += image::srgb8_to_linear(image.rgba[i * 4 + std::size_t(c)]);
  return glm::vec3(sum / double(texels));
}

}  // namespace proxygi::render
