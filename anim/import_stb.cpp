// stb_image compiled here (third-party code: built without the project's warnings), reduced to
// the two formats glTF core allows.
#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_STATIC
#define STBI_ONLY_PNG
#define STBI_ONLY_JPEG
#define STBI_NO_STDIO
#define STBI_MAX_DIMENSIONS 65536
#include <stb/stb_image.h>

#include <climits>
#include <cstring>
#include <string>

#include "anim/import_stb.h"

namespace proxygi::anim::detail {

Result<DecodedImage> decode_image(std::span<const std::uint8_t> encoded, std::uint32_t max_dimension,
                                  std::uint64_t max_pixels) {
  if (encoded.empty()) return make_error("image data is empty");
  if (encoded.size() > static_cast<std::size_t>(INT_MAX)) return make_error("image data larger than 2 GiB");
  const int length = static_cast<int>(encoded.size());
  int width = 0;
  int height = 0;
  int channels = 0;
  if (stbi_info_from_memory(encoded.data(), length, &width, &height, &channels) == 0) {
    return make_error(std::string("not a PNG or JPEG image (") + stbi_failure_reason() + ")");
  }
  if (width <= 0 || height <= 0 || static_cast<std::uint32_t>(width) > max_dimension ||
      static_cast<std::uint32_t>(height) > max_dimension ||
      static_cast<std::uint64_t>(width) * static_cast<std::uint64_t>(height) > max_pixels) {
    return make_error("image size " + std::to_string(width) + "x" + std::to_string(height) +
                      " exceeds the limit (" + std::to_string(max_dimension) + " per side, " +
                      std::to_string(max_pixels) + " pixels)");
  }
  int decoded_width = 0;
  int decoded_height = 0;
  stbi_uc* pixels = stbi_load_from_memory(encoded.data(), length, &decoded_width, &decoded_height,
                                          &channels, 4);
  if (pixels == nullptr) return make_error(std::string("cannot decode image (") + stbi_failure_reason() + ")");
  if (decoded_width != width || decoded_height != height) {
    stbi_image_free(pixels);
    return make_error("image header and decoded size disagree");
  }
  DecodedImage image;
  image.width = width;
  image.height = height;
  image.rgba.assign(pixels, pixels + static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4);
  stbi_image_free(pixels);
  return image;
}

}  // namespace proxygi::anim::detail
