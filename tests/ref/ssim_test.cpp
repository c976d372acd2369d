#include <gtest/gtest.h>

#include "ref/ssim.h"

namespace proxygi::ref {
namespace {

using image::ImageF;

// The pair metrics_reference.py builds in ssim_pair() (linear values, 16x14).
void ssim_pair(ImageF& test, ImageF& reference) {
  test = ImageF(16, 14);
  reference = ImageF(16, 14);
  for (int y = 0; y < 14; ++y)
    for (int x = 0; x < 16; ++x) {
      test.at(x, y) = {float((x * 7 + y * 3) % 11) / 10.0f, float((x * 2 + y * 5) % 7) / 6.0f, 0.5f, 1.0f};
      reference.at(x, y) = {float((x * 5 + y * 2) % 9) / 8.0f, float((x * 2 + y * 5) % 7) / 6.0f,
                            0.25f + 0.05f * float(x % 3), 1.0f};
    }
}

TEST(Ssim, IdenticalImagesGiveOne) {
  ImageF test, reference;
  ssim_pair(test, reference);
  const auto result = ssim(reference, reference);
  ASSERT_TRUE(result.ok()) << result.message();
  EXPECT_NEAR(result->mean, 1.0, 1e-6);
}

TEST(Ssim, ConstantImagesFollowTheLuminanceTerm) {
  // Displayed values a = 0.5 and b = 0.25 everywhere: variances vanish, so
  // SSIM = (2ab + C1) / (a^2 + b^2 + C1) = (0.25 + 1e-4) / (0.3125 + 1e-4) = 0.8000640.
  const float a = image::srgb_to_linear(0.5f), b = image::srgb_to_linear(0.25f);
  const ImageF test(12, 12, glm::vec4(a, a, a, 1.0f)), reference(12, 12, glm::vec4(b, b, b, 1.0f));
  const auto result = ssim(test, reference);
  ASSERT_TRUE(result.ok()) << result.message();
  EXPECT_NEAR(result->mean, 0.8000640, 1e-6);
  EXPECT_EQ(result->pixels, 4u);  // 12x12 leaves a 2x2 block of full windows
  EXPECT_EQ(result->map.at(0, 0), 0.0f);
}

TEST(Ssim, MatchesIndependentNumpyComputation) {
  ImageF test, reference;
  ssim_pair(test, reference);
  const auto all = ssim(test, reference);
  ASSERT_TRUE(all.ok()) << all.message();
  // metrics_reference.py: direct 11x11 weighted sums per window, float64.
  EXPECT_EQ(all->pixels, 24u);
  EXPECT_NEAR(all->mean, 0.552585539, 1e-6);
  EXPECT_NEAR(all->map.at(7, 6), 0.571305153, 1e-6);
  const ReceiverMask left = mask_where(16, 14, [](int x, int) { return x < 8; });
  const auto masked = ssim(test, reference, &left);
  ASSERT_TRUE(masked.ok());
  EXPECT_EQ(masked->pixels, 12u);
  EXPECT_NEAR(masked->mean, 0.524561435, 1e-6);
}

TEST(Ssim, RefusesImagesSmallerThanTheWindow) {
  const ImageF small(10, 20);
  EXPECT_FALSE(ssim(small, small).ok());
}

}  // namespace
}  // namespace proxygi::ref
