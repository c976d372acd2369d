#include <gtest/gtest.h>

#include <filesystem>

#include "ref/error_image.h"

namespace proxygi::ref {
namespace {

float luminance(const glm::vec4& c) { return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b; }

TEST(ErrorImage, RampRunsFromNearBlackToPaleYellowWithRisingLuminance) {
  EXPECT_NEAR(image::linear_to_srgb(error_ramp(0.0f).b), 4.0f / 255.0f, 1e-5f);
  EXPECT_LT(luminance(error_ramp(0.0f)), 0.001f);
  const glm::vec4 top = error_ramp(1.0f);
  EXPECT_NEAR(image::linear_to_srgb(top.r), 252.0f / 255.0f, 1e-5f);
  EXPECT_NEAR(image::linear_to_srgb(top.b), 191.0f / 255.0f, 1e-5f);
  float previous = -1.0f;
  for (int i = 0; i <= 100; ++i) {
    const float l = luminance(error_ramp(float(i) / 100.0f));
    EXPECT_GT(l, previous) << i;  // ordered: more error always reads brighter
    previous = l;
  }
  EXPECT_EQ(error_ramp(-3.0f), error_ramp(0.0f));
  EXPECT_EQ(error_ramp(7.0f), error_ramp(1.0f));
}

TEST(ErrorImage, WritesScaledMapWithIgnoredPixelsGray) {
  Plane map(3, 1);
  map.values = {0.0f, 0.5f, 2.0f};
  const std::vector<std::uint8_t> mask = {1, 1, 0};
  const auto directory = std::filesystem::path(PROXYGI_TEST_OUTPUT_DIR);
  std::filesystem::create_directories(directory);
  const auto path = directory / "error_image.png";
  ASSERT_TRUE(write_error_image(path, map, 1.0f, &mask).ok());
  const auto read = image::read_image(path);
  ASSERT_TRUE(read.ok()) << read.message();
  EXPECT_NEAR(image::linear_to_srgb(read->at(1, 0).r), image::linear_to_srgb(error_ramp(0.5f).r), 1.0f / 255.0f);
  EXPECT_NEAR(image::linear_to_srgb(read->at(2, 0).g), 0.5f, 1.0f / 255.0f);  // ignored: mid gray
  EXPECT_FALSE(write_error_image(path, map, 0.0f).ok());
}

}  // namespace
}  // namespace proxygi::ref
