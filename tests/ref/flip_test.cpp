#include <gtest/gtest.h>

#include <algorithm>

#include "ref/flip.h"

namespace proxygi::ref {
namespace {

using image::ImageF;

ImageF uniform(int w, int h, float v) { return ImageF(w, h, glm::vec4(v, v, v, 1.0f)); }

TEST(Flip, IdenticalImagesGiveZero) {
  ImageF image(9, 7);
  for (int y = 0; y < 7; ++y)
    for (int x = 0; x < 9; ++x) image.at(x, y) = {float(x) / 8.0f, float(y) / 6.0f, 0.3f, 1.0f};
  const auto result = flip_ldr(image, image);
  ASSERT_TRUE(result.ok()) << result.message();
  EXPECT_EQ(result->mean, 0.0);
}

// Uniform images: the CSF filters keep constants and the feature detectors (weights summing to
// 0) see nothing, so FLIP is the remapped color term alone.
// cmax = HyAB(Hunt(Lab(green)), Hunt(Lab(blue)))^0.7 = 41.276098 (metrics_reference.py).
TEST(Flip, WhiteAgainstBlackByHand) {
  // Lab(white) = (100, 0, 0), Lab(black) = (0, 0, 0): HyAB = 100, 100^0.7 = 25.118864 > 0.4 cmax,
  // so FLIP = 0.95 + (25.118864 - 16.510439) / (41.276098 - 16.510439) * 0.05 = 0.9673798.
  const auto result = flip_ldr(uniform(8, 8, 1.0f), uniform(8, 8, 0.0f));
  ASSERT_TRUE(result.ok()) << result.message();
  EXPECT_NEAR(result->mean, 0.9673798, 1e-6);
  EXPECT_NEAR(*std::min_element(result->map.values.begin(), result->map.values.end()), 0.9673798f, 1e-6f);
}

TEST(Flip, CloseGraysByHand) {
  // Grays keep a = b = 0, so HyAB = |L(0.5) - L(0.45)| with L(t) = 116 t^(1/3) - 16:
  // 76.069261 - 72.891894 = 3.177367; ^0.7 = 2.246193 < 0.4 cmax, FLIP = 0.95 / 16.510439 * 2.246193.
  const auto result = flip_ldr(uniform(6, 6, 0.45f), uniform(6, 6, 0.5f));
  ASSERT_TRUE(result.ok()) << result.message();
  EXPECT_NEAR(result->mean, 0.1292445, 1e-6);
}

// The pair metrics_reference.py builds in flip_pair(): a vertical color edge at x = 10 in the
// reference, at x = 11 in the test, plus a fixed +-0.06 pattern.
void flip_pair(ImageF& test, ImageF& reference) {
  test = ImageF(20, 16);
  reference = ImageF(20, 16);
  const glm::vec4 gray(0.2f, 0.2f, 0.2f, 1.0f), orange(0.8f, 0.3f, 0.1f, 1.0f);
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 20; ++x) {
      reference.at(x, y) = x < 10 ? gray : orange;
      const float noise = float((x * 7 + y * 13) % 5 - 2) * 0.03f;
      const glm::vec4 base = x < 11 ? gray : orange;
      for (int c = 0; c < 3; ++c) test.at(x, y)[c] = std::clamp(base[c] + noise, 0.0f, 1.0f);
      test.at(x, y).a = 1.0f;
    }
}

TEST(Flip, MatchesIndependentNumpyComputation) {
  ImageF test, reference;
  flip_pair(test, reference);
  const auto result = flip_ldr(test, reference);
  ASSERT_TRUE(result.ok()) << result.message();
  // metrics_reference.py: full 2D kernels, direct sums, float64. The C++ stores planes in float32
  // (measured: mean within 3e-9, pixels within 9e-7).
  EXPECT_NEAR(result->mean, 0.147298523, 1e-6);
  EXPECT_NEAR(result->map.at(10, 8), 0.346649199, 5e-6);
  EXPECT_NEAR(result->map.at(3, 4), 0.053792677, 5e-6);
  FlipOptions low;
  low.pixels_per_degree = 10.0;
  const auto coarse = flip_ldr(test, reference, nullptr, low);
  ASSERT_TRUE(coarse.ok());
  EXPECT_NEAR(coarse->mean, 0.270477165, 1e-6);
}

TEST(Flip, MaskAveragesReceiversOnly) {
  ImageF test, reference;
  flip_pair(test, reference);
  const auto all = flip_ldr(test, reference);
  const ReceiverMask column = mask_where(20, 16, [](int x, int) { return x == 10; });
  const auto masked = flip_ldr(test, reference, &column);
  ASSERT_TRUE(all.ok() && masked.ok());
  double sum = 0.0;
  for (int y = 0; y < 16; ++y) sum += all->map.at(10, y);
  EXPECT_NEAR(masked->mean, sum / 16.0, 1e-6);
  EXPECT_EQ(masked->pixels, 16u);
}

TEST(HdrFlip, MatchesIndependentNumpyComputation) {
  // hdr_pair(): a ramp with one bright pixel (8.0 in blue); the test is 1.25x the reference.
  ImageF reference(12, 12);
  for (int y = 0; y < 12; ++y)
    for (int x = 0; x < 12; ++x)
      reference.at(x, y) = {0.05f * float(x + 1), 0.02f * float(y + 1), (x == 6 && y == 6) ? 8.0f : 0.1f, 1.0f};
  ImageF test = reference;
  for (auto& p : test.pixels) p = glm::vec4(glm::vec3(p) * 1.25f, 1.0f);
  const auto result = flip_hdr(test, reference);
  ASSERT_TRUE(result.ok()) << result.message();
  EXPECT_NEAR(result->start_exposure, 1.494227366, 1e-5);
  EXPECT_NEAR(result->stop_exposure, 3.645719476, 1e-5);
  EXPECT_EQ(result->exposure_count, 3);
  EXPECT_NEAR(result->flip.mean, 0.251065255, 1e-6);
}

TEST(HdrFlip, ToneMapperEndPoints) {
  EXPECT_EQ(flip_tone_map_aces(0.0f, 0.0), 0.0f);
  EXPECT_EQ(flip_tone_map_aces(-1.0f, 0.0), 0.0f);  // negatives are clipped
  EXPECT_EQ(flip_tone_map_aces(1e30f, 10.0), 1.0f);
  // x = 1: (k0 + k1) / (k3 + k4 + k5) with k0 = 0.36 * 2.51 = 0.9036, k1 = 0.6 * 0.03 = 0.018,
  // k3 = 0.36 * 2.43 = 0.8748, k4 = 0.6 * 0.59 = 0.354, k5 = 0.14: 0.9216 / 1.3688.
  EXPECT_NEAR(flip_tone_map_aces(1.0f, 0.0), 0.9216 / 1.3688, 1e-6);
  EXPECT_NEAR(flip_tone_map_aces(0.5f, 1.0), 0.9216 / 1.3688, 1e-6);  // 2^1 * 0.5 = 1
}

}  // namespace
}  // namespace proxygi::ref
