// write_png / write_exr: encode in memory, then hand the bytes to write_file_atomically
// (temporary file in the destination folder + rename), so a failed or interrupted write never
// leaves a partial image under the final name.
#include <stb/stb_image_write.h>
#include <tinyexr.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

#include "base/atomic_file.h"
#include "image/image.h"

namespace proxygi::image {
namespace {

Error file_error(const std::filesystem::path& path, const std::string& what) {
  return make_error(path.string() + ": " + what);
}

Status check_writable(const std::filesystem::path& path, const ImageF& image) {
  if (image.width <= 0 || image.height <= 0)
    return file_error(path, "cannot write an empty image (" + std::to_string(image.width) + "x" +
                                std::to_string(image.height) + ")");
  if (image.pixels.size() != std::size_t(image.width) * std::size_t(image.height))
    return file_error(path, "image has " + std::to_string(image.pixels.size()) + " pixels, expected " +
                                std::to_string(image.width) + "x" + std::to_string(image.height));
  return {};
}

// Clamps to [0, 1] (NaN becomes 0) and rounds to the nearest 8-bit code.
std::uint8_t to_byte(float unit) {
  if (!(unit > 0.0f)) return 0;
  return static_cast<std::uint8_t>(std::lround(std::min(unit, 1.0f) * 255.0f));
}

void append_bytes(void* context, void* data, int size) {
  auto* out = static_cast<std::vector<std::uint8_t>*>(context);
  const auto* bytes = static_cast<const std::uint8_t*>(data);
  out->insert(out->end(), bytes, bytes + size);
}

}  // namespace

Status write_png(const std::filesystem::path& path, const ImageF& image) {
  if (Status ok = check_writable(path, image); !ok) return ok;
  std::vector<std::uint8_t> rgba(image.pixels.size() * 4);
  for (std::size_t i = 0; i < image.pixels.size(); ++i) {
    const glm::vec4& p = image.pixels[i];
    rgba[4 * i + 0] = to_byte(linear_to_srgb(std::clamp(p.r, 0.0f, 1.0f)));
    rgba[4 * i + 1] = to_byte(linear_to_srgb(std::clamp(p.g, 0.0f, 1.0f)));
    rgba[4 * i + 2] = to_byte(linear_to_srgb(std::clamp(p.b, 0.0f, 1.0f)));
    rgba[4 * i + 3] = to_byte(p.a);
  }
  return write_png_rgba8(path, rgba, image.width, image.height);
}

Status write_png_rgba8(const std::filesystem::path& path, std::span<const std::uint8_t> rgba8, int width, int height) {
  if (width <= 0 || height <= 0 || rgba8.size() != std::size_t(width) * std::size_t(height) * 4)
    return file_error(path, "cannot write " + std::to_string(rgba8.size()) + " bytes as a " + std::to_string(width) +
                                "x" + std::to_string(height) + " RGBA8 image");
  // stb's deflate has no randomness or timestamps: equal pixels give equal bytes.
  std::vector<std::uint8_t> encoded;
  if (stbi_write_png_to_func(append_bytes, &encoded, width, height, 4, rgba8.data(), width * 4) == 0)
    return file_error(path, "PNG encoding failed");
  return write_file_atomically(path, encoded);
}

Status write_exr(const std::filesystem::path& path, const ImageF& image) {
  if (Status ok = check_writable(path, image); !ok) return ok;
  // Planar channels in the alphabetical order EXR readers expect: A, B, G, R.
  const std::size_t count = image.pixels.size();
  std::array<std::vector<float>, 4> planes;
  for (auto& plane : planes) plane.resize(count);
  for (std::size_t i = 0; i < count; ++i) {
    planes[0][i] = image.pixels[i].a;
    planes[1][i] = image.pixels[i].b;
    planes[2][i] = image.pixels[i].g;
    planes[3][i] = image.pixels[i].r;
  }
  std::array<float*, 4> plane_pointers{planes[0].data(), planes[1].data(), planes[2].data(), planes[3].data()};

  EXRHeader header;
  InitEXRHeader(&header);
  EXRImage exr_image;
  InitEXRImage(&exr_image);
  exr_image.num_channels = 4;
  exr_image.images = reinterpret_cast<unsigned char**>(plane_pointers.data());
  exr_image.width = image.width;
  exr_image.height = image.height;

  std::array<EXRChannelInfo, 4> channels{};
  std::array<int, 4> pixel_types{};
  std::array<int, 4> requested_types{};
  const char* names[4] = {"A", "B", "G", "R"};
  for (int c = 0; c < 4; ++c) {
    channels[std::size_t(c)].name[0] = names[c][0];
    channels[std::size_t(c)].name[1] = '\0';
    pixel_types[std::size_t(c)] = TINYEXR_PIXELTYPE_FLOAT;
    requested_types[std::size_t(c)] = TINYEXR_PIXELTYPE_FLOAT;
  }
  header.num_channels = 4;
  header.channels = channels.data();
  header.pixel_types = pixel_types.data();
  header.requested_pixel_types = requested_types.data();
  header.compression_type = TINYEXR_COMPRESSIONTYPE_ZIP;  // lossless

  unsigned char* memory = nullptr;
  const char* error = nullptr;
  const std::size_t size = SaveEXRImageToMemory(&exr_image, &header, &memory, &error);
  if (size == 0 || memory == nullptr) {
    std::string message = error != nullptr ? error : "unknown error";
    if (error != nullptr) FreeEXRErrorMessage(error);
    std::free(memory);
    return file_error(path, "OpenEXR encoding failed: " + message);
  }
  const std::vector<std::uint8_t> encoded(memory, memory + size);
  std::free(memory);  // tinyexr allocates the buffer with malloc
  return write_file_atomically(path, encoded);
}

}  // namespace proxygi::image
