#pragma once
// CPU twin of supersample_resolve.comp (render.antialiasing): the display frame from its f × f
// shading samples per pixel. Samples are row-major, (width·f) × (height·f); display pixel (x, y)
// takes samples (x·f + i, y·f + j), i, j in 0..f−1, summed in that order (j outer) as the shader
// does.
//   hdr: the mean of the samples' vec4 radiance (linear; what the reference integrates a pixel over)
//   ldr: RGBA8 sRGB, the mean of the samples' displayed colours: each sample's bytes decoded to
//        linear (image::srgb_to_linear), averaged, encoded (image::linear_to_srgb, rounded);
//        alpha 255. The tonemap ran per sample (a resolve after the tonemap).
#include <cstdint>
#include <span>
#include <vector>

#include "image/image.h"

namespace proxygi::render {

struct ResolvedFrame {
  image::ImageF hdr;              // width × height
  std::vector<std::uint8_t> ldr;  // width × height × 4 (R, G, B, A)
};

// `sample_hdr` is (width·factor) × (height·factor); `sample_ldr` holds 4 bytes per sample
// (R, G, B, A); factor ≥ 1 and the sizes divisible by it (checked).
ResolvedFrame resolve_supersampled(const image::ImageF& sample_hdr, std::span<const std::uint8_t> sample_ldr, int factor);

}  // namespace proxygi::render
