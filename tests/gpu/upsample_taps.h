#pragma once
// The CPU side of the composite's upsampling, for the twin tests: the four receiver taps around
// display pixel (x, y) at 1/scale, as upsample_composite.comp gathers them (receiver centers at
// (i + 0.5)·scale, clamped at the edges, bilinear weights), ready for render::upsample.
#include <array>
#include <functional>

#include <glm/glm.hpp>

#include "image/image.h"
#include "render/shading.h"

namespace proxygi::gpu::testing {

// value(rx, ry): the receiver quantity upsampled; positions: receiver world xyz; depths: receiver
// eye depth in w (0 = no receiver); normals: receiver normal xyz. `receivers`: receivers per row
// and column (square frames).
inline std::array<render::UpsampleTap, 4> upsample_taps(int x, int y, int scale, int receivers,
                                                        const std::function<glm::vec3(int, int)>& value,
                                                        const image::ImageF& positions, const image::ImageF& depths,
                                                        const image::ImageF& normals) {
  const glm::vec2 coordinate = (glm::vec2(x, y) + 0.5f) / float(scale) - 0.5f;
  const glm::ivec2 base = glm::ivec2(glm::floor(coordinate));
  const glm::vec2 fraction = coordinate - glm::vec2(base);
  std::array<render::UpsampleTap, 4> taps;
  for (int tap = 0; tap < 4; ++tap) {
    const glm::ivec2 offset(tap & 1, tap >> 1);
    const glm::ivec2 source = glm::clamp(base + offset, glm::ivec2(0), glm::ivec2(receivers - 1));
    render::UpsampleTap& t = taps[std::size_t(tap)];
    t.value = value(source.x, source.y);
    t.position = glm::vec3(positions.at(source.x, source.y));
    t.depth = depths.at(source.x, source.y).w;
    t.normal = glm::vec3(normals.at(source.x, source.y));
    t.bilinear_weight = (offset.x == 1 ? fraction.x : 1.0f - fraction.x) * (offset.y == 1 ? fraction.y : 1.0f - fraction.y);
  }
  return taps;
}

}  // namespace proxygi::gpu::testing
