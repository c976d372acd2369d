#include <gtest/gtest.h>

#include <cmath>

#include "ref/metrics.h"

namespace proxygi::ref {
namespace {

using image::ImageF;

// Reference 0.5 everywhere; the test differs by 0.1 in R at (1,0), 0.3 in G at (0,1) and 1.0 in
// B at (1,1). Squared errors: 0, 0.01, 0.09, 1.0 (one channel each).
struct Pair {
  ImageF test{2, 2, glm::vec4(0.5f, 0.5f, 0.5f, 1.0f)};
  ImageF reference{2, 2, glm::vec4(0.5f, 0.5f, 0.5f, 1.0f)};
  Pair() {
    test.at(1, 0).r = 0.6f;
    test.at(0, 1).g = 0.2f;
    test.at(1, 1).b = 1.5f;
  }
};

TEST(Rmse, HandComputed) {
  const Pair pair;
  const auto result = rmse(pair.test, pair.reference);
  ASSERT_TRUE(result.ok()) << result.message();
  // sqrt((0 + 0.01 + 0.09 + 1.0) / 12) = sqrt(0.0916667) = 0.3027650
  EXPECT_NEAR(result->mean, 0.3027650, 1e-6);
  EXPECT_EQ(result->pixels, 4u);
  // Per pixel: sqrt(sq / 3).
  EXPECT_FLOAT_EQ(result->map.at(0, 0), 0.0f);
  EXPECT_NEAR(result->map.at(1, 0), std::sqrt(0.01 / 3), 1e-6);
  EXPECT_NEAR(result->map.at(0, 1), std::sqrt(0.09 / 3), 1e-6);
  EXPECT_NEAR(result->map.at(1, 1), std::sqrt(1.0 / 3), 1e-6);
}

TEST(RelativeMse, HandComputed) {
  const Pair pair;
  const auto result = relative_mse(pair.test, pair.reference);
  ASSERT_TRUE(result.ok()) << result.message();
  // (0.01 + 0.09 + 1.0) / (0.5^2 + 0.01) / 12 = 1.1 / 3.12 = 0.3525641
  EXPECT_NEAR(result->mean, 0.3525641, 1e-6);
  EXPECT_NEAR(result->map.at(1, 1), 1.0 / 0.26 / 3.0, 1e-6);
  // A different epsilon changes the denominator only: 1.1 / (0.26 * 12) -> 1.1 / (0.35 * 12).
  const auto wide = relative_mse(pair.test, pair.reference, nullptr, 0.1);
  ASSERT_TRUE(wide.ok());
  EXPECT_NEAR(wide->mean, 1.1 / (0.35 * 12.0), 1e-6);
}

TEST(Metrics, MaskSelectsReceiverPixels) {
  const Pair pair;
  const ReceiverMask top_row = mask_where(2, 2, [](int, int y) { return y == 0; });
  const auto r = rmse(pair.test, pair.reference, &top_row);
  ASSERT_TRUE(r.ok());
  // Only (0,0) and (1,0): sqrt(0.01 / 6) = 0.0408248
  EXPECT_NEAR(r->mean, 0.0408248, 1e-6);
  EXPECT_EQ(r->pixels, 2u);
  EXPECT_EQ(r->map.at(1, 1), 0.0f);  // outside the mask
  const auto rel = relative_mse(pair.test, pair.reference, &top_row);
  ASSERT_TRUE(rel.ok());
  EXPECT_NEAR(rel->mean, 0.01 / 0.26 / 6.0, 1e-7);
}

TEST(Metrics, MaskFromImageAndAlpha) {
  ImageF mask_image(3, 1, glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
  mask_image.at(1, 0) = glm::vec4(1.0f);                    // white: receiver
  mask_image.at(2, 0) = glm::vec4(1.0f, 1.0f, 1.0f, 0.0f);  // white but transparent: not
  const ReceiverMask from_image = mask_from_image(mask_image);
  EXPECT_EQ(from_image.receiver, (std::vector<std::uint8_t>{0, 1, 0}));
  const ReceiverMask from_alpha = mask_from_alpha(mask_image);
  EXPECT_EQ(from_alpha.receiver, (std::vector<std::uint8_t>{1, 1, 0}));
}

TEST(Metrics, RefusesSizeMismatchAndEmptyMask) {
  const ImageF a(4, 4), b(4, 5);
  const auto mismatch = rmse(a, b);
  ASSERT_FALSE(mismatch.ok());
  EXPECT_EQ(mismatch.message(), "size mismatch: test is 4x4, reference is 4x5");
  const ReceiverMask wrong_size = mask_where(3, 3, [](int, int) { return true; });
  EXPECT_FALSE(relative_mse(a, a, &wrong_size).ok());
  const ReceiverMask nothing = mask_where(4, 4, [](int, int) { return false; });
  const auto empty = rmse(a, a, &nothing);
  ASSERT_FALSE(empty.ok());
  EXPECT_NE(empty.message().find("no receiver"), std::string::npos);
}

TEST(MetricsPlane, BoxMeanCutsWindowsAtTheBorder) {
  Plane p(3, 1);
  p.values = {1.0f, 2.0f, 6.0f};
  const Plane m = box_mean(p, 1);
  // Windows: {1,2}, {1,2,6}, {2,6}
  EXPECT_FLOAT_EQ(m.at(0, 0), 1.5f);
  EXPECT_FLOAT_EQ(m.at(1, 0), 3.0f);
  EXPECT_FLOAT_EQ(m.at(2, 0), 4.0f);
}

TEST(MetricsPlane, SeparableConvolutionReplicatesBorders) {
  Plane p(3, 1);
  p.values = {1.0f, 2.0f, 6.0f};
  const double k[] = {0.25, 0.5, 0.25};
  const double one[] = {1.0};
  const Plane c = convolve_separable(p, k, one);
  // x=0 sees (1, 1, 2): 0.25 + 0.5 + 0.5 = 1.25; x=1: 0.25 + 1 + 1.5 = 2.75; x=2 sees (2, 6, 6): 5
  EXPECT_FLOAT_EQ(c.at(0, 0), 1.25f);
  EXPECT_FLOAT_EQ(c.at(1, 0), 2.75f);
  EXPECT_FLOAT_EQ(c.at(2, 0), 5.0f);
}

}  // namespace
}  // namespace proxygi::ref
