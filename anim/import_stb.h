#pragma once
// Private to the importer: PNG/JPEG decoding with stb_image (compiled in import_stb.cpp with
// only those two formats), dimensions checked from the header before any pixel is decoded.
#include <cstdint>
#include <span>
#include <vector>

#include "base/result.h"

namespace proxygi::anim::detail {

struct DecodedImage {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgba;  // width * height * 4
};

Result<DecodedImage> decode_image(std::span<const std::uint8_t> encoded, std::uint32_t max_dimension,
                                  std::uint64_t max_pixels);

}  // namespace proxygi::anim::detail
