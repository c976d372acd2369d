#include "render/supersample_resolve.h"

#include <algorithm>

#include "base/check.h"

namespace proxygi::render {

ResolvedFrame resolve_supersampled(const image::ImageF& sample_hdr, std::span<const std::uint8_t> sample_ldr, int factor) {
  PROXYGI_CHECK(factor >= 1 && sample_hdr.width % factor == 0 && sample_hdr.height % factor == 0,
                "samples divisible by the supersampling factor");
  PROXYGI_CHECK(sample_ldr.size() == std::size_t(sample_hdr.width) * std::size_t(sample_hdr.height) * 4,
                "one RGBA8 sample per HDR sample");
  const int width = sample_hdr.width / factor, height = sample_hdr.height / factor;
  ResolvedFrame out{image::ImageF{width, height}, std::vector<std::uint8_t>(std::size_t(width) * std::size_t(height) * 4)};
  const float count = float(factor * factor);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      glm::vec4 radiance(0.0f);
      glm::vec3 display(0.0f);
      for (int j = 0; j < factor; ++j)
        for (int i = 0; i < factor; ++i) {
          const std::size_t s = std::size_t(y * factor + j) * std::size_t(sample_hdr.width) + std::size_t(x * factor + i);
          radiance += sample_hdr.pixels[s];
          for (int c = 0; c < 3; ++c) display[c] += image::srgb_to_linear(float(sample_ldr[s * 4 + std::size_t(c)]) / 255.0f);
        }
      const std::size_t p = std::size_t(y) * std::size_t(width) + std::size_t(x);
      out.hdr.pixels[p] = radiance / count;
      display /= count;
      for (int c = 0; c < 3; ++c)
        out.ldr[p * 4 + std::size_t(c)] =
            std::uint8_t(std::clamp(image::linear_to_srgb(display[c]), 0.0f, 1.0f) * 255.0f + 0.5f);
      out.ldr[p * 4 + 3] = 255;
    }
  return out;
}

}  // namespace proxygi::render
