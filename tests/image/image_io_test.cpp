#include <gtest/gtest.h>
#include <tinyexr.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "image/image.h"

namespace proxygi::image {
namespace {

namespace fs = std::filesystem;

fs::path fresh_directory(const std::string& name) {
  const auto directory = fs::path(PROXYGI_TEST_OUTPUT_DIR) / "image" / name;
  fs::remove_all(directory);
  fs::create_directories(directory);
  return directory;
}

std::vector<char> read_bytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

void write_bytes(const fs::path& path, const std::vector<char>& bytes) {
  std::ofstream(path, std::ios::binary).write(bytes.data(), std::streamsize(bytes.size()));
}

// A 5x3 image with distinct values in every channel, HDR values and negatives included.
ImageF sample_image() {
  ImageF image(5, 3);
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 5; ++x)
      image.at(x, y) = {0.1f * float(x) + 0.013f * float(y), std::pow(10.0f, float(x - 2)), -0.25f * float(y),
                        0.2f * float(x)};
  return image;
}

TEST(ImageIo, ExrRoundTripIsBitExact) {
  const fs::path path = fresh_directory("exr_round_trip") / "a.exr";
  const ImageF image = sample_image();
  ASSERT_TRUE(write_exr(path, image).ok());
  const Result<ImageF> read = read_image(path);
  ASSERT_TRUE(read.ok()) << read.message();
  ASSERT_EQ(read->width, 5);
  ASSERT_EQ(read->height, 3);
  for (std::size_t i = 0; i < image.pixels.size(); ++i)
    for (int c = 0; c < 4; ++c) EXPECT_EQ(read->pixels[i][c], image.pixels[i][c]) << i << " " << c;
}

TEST(ImageIo, PngRoundTripIsWithinHalfACodeInSrgb) {
  const fs::path path = fresh_directory("png_round_trip") / "a.png";
  ImageF image(7, 2);
  for (int x = 0; x < 7; ++x) {
    const float v = float(x) / 6.0f;  // 0 .. 1 linear
    image.at(x, 0) = {v, v * v, 1.0f - v, 1.0f};
    image.at(x, 1) = {v * 0.01f, 0.5f, v, v};
  }
  ASSERT_TRUE(write_png(path, image).ok());
  const Result<ImageF> read = read_image(path);
  ASSERT_TRUE(read.ok()) << read.message();
  for (std::size_t i = 0; i < image.pixels.size(); ++i) {
    // Rounding to the nearest 8-bit code moves an sRGB value by at most 0.5/255.
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(linear_to_srgb(read->pixels[i][c]), linear_to_srgb(image.pixels[i][c]), 0.5f / 255.0f + 1e-6f);
    EXPECT_NEAR(read->pixels[i].a, image.pixels[i].a, 0.5f / 255.0f + 1e-6f);
  }
}

TEST(ImageIo, PngClampsOutOfRangeAndNan) {
  const fs::path path = fresh_directory("png_clamp") / "a.png";
  ImageF image(3, 1);
  image.at(0, 0) = {-1.0f, 7.0f, std::nanf(""), 2.0f};
  image.at(1, 0) = {0.0f, 1.0f, 0.0f, -3.0f};
  ASSERT_TRUE(write_png(path, image).ok());
  const Result<ImageF> read = read_image(path);
  ASSERT_TRUE(read.ok()) << read.message();
  EXPECT_EQ(read->at(0, 0), glm::vec4(0.0f, 1.0f, 0.0f, 1.0f));
  EXPECT_EQ(read->at(1, 0), glm::vec4(0.0f, 1.0f, 0.0f, 0.0f));
}

TEST(ImageIo, PngBytesAreDeterministic) {
  const fs::path directory = fresh_directory("png_deterministic");
  const ImageF image = sample_image();
  ASSERT_TRUE(write_png(directory / "a.png", image).ok());
  ASSERT_TRUE(write_png(directory / "b.png", image).ok());
  EXPECT_EQ(read_bytes(directory / "a.png"), read_bytes(directory / "b.png"));
}

// The recorder writes the renderer's sRGB bytes directly: the same file as decoding them to linear
// and encoding again, for every code in every channel.
TEST(ImageIo, Rgba8PngEqualsThePngOfItsLinearDecoding) {
  const fs::path directory = fresh_directory("png_rgba8");
  const int width = 64, height = 16;
  std::vector<std::uint8_t> rgba(std::size_t(width) * height * 4);
  for (std::size_t i = 0; i < rgba.size(); ++i) rgba[i] = std::uint8_t((i * 37 + i / 4) % 256);
  ImageF linear(width, height);
  for (std::size_t i = 0; i < linear.pixels.size(); ++i)
    linear.pixels[i] = glm::vec4(srgb8_to_linear(rgba[4 * i]), srgb8_to_linear(rgba[4 * i + 1]),
                                 srgb8_to_linear(rgba[4 * i + 2]), float(rgba[4 * i + 3]) / 255.0f);
  ASSERT_TRUE(write_png_rgba8(directory / "direct.png", rgba, width, height).ok());
  ASSERT_TRUE(write_png(directory / "linear.png", linear).ok());
  EXPECT_EQ(read_bytes(directory / "direct.png"), read_bytes(directory / "linear.png"));
  EXPECT_FALSE(write_png_rgba8(directory / "short.png", std::span(rgba).first(10), width, height).ok());
  EXPECT_FALSE(fs::exists(directory / "short.png"));
}

TEST(ImageIo, ReadsHalfFloatRgbExrWrittenByTinyexr) {
  const fs::path path = fresh_directory("exr_half") / "rgb_half.exr";
  // Values exactly representable in half precision, so the expected result is exact.
  const std::vector<float> rgb = {0.5f, 2.0f, 0.25f, 1024.0f, 0.0f, -0.125f};  // 2x1, interleaved RGB
  const char* error = nullptr;
  ASSERT_EQ(SaveEXR(rgb.data(), 2, 1, 3, 1, path.c_str(), &error), TINYEXR_SUCCESS);
  const Result<ImageF> read = read_image(path);
  ASSERT_TRUE(read.ok()) << read.message();
  EXPECT_EQ(read->at(0, 0), glm::vec4(0.5f, 2.0f, 0.25f, 1.0f));
  EXPECT_EQ(read->at(1, 0), glm::vec4(1024.0f, 0.0f, -0.125f, 1.0f));
}

TEST(ImageIo, ReadsRadianceHdr) {
  const fs::path path = fresh_directory("hdr") / "a.hdr";
  // Flat (non-RLE) 2x1 RGBE: value = mantissa * 2^(exponent - 136).
  // (128, 64, 32, 129) -> (1, 0.5, 0.25);  (128, 0, 255, 131) -> (4, 0, 7.96875).
  std::string text = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 1 +X 2\n";
  std::vector<char> bytes(text.begin(), text.end());
  for (int v : {128, 64, 32, 129, 128, 0, 255, 131}) bytes.push_back(char(v));
  write_bytes(path, bytes);
  const Result<ImageF> read = read_image(path);
  ASSERT_TRUE(read.ok()) << read.message();
  ASSERT_EQ(read->width, 2);
  EXPECT_EQ(read->at(0, 0), glm::vec4(1.0f, 0.5f, 0.25f, 1.0f));
  EXPECT_EQ(read->at(1, 0), glm::vec4(4.0f, 0.0f, 7.96875f, 1.0f));
}

TEST(ImageIo, RefusesImagesOverThePixelLimit) {
  const fs::path directory = fresh_directory("limit");
  const ImageF image = sample_image();  // 15 pixels
  ASSERT_TRUE(write_exr(directory / "a.exr", image).ok());
  ASSERT_TRUE(write_png(directory / "a.png", image).ok());
  for (const char* name : {"a.exr", "a.png"}) {
    const Result<ImageF> read = read_image(directory / name, 14);
    ASSERT_FALSE(read.ok()) << name;
    EXPECT_NE(read.message().find(name), std::string::npos) << read.message();
    EXPECT_NE(read.message().find("limit"), std::string::npos) << read.message();
    EXPECT_TRUE(read_image(directory / name, 15).ok()) << name;
  }
}

TEST(ImageIo, RefusesTruncatedAndGarbageFilesWithoutCrashing) {
  const fs::path directory = fresh_directory("truncated");
  const ImageF image = sample_image();
  ASSERT_TRUE(write_exr(directory / "good.exr", image).ok());
  ASSERT_TRUE(write_png(directory / "good.png", image).ok());
  for (const char* name : {"good.exr", "good.png"}) {
    const std::vector<char> bytes = read_bytes(directory / name);
    // Every prefix that cuts into the header or pixel data must be refused, never crash. (A PNG
    // cut only inside its final 12-byte IEND chunk still decodes: stb does not check that chunk,
    // so the last PNG cut removes IEND and one byte of the pixel chunk.)
    const std::size_t last = std::string(name).ends_with(".png") ? bytes.size() - 13 : bytes.size() - 1;
    for (std::size_t length : {std::size_t(0), std::size_t(3), std::size_t(8), std::size_t(20), bytes.size() / 2, last}) {
      const fs::path cut = directory / ("cut_" + std::to_string(length) + "_" + name);
      write_bytes(cut, std::vector<char>(bytes.begin(), bytes.begin() + std::ptrdiff_t(length)));
      const Result<ImageF> read = read_image(cut);
      EXPECT_FALSE(read.ok()) << cut;
      if (!read.ok()) {
        EXPECT_NE(read.message().find(cut.filename().string()), std::string::npos) << read.message();
      }
    }
  }
  write_bytes(directory / "garbage.exr", std::vector<char>(100, 'x'));
  const Result<ImageF> garbage = read_image(directory / "garbage.exr");
  ASSERT_FALSE(garbage.ok());
  EXPECT_NE(garbage.message().find("garbage.exr"), std::string::npos);
  EXPECT_FALSE(read_image(directory / "missing.png").ok());
}

TEST(ImageIo, FailedWritesLeaveNothingBehind) {
  const fs::path directory = fresh_directory("failed_write");
  // Empty image: refused before anything touches the disk.
  EXPECT_FALSE(write_png(directory / "empty.png", ImageF()).ok());
  EXPECT_FALSE(write_exr(directory / "empty.exr", ImageF()).ok());
  // Destination folder missing: the temporary cannot be created either.
  const Status missing = write_exr(directory / "no" / "a.exr", sample_image());
  ASSERT_FALSE(missing.ok());
  EXPECT_NE(missing.message().find("a.exr"), std::string::npos) << missing.message();
  EXPECT_FALSE(write_png(directory / "no" / "a.png", sample_image()).ok());
  EXPECT_TRUE(fs::is_empty(directory));
}

}  // namespace
}  // namespace proxygi::image
