// Tangent-plane rules (shaders/shared/tangent_plane.h): the cases, the joints of the fade and
// continuity. Continuity is checked on s², which the blocked light of a cap follows.
#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "sh/tangent_plane.h"

namespace proxygi::sh {
namespace {

const glm::vec3 kReceiver(0.0f);
const glm::vec3 kNormal(0.0f, 1.0f, 0.0f);

// Proxy strength as the receiver sees it: s (0 when skipped).
float sine_at(const ProxySphere& sphere) {
  const auto result = proxy_at_receiver(kReceiver, kNormal, sphere);
  return result ? result->sine : 0.0f;
}

TEST(ShTangentPlane, SpheresAboveThePlaneAreUnchanged) {
  const ProxySphere sphere{{0.5f, 2.0f, 0.0f}, 1.0f};
  const auto result = proxy_at_receiver(kReceiver, kNormal, sphere);
  ASSERT_TRUE(result);
  EXPECT_EQ(result->sphere.radius, 1.0f);
  EXPECT_NEAR(result->sine, 1.0f / std::sqrt(4.25f), 1e-6f);
  EXPECT_NEAR(glm::length(result->direction), 1.0f, 1e-6f);
}

TEST(ShTangentPlane, SkipsSpheresBelowThePlaneOrAroundTheReceiverWithCentreBelow) {
  EXPECT_FALSE(proxy_at_receiver(kReceiver, kNormal, {{1.0f, -1.5f, 0.0f}, 1.0f}));  // below
  EXPECT_FALSE(proxy_at_receiver(kReceiver, kNormal, {{0.2f, -0.3f, 0.0f}, 1.0f}));  // inside, centre below
  EXPECT_FALSE(proxy_at_receiver(kReceiver, kNormal, {{0.0f, 0.0f, 0.0f}, 1.0f}));   // centre on the receiver
}

TEST(ShTangentPlane, StraddlingSphereFarFromTheCutIsTheInscribedSphere) {
  // x = 3 ≥ 2ρ (ρ = √(1 − 0.16)): the fade is 1, the inscribed sphere is unscaled.
  const ProxySphere sphere{{3.0f, 0.4f, 0.0f}, 1.0f};
  const auto result = proxy_at_receiver(kReceiver, kNormal, sphere);
  ASSERT_TRUE(result);
  EXPECT_NEAR(result->sphere.radius, 0.7f, 1e-6f);                  // (r + h) / 2
  EXPECT_NEAR(result->sphere.center.y, 0.4f + 0.3f, 1e-6f);         // c + N (r - h) / 2
  EXPECT_NEAR(result->sphere.center.y + result->sphere.radius, 1.4f, 1e-6f);  // top point kept
  EXPECT_NEAR(result->sphere.center.y - result->sphere.radius, 0.0f, 1e-6f);  // touches the plane
}

TEST(ShTangentPlane, FadeAtItsJointsAndLimits) {
  const float r = 1.0f;
  for (float h : {-0.9f, -0.5f, -0.3f, 0.0f}) {
    const float rho = std::sqrt(r * r - h * h);
    EXPECT_EQ(tangent_plane_fade(h, r, 0.5f * rho), 0.0f) << h;  // p inside, centre below: skipped
    EXPECT_NEAR(tangent_plane_fade(h, r, 1.5f * rho), 0.5f, 1e-5f) << h;  // x/ρ − 1
    EXPECT_EQ(tangent_plane_fade(h, r, 2.0f * rho), 1.0f) << h;
  }
  for (float h : {0.1f, 0.3f, 0.5f, 0.9f}) {
    const float rho = std::sqrt(r * r - h * h);
    EXPECT_NEAR(tangent_plane_fade(h, r, 0.0f), h / r, 1e-6f) << h;  // inside: φ = t
    EXPECT_NEAR(tangent_plane_fade(h, r, rho), h / r, 1e-6f) << h;   // up to the cut circle
    EXPECT_NEAR(tangent_plane_fade(h, r, 1.5f * rho), h / r + 0.5f * (1.0f - h / r), 1e-5f) << h;
    EXPECT_EQ(tangent_plane_fade(h, r, 2.0f * rho), 1.0f) << h;
  }
  // The joint at h = 0 from both sides, at every x; the limit h → r.
  for (float x = 0.0f; x < 3.0f; x += 0.01f)
    EXPECT_NEAR(tangent_plane_fade(-1e-5f, r, x), tangent_plane_fade(1e-5f, r, x), 1e-4f) << x;
  EXPECT_GT(tangent_plane_fade(0.99999f, r, 0.0f), 0.9999f);
  EXPECT_EQ(tangent_plane_fade(0.99999f, r, 0.1f), 1.0f);
}

TEST(ShTangentPlane, ContinuousAsTheSphereSinksAndRises) {
  // Sweep the centre height from below −r to above r at fixed horizontal offsets, including
  // receivers inside the sphere (offsets < 1) and near the cut circle: s² changes by small steps.
  for (float offset : {0.0f, 0.3f, 0.8f, 1.0f, 1.5f, 3.0f, 6.0f}) {
    float previous = sine_at({{offset, -1.2f, 0.0f}, 1.0f});
    EXPECT_EQ(previous, 0.0f);
    for (int k = 1; k <= 4000; ++k) {
      const float h = -1.2f + 2.4f * float(k) / 4000.0f;
      const float s = sine_at({{offset, h, 0.0f}, 1.0f});
      EXPECT_LT(std::abs(s * s - previous * previous), 3e-3f) << "offset " << offset << " h " << h;
      previous = s;
    }
  }
}

TEST(ShTangentPlane, ContinuousAsTheReceiverSlidesThroughTheCutCircle) {
  // Sideways at fixed heights: s² has no step where p enters or leaves the sphere.
  for (float h : {-0.5f, -0.3f, 0.0f, 0.3f, 0.5f}) {
    float previous = sine_at({{-2.5f, h, 0.0f}, 1.0f});
    for (int k = 1; k <= 5000; ++k) {
      const float x = -2.5f + 5.0f * float(k) / 5000.0f;
      const float s = sine_at({{x, h, 0.0f}, 1.0f});
      EXPECT_LT(std::abs(s * s - previous * previous), 3e-3f) << "h " << h << " x " << x;
      previous = s;
    }
  }
  // Centre below the plane: the proxy vanishes as p reaches the cut circle.
  const float h = -0.3f, rho = std::sqrt(1.0f - h * h);
  EXPECT_LT(sine_at({{rho + 1e-4f, h, 0.0f}, 1.0f}), 2e-2f);
  EXPECT_EQ(sine_at({{rho - 1e-4f, h, 0.0f}, 1.0f}), 0.0f);
}

TEST(ShTangentPlane, SphereSinkingThroughTheReceiverFadesLinearlyInSSquared) {
  // p on the axis (x = 0) inside the sphere: the inscribed sphere touches p, so s = √φ = √(h/r)
  // and s² falls linearly from 1 (h = r, the sphere touching p from above) to 0 (h = 0).
  for (float h : {0.05f, 0.25f, 0.5f, 0.75f, 0.95f}) {
    const float s = sine_at({{0.0f, h, 0.0f}, 1.0f});
    EXPECT_NEAR(s * s, h, 1e-5f) << h;
  }
  EXPECT_NEAR(sine_at({{0.0f, 1.0001f, 0.0f}, 1.0f}), 1.0f, 1e-3f);
  EXPECT_EQ(sine_at({{0.0f, -1e-4f, 0.0f}, 1.0f}), 0.0f);
}

}  // namespace
}  // namespace proxygi::sh
