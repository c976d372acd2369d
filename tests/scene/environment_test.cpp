// The analytic sky: finite and non-negative, the sun disc's radius and irradiance, rotation,
// and the equirectangular mapping.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include <glm/gtc/constants.hpp>

#include "scene/environment.h"

namespace proxygi::scene {
namespace {

// Evenly spread unit vectors (Fibonacci sphere).
std::vector<glm::vec3> sphere_directions(int count) {
  std::vector<glm::vec3> directions;
  const float golden = glm::pi<float>() * (3.0f - std::sqrt(5.0f));
  for (int i = 0; i < count; ++i) {
    const float y = 1.0f - 2.0f * (float(i) + 0.5f) / float(count);
    const float r = std::sqrt(1.0f - y * y);
    directions.emplace_back(r * std::cos(golden * float(i)), y, r * std::sin(golden * float(i)));
  }
  return directions;
}

// A unit vector at angle `angle` (radians) from `axis`, turned by `around` about it.
glm::vec3 off_axis(const glm::vec3& axis, float angle, float around) {
  const glm::vec3 helper = std::fabs(axis.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
  const glm::vec3 u = glm::normalize(glm::cross(axis, helper));
  const glm::vec3 v = glm::cross(axis, u);
  return glm::normalize(std::cos(angle) * axis + std::sin(angle) * (std::cos(around) * u + std::sin(around) * v));
}

Environment test_sky() {
  Environment e;
  e.sun.elevation_degrees = 35.0f;
  e.sun.azimuth_degrees = 120.0f;
  e.sun.angular_radius_degrees = 3.0f;
  e.sun.color = glm::vec3(1.0f, 0.9f, 0.7f);
  e.sun.irradiance = 5.0f;
  e.intensity = 1.5f;
  e.rotation_degrees = 20.0f;
  return e;
}

TEST(Environment, SkyIsFiniteAndNonNegativeEverywhere) {
  for (Environment e : {Environment{}, test_sky()}) {
    const AnalyticSky sky(e);
    for (const glm::vec3& d : sphere_directions(20000)) {
      const glm::vec3 L = sky.radiance(d);
      for (int c = 0; c < 3; ++c) {
        ASSERT_TRUE(std::isfinite(L[c]));
        ASSERT_GE(L[c], 0.0f);
      }
    }
  }
}

TEST(Environment, SunIsBrighterThanAnyPartOfTheSky) {
  const Environment e = test_sky();
  const AnalyticSky sky(e);
  glm::vec3 brightest_sky(0.0f);
  for (const glm::vec3& d : sphere_directions(20000)) brightest_sky = glm::max(brightest_sky, sky.sky_radiance(d));
  const glm::vec3 sun = sky.radiance(sky.sun_direction());
  for (int c = 0; c < 3; ++c) EXPECT_GT(sun[c], 10.0f * brightest_sky[c]);
}

TEST(Environment, SunDiscHasTheDocumentedAngularRadius) {
  const Environment e = test_sky();
  const AnalyticSky sky(e);
  const float radius = glm::radians(e.sun.angular_radius_degrees);
  for (float around = 0.0f; around < 6.28f; around += 0.7f) {
    const glm::vec3 inside = off_axis(sky.sun_direction(), radius * 0.99f, around);
    const glm::vec3 outside = off_axis(sky.sun_direction(), radius * 1.01f, around);
    EXPECT_EQ(sky.radiance(inside) - sky.sky_radiance(inside), sky.sun_radiance());
    EXPECT_EQ(sky.radiance(outside), sky.sky_radiance(outside));
  }
}

// Integrating the disc's radiance times cos over the sky gives the documented irradiance.
TEST(Environment, SunIrradianceMatchesTheSetting) {
  const Environment e = test_sky();
  const AnalyticSky sky(e);
  const glm::vec3 axis = sky.sun_direction();
  const double outer = 1.5 * glm::radians(double(e.sun.angular_radius_degrees));
  constexpr int kTheta = 3000;
  constexpr int kPhi = 64;
  glm::dvec3 irradiance(0.0);
  for (int i = 0; i < kTheta; ++i) {
    const double theta = outer * (i + 0.5) / kTheta;
    for (int j = 0; j < kPhi; ++j) {
      const double phi = glm::two_pi<double>() * (j + 0.5) / kPhi;
      const glm::vec3 d = off_axis(axis, float(theta), float(phi));
      const glm::dvec3 sun(sky.radiance(d) - sky.sky_radiance(d));
      irradiance += sun * std::cos(theta) * std::sin(theta) * (outer / kTheta) * (glm::two_pi<double>() / kPhi);
    }
  }
  const glm::dvec3 expected = glm::dvec3(e.sun.color) * double(e.sun.irradiance * e.intensity);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(irradiance[c], expected[c], 0.005 * expected[c]);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(sky.sun_irradiance()[c], expected[c], 1e-5 * expected[c]);
}

TEST(Environment, SunDirectionConventionAndRotation) {
  Environment e;
  e.sun.elevation_degrees = 0.0f;
  e.sun.azimuth_degrees = 0.0f;
  EXPECT_NEAR(glm::length(sun_direction(e) - glm::vec3(0, 0, 1)), 0.0f, 1e-6f);
  e.sun.azimuth_degrees = 90.0f;
  EXPECT_NEAR(glm::length(sun_direction(e) - glm::vec3(1, 0, 0)), 0.0f, 1e-6f);
  e.sun.elevation_degrees = 90.0f;
  EXPECT_NEAR(glm::length(sun_direction(e) - glm::vec3(0, 1, 0)), 0.0f, 1e-6f);

  // Rotating the environment adds to the sun azimuth and turns the whole sky with it.
  Environment a = test_sky();
  Environment b = a;
  b.rotation_degrees = a.rotation_degrees + 90.0f;
  Environment c = a;
  c.sun.azimuth_degrees = a.sun.azimuth_degrees + 90.0f;
  EXPECT_NEAR(glm::length(sun_direction(b) - sun_direction(c)), 0.0f, 1e-5f);
  const AnalyticSky sky_a(a);
  const AnalyticSky sky_b(b);
  const glm::mat3 turn = glm::mat3(glm::vec3(0, 0, -1), glm::vec3(0, 1, 0), glm::vec3(1, 0, 0));  // +Z -> +X
  for (const glm::vec3& d : sphere_directions(500)) {
    const glm::vec3 la = sky_a.radiance(d);
    const glm::vec3 lb = sky_b.radiance(turn * d);
    EXPECT_NEAR(glm::length(la - lb), 0.0f, 1e-4f * (1.0f + glm::length(la)));
  }
}

TEST(Environment, GradientEndpointsAndHorizon) {
  Environment e;
  e.intensity = 2.0f;
  e.sun.elevation_degrees = -60.0f;  // keep the disc away from the probes
  const AnalyticSky sky(e);
  const float scale = e.sky.radiance * e.intensity;
  auto expect_color = [&](const glm::vec3& d, const glm::vec3& color) {
    EXPECT_NEAR(glm::length(sky.radiance(glm::normalize(d)) - color * scale), 0.0f, 1e-5f);
  };
  expect_color(glm::vec3(0, 1, 0), e.sky.zenith_color);
  expect_color(glm::vec3(1, 0, 0), e.sky.horizon_color);
  // sqrt gradient: a quarter of the way up in y is half way in color.
  expect_color(glm::vec3(std::sqrt(1.0f - 0.0625f), 0.25f, 0), glm::mix(e.sky.horizon_color, e.sky.zenith_color, 0.5f));
  // Uniform below the horizon.
  for (const glm::vec3& d : {glm::vec3(0, -1, 0), glm::vec3(1, -1e-4f, 0), glm::vec3(-0.3f, -0.5f, 0.8f)}) {
    expect_color(d, e.sky.below_horizon_color);
  }
  // Continuous just above the horizon: the color moves away from horizon_color as sqrt(y).
  const glm::vec3 near_horizon = sky.radiance(glm::normalize(glm::vec3(1, 1e-8f, 0)));
  EXPECT_NEAR(glm::length(near_horizon - e.sky.horizon_color * scale),
              1e-4f * glm::length(e.sky.zenith_color - e.sky.horizon_color) * scale, 1e-6f);
  // The plain-function form agrees with the class.
  EXPECT_EQ(sky_radiance(e, glm::vec3(0, 1, 0)), sky.radiance(glm::vec3(0, 1, 0)));
}

TEST(Environment, EquirectangularMapping) {
  EXPECT_NEAR(equirect_uv(glm::vec3(0, 0, -1)).x, 0.5f, 1e-6f);  // center column looks at -Z
  EXPECT_NEAR(equirect_uv(glm::vec3(0, 0, -1)).y, 0.5f, 1e-6f);
  EXPECT_NEAR(equirect_uv(glm::vec3(1, 0, 0)).x, 0.75f, 1e-6f);  // u grows toward +X
  EXPECT_NEAR(equirect_uv(glm::vec3(-1, 0, 0)).x, 0.25f, 1e-6f);
  EXPECT_NEAR(equirect_uv(glm::vec3(0, 1, 0)).y, 0.0f, 1e-6f);  // top row is +Y
  EXPECT_NEAR(equirect_uv(glm::vec3(0, -1, 0)).y, 1.0f, 1e-6f);
  EXPECT_NEAR(glm::length(equirect_direction(glm::vec2(0.75f, 0.5f)) - glm::vec3(1, 0, 0)), 0.0f, 1e-6f);
  for (const glm::vec3& d : sphere_directions(2000)) {
    const glm::vec2 uv = equirect_uv(d);
    EXPECT_GE(uv.x, 0.0f);
    EXPECT_LT(uv.x, 1.0f);
    EXPECT_NEAR(glm::length(equirect_direction(uv) - d), 0.0f, 1e-5f);
  }
}

TEST(Environment, MapInfoResolvesThePath) {
  Scene scene;
  scene.base_dir = "shots";
  scene.environment.type = Environment::Type::map;
  scene.environment.map_path = "hdr/studio.exr";
  scene.environment.intensity = 0.7f;
  scene.environment.rotation_degrees = 45.0f;
  const EnvironmentMapInfo info = environment_map_info(scene);
  EXPECT_EQ(info.file, std::filesystem::path("shots/hdr/studio.exr"));
  EXPECT_FLOAT_EQ(info.intensity, 0.7f);
  EXPECT_FLOAT_EQ(info.rotation_degrees, 45.0f);
}

}  // namespace
}  // namespace proxygi::scene
