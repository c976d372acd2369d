#pragma once
// Bilinear resampling of RGBA8 frames: the CPU twin of shaders/frame_output.comp (the viewer's
// frame at a lower internal resolution, filled into its window).
#include <cstdint>
#include <span>
#include <vector>

namespace proxygi::image {

// `source` (source_width × source_height RGBA8, row 0 on top, sRGB-encoded) at target size, as
// vkCmdBlitImage's LINEAR filter: target texel x samples source position (x + 0.5)·sw/tw − 0.5,
// edges clamped. `decode` filters decoded (linear) values and encodes the result, as a blit into
// an sRGB image does; otherwise the encoded values are filtered (a UNORM image). The same size
// returns `source` unchanged. Sizes must be ≥ 1 and source.size() = 4·sw·sh.
std::vector<std::uint8_t> resample_rgba8(std::span<const std::uint8_t> source, int source_width, int source_height,
                                         int target_width, int target_height, bool decode);

}  // namespace proxygi::image
