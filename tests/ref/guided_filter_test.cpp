#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>

#include "ref/guided_filter.h"
#include "ref/metrics.h"

namespace proxygi::ref {
namespace {

using image::ImageF;

constexpr int kW = 64, kH = 48, kEdge = 32;

// Uniform noise in [-amplitude, amplitude] from a fixed integer hash: identical on every platform.
float hash_noise(int x, int y, int c, float amplitude) {
  std::uint32_t h = std::uint32_t(x) * 73856093u ^ std::uint32_t(y) * 19349663u ^ std::uint32_t(c + 1) * 83492791u;
  h ^= h >> 13;
  h *= 0x5bd1e995u;
  h ^= h >> 15;
  return amplitude * (float(h & 0xffffu) / 32767.5f - 1.0f);
}

// A wall (left, normal +z, depth rising to the right) meets a floor (right, normal +y) at x = 32.
// The clean indirect light is linear in depth on the wall and constant on the floor, so it is
// exactly a per-region linear function of the features, as the filter assumes.
struct Scene {
  ImageF normal{kW, kH}, depth{kW, kH}, clean{kW, kH}, noisy{kW, kH};
  Scene() {
    for (int y = 0; y < kH; ++y)
      for (int x = 0; x < kW; ++x) {
        const bool wall = x < kEdge;
        const float d = wall ? 2.0f + 0.05f * float(x) : 3.0f + 0.02f * float(y);
        normal.at(x, y) = wall ? glm::vec4(0, 0, 1, 1) : glm::vec4(0, 1, 0, 1);
        depth.at(x, y) = glm::vec4(d, d, d, 1);
        const glm::vec3 light = wall ? glm::vec3(0.1f + 0.1f * d, 0.15f, 0.3f) : glm::vec3(0.8f, 0.5f, 0.2f);
        clean.at(x, y) = glm::vec4(light, 1.0f);
        for (int c = 0; c < 3; ++c) noisy.at(x, y)[c] = light[c] + hash_noise(x, y, c, 0.25f);
        noisy.at(x, y).a = 1.0f;
      }
  }
};

TEST(GuidedFilter, LowersErrorOfNoisyIndirectLight) {
  const Scene scene;
  GuideFeatures features{&scene.normal, &scene.depth, 5.0f, nullptr};
  GuidedFilterOptions options;
  options.radius = 8;
  const auto filtered = guided_filter_indirect(scene.noisy, features, options);
  ASSERT_TRUE(filtered.ok()) << filtered.message();
  const double before = rmse(scene.noisy, scene.clean)->mean;
  const double after = rmse(*filtered, scene.clean)->mean;
  // Uniform noise of amplitude 0.25 has RMSE 0.25 / sqrt(3) = 0.144; averaging a 17x17 window
  // cuts it by ~17x where the model fits exactly. Demand at least 5x overall.
  EXPECT_NEAR(before, 0.144, 0.01);
  EXPECT_LT(after, before / 5.0) << "before " << before << " after " << after;
}

TEST(GuidedFilter, KeepsTheEdgeThatTheFeaturesShow) {
  const Scene scene;
  GuideFeatures features{&scene.normal, &scene.depth, 5.0f, nullptr};
  GuidedFilterOptions options;
  options.radius = 8;
  const auto filtered = guided_filter_indirect(scene.noisy, features, options);
  ASSERT_TRUE(filtered.ok());
  // Red jumps from 0.1 + 0.1 * 3.55 = 0.455 (x = 31) to 0.8 (x = 32) in the clean image. Averaged
  // over the middle rows, the filtered pixels next to the edge stay within 0.03 of it, while a
  // plain box filter of the same radius would pull both towards the middle (~0.6).
  double left = 0.0, right = 0.0, box_left = 0.0;
  const Plane box = box_mean(channel_plane(scene.noisy, 0), options.radius);
  for (int y = 16; y < 32; ++y) {
    left += filtered->at(kEdge - 1, y).r / 16.0;
    right += filtered->at(kEdge, y).r / 16.0;
    box_left += box.at(kEdge - 1, y) / 16.0;
  }
  EXPECT_NEAR(left, 0.455, 0.03);
  EXPECT_NEAR(right, 0.8, 0.03);
  EXPECT_GT(box_left, 0.55);  // the edge-blind filter does smear it
}

TEST(GuidedFilter, ConstantImageStaysConstant) {
  const Scene scene;
  const ImageF constant(kW, kH, glm::vec4(0.3f, 0.6f, 0.9f, 0.5f));
  GuideFeatures features{&scene.normal, &scene.depth, 5.0f, &scene.clean};
  const auto filtered = guided_filter_indirect(constant, features);
  ASSERT_TRUE(filtered.ok()) << filtered.message();
  for (const glm::vec4& p : filtered->pixels) {
    EXPECT_NEAR(p.r, 0.3f, 1e-5f);
    EXPECT_NEAR(p.g, 0.6f, 1e-5f);
    EXPECT_NEAR(p.b, 0.9f, 1e-5f);
    EXPECT_EQ(p.a, 0.5f);
  }
}

TEST(GuidedFilter, LargeEpsilonTendsToTheBoxMean) {
  // With epsilon >> feature variance, a -> 0 and q -> mean(mean(p)): the guided filter degrades
  // gracefully into a (twice applied) box filter.
  const Scene scene;
  const Plane depth = channel_plane(scene.depth, 0);
  const float epsilon = 1e6f;
  const auto filtered = guided_filter(scene.noisy, std::span<const Plane>(&depth, 1), std::span<const float>(&epsilon, 1), 3);
  ASSERT_TRUE(filtered.ok());
  const Plane twice = box_mean(box_mean(channel_plane(scene.noisy, 1), 3), 3);
  for (std::size_t i = 0; i < twice.values.size(); ++i) EXPECT_NEAR(filtered->pixels[i].g, twice.values[i], 1e-4f);
}

TEST(GuidedFilter, RefusesBadArguments) {
  const Scene scene;
  EXPECT_FALSE(guided_filter_indirect(scene.noisy, GuideFeatures{}).ok());
  const ImageF small(4, 4);
  GuideFeatures wrong{&small, nullptr, 1.0f, nullptr};
  const auto mismatch = guided_filter_indirect(scene.noisy, wrong);
  ASSERT_FALSE(mismatch.ok());
  EXPECT_NE(mismatch.message().find("normal image is 4x4"), std::string::npos) << mismatch.message();
  GuideFeatures good{&scene.normal, nullptr, 1.0f, nullptr};
  GuidedFilterOptions bad;
  bad.radius = 0;
  EXPECT_FALSE(guided_filter_indirect(scene.noisy, good, bad).ok());
  bad.radius = 4;
  bad.epsilon_normal = 0.0f;
  EXPECT_FALSE(guided_filter_indirect(scene.noisy, good, bad).ok());
}

}  // namespace
}  // namespace proxygi::ref
