// read_image: .hdr and .png through stb_image, .exr through tinyexr. The file is read into memory
// once (with a byte limit), its header is parsed and the pixel count checked against max_pixels
// before anything is decoded, so a hostile header cannot make a decoder allocate gigabytes.
#include <stb/stb_image.h>
#include <tinyexr.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <memory>
#include <string>

#include "base/atomic_file.h"
#include "image/image.h"

namespace proxygi::image {
namespace {

// A float RGBA pixel is 16 bytes; compressed files are smaller than that, so 16 bytes per
// allowed pixel (plus headers) bounds every legitimate file.
constexpr std::uint64_t kHeaderSlack = std::uint64_t(1) << 20;

Error file_error(const std::filesystem::path& path, const std::string& what) {
  return make_error(path.string() + ": " + what);
}

Status check_size(const std::filesystem::path& path, std::int64_t width, std::int64_t height,
                  std::size_t max_pixels) {
  if (width <= 0 || height <= 0)
    return file_error(path, "invalid size " + std::to_string(width) + "x" + std::to_string(height));
  if (std::uint64_t(width) * std::uint64_t(height) > max_pixels)
    return file_error(path, "image is " + std::to_string(width) + "x" + std::to_string(height) +
                                ", more than the limit of " + std::to_string(max_pixels) + " pixels" +
                                (max_pixels == settings::kMaxImagePixels ? " (" + std::to_string(settings::kMaxImageSize) + " x " +
                                                                               std::to_string(settings::kMaxImageSize) + ")"
                                                                         : std::string()));
  return {};
}

std::string stb_reason() {
  const char* reason = stbi_failure_reason();
  return reason != nullptr ? reason : "unknown error";
}

struct StbFree {
  void operator()(void* data) const { stbi_image_free(data); }
};

Result<ImageF> read_stb(const std::filesystem::path& path, const std::vector<std::uint8_t>& bytes,
                        std::size_t max_pixels, bool is_hdr) {
  const auto* data = bytes.data();
  const int length = static_cast<int>(bytes.size());
  int width = 0, height = 0, channels = 0;
  if (stbi_info_from_memory(data, length, &width, &height, &channels) == 0)
    return file_error(path, "cannot decode header: " + stb_reason());
  if (Status size = check_size(path, width, height, max_pixels); !size) return size.error();

  ImageF image(width, height);
  const std::size_t count = image.pixels.size();
  if (is_hdr) {
    // Radiance RGBE is linear already; stb fills alpha with 1.
    std::unique_ptr<float, StbFree> pixels(stbi_loadf_from_memory(data, length, &width, &height, &channels, 4));
    if (!pixels) return file_error(path, "cannot decode Radiance HDR: " + stb_reason());
    std::memcpy(image.pixels.data(), pixels.get(), count * sizeof(glm::vec4));
    return image;
  }
  // PNG: color is sRGB-encoded, alpha is linear coverage. 8- and 16-bit files keep their precision.
  const bool sixteen_bit = stbi_is_16_bit_from_memory(data, length) != 0;
  if (sixteen_bit) {
    std::unique_ptr<stbi_us, StbFree> pixels(stbi_load_16_from_memory(data, length, &width, &height, &channels, 4));
    if (!pixels) return file_error(path, "cannot decode PNG: " + stb_reason());
    for (std::size_t i = 0; i < count; ++i) {
      const stbi_us* p = pixels.get() + 4 * i;
      image.pixels[i] = {srgb_to_linear(p[0] / 65535.0f), srgb_to_linear(p[1] / 65535.0f),
                         srgb_to_linear(p[2] / 65535.0f), p[3] / 65535.0f};
    }
    return image;
  }
  std::unique_ptr<stbi_uc, StbFree> pixels(stbi_load_from_memory(data, length, &width, &height, &channels, 4));
  if (!pixels) return file_error(path, "cannot decode PNG: " + stb_reason());
  std::array<float, 256> table{};  // 8-bit sRGB code -> linear
  for (int code = 0; code < 256; ++code) table[std::size_t(code)] = srgb_to_linear(float(code) / 255.0f);
  for (std::size_t i = 0; i < count; ++i) {
    const stbi_uc* p = pixels.get() + 4 * i;
    image.pixels[i] = {table[p[0]], table[p[1]], table[p[2]], float(p[3]) / 255.0f};
  }
  return image;
}

// Frees tinyexr's header, image and error string on every path out of read_exr. A failed header
// parse may leave allocations behind (found by ASan), so the header is always freed (the free
// function accepts a zero-initialized header); a failed image load cleans up after itself and
// freeing it again would be a double free.
struct ExrState {
  EXRHeader header;
  EXRImage image;
  bool image_loaded = false;
  const char* error = nullptr;
  ExrState() {
    InitEXRHeader(&header);
    InitEXRImage(&image);
  }
  ~ExrState() {
    if (image_loaded) FreeEXRImage(&image);
    FreeEXRHeader(&header);
    if (error != nullptr) FreeEXRErrorMessage(error);
  }
  ExrState(const ExrState&) = delete;
  ExrState& operator=(const ExrState&) = delete;
  std::string message(const char* fallback) const { return error != nullptr ? error : fallback; }
};

float exr_sample(const EXRHeader& header, const EXRImage& image, int channel, std::size_t index) {
  const unsigned char* plane = image.images[channel];
  if (header.pixel_types[channel] == TINYEXR_PIXELTYPE_UINT)
    return float(reinterpret_cast<const unsigned int*>(plane)[index]);
  return reinterpret_cast<const float*>(plane)[index];  // HALF was requested as FLOAT
}

Result<ImageF> read_exr(const std::filesystem::path& path, const std::vector<std::uint8_t>& bytes,
                        std::size_t max_pixels) {
  EXRVersion version;
  if (ParseEXRVersionFromMemory(&version, bytes.data(), bytes.size()) != TINYEXR_SUCCESS)
    return file_error(path, "not an OpenEXR file (bad version header)");
  if (version.multipart != 0 || version.non_image != 0)
    return file_error(path, "multi-part and deep OpenEXR files are not supported");
  if (version.tiled != 0) return file_error(path, "tiled OpenEXR files are not supported (write scanlines)");

  ExrState exr;
  if (ParseEXRHeaderFromMemory(&exr.header, &version, bytes.data(), bytes.size(), &exr.error) != TINYEXR_SUCCESS)
    return file_error(path, "cannot parse OpenEXR header: " + exr.message("unknown error"));
  const EXRBox2i window = exr.header.data_window;
  const std::int64_t width = std::int64_t(window.max_x) - window.min_x + 1;
  const std::int64_t height = std::int64_t(window.max_y) - window.min_y + 1;
  if (Status size = check_size(path, width, height, max_pixels); !size) return size.error();

  // Channels are matched by name (last component after a layer prefix is not considered:
  // only plain R, G, B, A or a luminance-only Y image are read).
  int r = -1, g = -1, b = -1, a = -1, y = -1;
  for (int c = 0; c < exr.header.num_channels; ++c) {
    const std::string name = exr.header.channels[c].name;
    if (name == "R") r = c;
    else if (name == "G") g = c;
    else if (name == "B") b = c;
    else if (name == "A") a = c;
    else if (name == "Y") y = c;
    if (exr.header.pixel_types[c] == TINYEXR_PIXELTYPE_HALF)
      exr.header.requested_pixel_types[c] = TINYEXR_PIXELTYPE_FLOAT;
  }
  const bool rgb = r >= 0 && g >= 0 && b >= 0;
  if (!rgb && y < 0) return file_error(path, "OpenEXR file has neither R, G, B nor Y channels");

  if (LoadEXRImageFromMemory(&exr.image, &exr.header, bytes.data(), bytes.size(), &exr.error) != TINYEXR_SUCCESS)
    return file_error(path, "cannot decode OpenEXR pixels: " + exr.message("unknown error"));
  exr.image_loaded = true;
  if (exr.image.images == nullptr || exr.image.width != width || exr.image.height != height)
    return file_error(path, "OpenEXR pixels do not match the header's data window");

  ImageF image(static_cast<int>(width), static_cast<int>(height));
  for (std::size_t i = 0; i < image.pixels.size(); ++i) {
    glm::vec4& p = image.pixels[i];
    if (rgb) {
      p = {exr_sample(exr.header, exr.image, r, i), exr_sample(exr.header, exr.image, g, i),
           exr_sample(exr.header, exr.image, b, i), 1.0f};
    } else {
      const float luminance = exr_sample(exr.header, exr.image, y, i);
      p = {luminance, luminance, luminance, 1.0f};
    }
    if (a >= 0) p.a = exr_sample(exr.header, exr.image, a, i);
  }
  return image;
}

bool starts_with(const std::vector<std::uint8_t>& bytes, std::initializer_list<std::uint8_t> magic) {
  return bytes.size() >= magic.size() && std::equal(magic.begin(), magic.end(), bytes.begin());
}

}  // namespace

Result<ImageF> read_image(const std::filesystem::path& path, std::size_t max_pixels) {
  const std::uint64_t max_bytes = std::uint64_t(max_pixels) * 16u + kHeaderSlack;
  Result<std::vector<std::uint8_t>> bytes = read_file(path, max_bytes);
  if (!bytes) return bytes.error();
  if (bytes->size() > std::size_t(INT32_MAX)) return file_error(path, "file too large to decode");
  // Dispatch on the file's magic bytes, not its extension, so a misnamed file still reads.
  if (starts_with(*bytes, {0x76, 0x2f, 0x31, 0x01})) return read_exr(path, *bytes, max_pixels);
  if (starts_with(*bytes, {0x89, 'P', 'N', 'G'})) return read_stb(path, *bytes, max_pixels, false);
  if (starts_with(*bytes, {'#', '?'})) return read_stb(path, *bytes, max_pixels, true);
  return file_error(path, "unknown image format (expected OpenEXR, PNG or Radiance HDR)");
}

}  // namespace proxygi::image
