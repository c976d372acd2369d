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
  const render::UpsampleFootprint footprint = render::upsample_footprint(x, y, scale, glm::ivec2(receivers));
  std::array<render::UpsampleTap, 4> taps;
  for (std::size_t tap = 0; tap < 4; ++tap) {
    const glm::ivec2 source = footprint.source[tap];
    render::UpsampleTap& t = taps[tap];
    t.value = value(source.x, source.y);
    t.position = glm::vec3(positions.at(source.x, source.y));
    t.depth = depths.at(source.x, source.y).w;
    t.normal = glm::vec3(normals.at(source.x, source.y));
    t.bilinear_weight = footprint.bilinear_weight[tap];
  }
  return taps;
}

}  // namespace proxygi::gpu::testing
