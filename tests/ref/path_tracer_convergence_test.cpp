// The path tracer against closed forms. Each estimate is the mean of many independent paths
// from one surface point; its standard error comes from the estimator's own sample variance,
// and the test accepts |mean - exact| <= 3 standard errors (and checks the error bar is tight
// enough for that to mean something).
#include <algorithm>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "ref/embree_scene.h"
#include "ref/path_tracer.h"
#include "ref/path_tracer_lighting.h"
#include "ref/sampling.h"
#include "ref/sampling_environment.h"
#include "sh/environment.h"
#include "image/image.h"
#include "scene/scene.h"

namespace proxygi::ref {
namespace {

constexpr double kPiD = 3.14159265358979323846;

struct Estimate {
  glm::dvec3 mean{0.0};
  glm::dvec3 standard_error{0.0};
};

// Mean of `paths` estimates of the radiance leaving (point, normal +Y) with albedo `albedo`.
Estimate estimate_radiance(const PathTracer& tracer, const glm::vec3& point, const glm::vec3& albedo, int paths,
                           std::uint32_t stream) {
  SurfaceHit hit;
  hit.position = point;
  hit.geometric_normal = glm::vec3(0.0f, 1.0f, 0.0f);
  hit.shading_normal = hit.geometric_normal;
  hit.albedo = albedo;
  glm::dvec3 sum(0.0), squared(0.0);
  for (int s = 0; s < paths; ++s) {
    SampleStream random(7u, stream, std::uint32_t(s));
    const glm::dvec3 value(tracer.shade(hit, random).radiance);
    sum += value;
    squared += value * value;
  }
  const double n = paths;
  Estimate out;
  out.mean = sum / n;
  out.standard_error = glm::sqrt(glm::max((squared - n * out.mean * out.mean) / (n - 1.0), glm::dvec3(0.0)) / n);
  return out;
}

void expect_within_three_standard_errors(const Estimate& estimate, double exact, double max_standard_error) {
  for (int c = 0; c < 3; ++c) {
    EXPECT_LE(estimate.standard_error[c], max_standard_error) << "channel " << c;
    EXPECT_NEAR(estimate.mean[c], exact, 3.0 * estimate.standard_error[c] + 1e-7)
        << "channel " << c << " standard error " << estimate.standard_error[c];
  }
}

// A large ground square at y = 0 plus an exact sphere.
EmbreeScene sphere_over_plane(const glm::vec3& center, float radius, float ground_size, const glm::vec3& albedo) {
  TriangleMesh ground;
  const float h = ground_size / 2.0f;
  ground.positions = {{-h, 0.0f, -h}, {h, 0.0f, -h}, {h, 0.0f, h}, {-h, 0.0f, h}};
  ground.indices = {0, 2, 1, 0, 3, 2};
  ground.material.albedo = albedo;
  SphereShape sphere{center, radius, SurfaceMaterial{albedo, nullptr}};
  std::vector<TriangleMesh> meshes;
  meshes.push_back(std::move(ground));
  auto scene = EmbreeScene::build(std::move(meshes), std::span<const SphereShape>(&sphere, 1));
  EXPECT_TRUE(scene.ok()) << (scene.ok() ? "" : scene.message());
  return std::move(*scene);
}

// Irradiance under a sphere (center height h, radius r < h) from a unit white sky on a receiver
// facing +Y at horizontal offset x: E = pi - pi (r/d)^2 cos(beta), d = |center - p|,
// cos(beta) = h / d (the sphere's cosine-weighted solid angle, exact while it is above the horizon).
double irradiance_under_sphere(double h, double r, double x) {
  const double d = std::sqrt(h * h + x * x);
  return kPiD - kPiD * (r / d) * (r / d) * (h / d);
}

TEST(PathTracerConvergence, DirectLightUnderSphereMatchesClosedForm) {
  const float h = 1.0f, r = 0.6f;
  const EmbreeScene scene = sphere_over_plane({0.0f, h, 0.0f}, r, 1000.0f, glm::vec3(0.7f));
  const EnvironmentLight white = EnvironmentLight::constant(glm::vec3(1.0f));
  const PathTracer tracer(scene, white, white, PathTracerSettings{LightTransport::direct});
  const glm::vec3 albedo(0.5f, 0.8f, 1.0f);
  std::uint32_t stream = 0;
  for (float x : {0.0f, 0.5f, 1.2f, 3.0f}) {
    const double exact_irradiance = irradiance_under_sphere(h, r, x);
    const Estimate e = estimate_radiance(tracer, {x, 0.0f, 0.0f}, glm::vec3(1.0f), 40000, stream++);
    SCOPED_TRACE("x = " + std::to_string(x));
    expect_within_three_standard_errors(e, exact_irradiance / kPiD, 0.005);
    // Radiance scales with albedo per channel (albedo/pi * E).
    const Estimate colored = estimate_radiance(tracer, {x, 0.0f, 0.0f}, albedo, 4000, stream++);
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(colored.mean[c], albedo[c] * exact_irradiance / kPiD, 3.0 * colored.standard_error[c] + 1e-7);
  }
}

TEST(PathTracerConvergence, EnvironmentSamplingKeepsTheClosedForm) {
  // The same closed form with lights that carry an importance sampler (NEE + MIS): a DC-only SH
  // vector of a unit sky (L_00 = sqrt(4 pi)) and a uniform white equirect map rotated by 30 deg.
  const float h = 1.0f, r = 0.6f;
  const EmbreeScene scene = sphere_over_plane({0.0f, h, 0.0f}, r, 1000.0f, glm::vec3(0.7f));
  sh::RgbSh dc;
  dc.order = 3;
  for (auto& channel : dc.channels) {
    channel.assign(9, 0.0);
    channel[0] = std::sqrt(4.0 * kPiD);
  }
  const EnvironmentLight sh_light = EnvironmentLight::spherical_harmonics(dc);
  ASSERT_NE(sh_light.importance(), nullptr);
  const float angle = 30.0f * float(kPiD) / 180.0f;
  const glm::mat3 rotation(glm::vec3(std::cos(angle), 0, std::sin(angle)), glm::vec3(0, 1, 0),
                           glm::vec3(-std::sin(angle), 0, std::cos(angle)));
  const EnvironmentLight map_light =
      EnvironmentLight::map(image::ImageF(32, 16, glm::vec4(1.0f)), 1.0f, rotation);
  ASSERT_NE(map_light.importance(), nullptr);
  std::uint32_t stream = 300;
  for (const EnvironmentLight* light : {&sh_light, &map_light}) {
    const PathTracer tracer(scene, *light, *light, PathTracerSettings{LightTransport::direct});
    for (float x : {0.0f, 1.2f}) {
      SCOPED_TRACE("x = " + std::to_string(x));
      const Estimate e = estimate_radiance(tracer, {x, 0.0f, 0.0f}, glm::vec3(1.0f), 20000, stream++);
      expect_within_three_standard_errors(e, irradiance_under_sphere(h, r, x) / kPiD, 0.005);
    }
  }
}

TEST(PathTracerSampling, EquirectSamplerPdfMatchesItsSamples) {
  // A table with one bright texel band: the pdf integrates to 1 over the sphere, and sampled
  // directions land in the bright band about as often as its probability says.
  const int w = 16, hgt = 8;
  std::vector<float> weights(std::size_t(w * hgt), 0.1f);
  for (int x = 0; x < w; ++x) weights[std::size_t(2 * w + x)] = 50.0f;  // row 2: theta in [45, 67.5] deg
  const EquirectSampler sampler(w, hgt, weights);
  double integral = 0.0;
  const int n = 200000;
  for (int i = 0; i < n; ++i) {
    SampleStream random(1u, 0u, std::uint32_t(i));
    integral += sampler.pdf(sample_uniform_sphere(random.next_2d())) * 4.0 * kPiD / n;
  }
  EXPECT_NEAR(integral, 1.0, 0.01);
  int in_band = 0;
  double band_probability = 0.0;
  for (int i = 0; i < n; ++i) {
    SampleStream random(2u, 0u, std::uint32_t(i));
    float pdf = 0.0f;
    const glm::vec3 d = sampler.sample(random.next_2d(), pdf);
    ASSERT_NEAR(glm::length(d), 1.0f, 1e-4f);
    ASSERT_NEAR(pdf, sampler.pdf(d), 1e-3f * pdf);
    const double theta = std::acos(std::clamp(double(d.y), -1.0, 1.0));
    if (theta >= kPiD / 4.0 && theta < 3.0 * kPiD / 8.0) ++in_band;
  }
  // Probability of row 2: its weight * sin(theta_center) share.
  double total = 0.0, band = 0.0;
  for (int y = 0; y < hgt; ++y) {
    const double row = (y == 2 ? 50.0 : 0.1) * w * std::sin(kPiD * (y + 0.5) / hgt);
    total += row;
    if (y == 2) band = row;
  }
  band_probability = band / total;
  EXPECT_NEAR(double(in_band) / n, band_probability, 0.01);
}

TEST(PathTracerConvergence, SunIsCountedOnceWithMis) {
  // Sky radiance 0: only the sun disc lights. An unshadowed receiver facing +Y gets
  // E = irradiance * sin(elevation) (a uniform disc wholly above the horizon).
  scene::Environment environment;
  environment.sky.radiance = 0.0f;
  environment.sun.elevation_degrees = 60.0f;
  environment.sun.azimuth_degrees = 0.0f;
  environment.sun.angular_radius_degrees = 5.0f;  // wide enough that BSDF samples find it often
  environment.sun.color = glm::vec3(1.0f);
  environment.sun.irradiance = 3.0f;
  const EnvironmentLight sky = EnvironmentLight::analytic_sky(environment);
  ASSERT_TRUE(sky.has_sun());

  // A sphere sitting on the sun's ray through (0, 0, 4) shadows that point completely.
  const glm::vec3 shadowed(0.0f, 0.0f, 4.0f);
  const glm::vec3 center = shadowed + 2.0f * sky.sun_direction();
  const EmbreeScene scene = sphere_over_plane(center, 0.5f, 1000.0f, glm::vec3(0.5f));
  const PathTracer tracer(scene, sky, sky, PathTracerSettings{LightTransport::direct});

  const double exact = 3.0 * std::sin(60.0 * kPiD / 180.0) / kPiD;
  expect_within_three_standard_errors(estimate_radiance(tracer, {0.0f, 0.0f, -4.0f}, glm::vec3(1.0f), 20000, 1),
                                      exact, 0.005);
  const Estimate dark = estimate_radiance(tracer, shadowed, glm::vec3(1.0f), 2000, 2);
  for (int c = 0; c < 3; ++c) EXPECT_EQ(dark.mean[c], 0.0);
}

TEST(PathTracerConvergence, WhiteFurnaceMultiBounceIsOne) {
  // Albedo 1 everywhere under a uniform environment of radiance 1 in every direction: L = 1 is
  // the solution of the rendering equation at every point, however the surfaces shadow each
  // other, so any bias (lost or double-counted bounces, roulette) shows as a departure from 1.
  const EmbreeScene scene = sphere_over_plane({0.0f, 0.55f, 0.0f}, 0.5f, 3.0f, glm::vec3(1.0f));
  const EnvironmentLight white = EnvironmentLight::constant(glm::vec3(1.0f));
  PathTracerSettings settings{LightTransport::multi_bounce};
  const PathTracer tracer(scene, white, white, settings);
  std::uint32_t stream = 100;
  for (float x : {0.0f, 0.3f, 0.8f}) {
    SCOPED_TRACE("x = " + std::to_string(x));
    const Estimate e = estimate_radiance(tracer, {x, 0.0f, 0.0f}, glm::vec3(1.0f), 20000, stream++);
    expect_within_three_standard_errors(e, 1.0, 0.01);
  }
  // One bounce loses the light of longer paths: strictly darker under the sphere.
  const PathTracer one_bounce(scene, white, white, PathTracerSettings{LightTransport::one_bounce});
  const Estimate partial = estimate_radiance(one_bounce, {0.0f, 0.0f, 0.0f}, glm::vec3(1.0f), 20000, 200);
  EXPECT_LT(partial.mean.x + 3.0 * partial.standard_error.x, 1.0);
}

TEST(PathTracerConvergence, HalfAlbedoPlaneFurnace) {
  // Albedo 0.5 open plane under a constant sky of 2 in multi-bounce mode: nothing bounces back,
  // so L = 0.5/pi * (2 pi) = 1 exactly, and the estimator has zero variance.
  const EmbreeScene scene = sphere_over_plane({0.0f, 50.0f, 0.0f}, 0.001f, 100.0f, glm::vec3(0.5f));
  const EnvironmentLight sky = EnvironmentLight::constant(glm::vec3(2.0f));
  const PathTracer tracer(scene, sky, sky, PathTracerSettings{LightTransport::multi_bounce});
  const Estimate e = estimate_radiance(tracer, {1.0f, 0.0f, 2.0f}, glm::vec3(0.5f), 1000, 3);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(e.mean[c], 1.0, 1e-5);
}

TEST(PathTracerLighting, ShOfUniformSkyIsTheSameConstant) {
  // A sky of one color everywhere and no sun projects to a pure DC term, which the ringing
  // window keeps (w_0 = 1): the SH lighting must reproduce the constant in every direction.
  scene::Scene scene;
  scene.environment.sky.zenith_color = scene.environment.sky.horizon_color =
      scene.environment.sky.below_horizon_color = glm::vec3(0.2f, 0.4f, 0.6f);
  scene.environment.sky.radiance = 2.0f;
  scene.environment.sun.irradiance = 0.0f;
  auto sh = EnvironmentLight::from_scene(scene, LightingKind::sh, scene.render.sh_order);
  ASSERT_TRUE(sh.ok()) << sh.message();
  for (const glm::vec3 d : {glm::vec3(0, 1, 0), glm::vec3(0, -1, 0), glm::normalize(glm::vec3(1, 0.2f, -0.5f))}) {
    const glm::vec3 value = sh->radiance(d);
    EXPECT_NEAR(value.r, 0.4f, 2e-3f);
    EXPECT_NEAR(value.g, 0.8f, 2e-3f);
    EXPECT_NEAR(value.b, 1.2f, 2e-3f);
  }
}

TEST(PathTracerLighting, ShUsesTheGivenOrderNotTheScenes) {
  // The reference's band limit is its own: the scene's render.sh_order (4 here) does not matter.
  scene::Scene scene;  // the default sky with its sun: every band carries energy
  scene.render.sh_order = 4;
  auto six = EnvironmentLight::from_scene(scene, LightingKind::sh, 6);
  ASSERT_TRUE(six.ok()) << six.message();
  scene::Scene six_scene = scene;
  six_scene.render.sh_order = 6;
  auto also_six = EnvironmentLight::from_scene(six_scene, LightingKind::sh, 6);
  auto four = EnvironmentLight::from_scene(scene, LightingKind::sh, 4);
  ASSERT_TRUE(also_six.ok() && four.ok());
  float differs = 0.0f;
  for (const glm::vec3 d : {glm::vec3(0, 1, 0), glm::normalize(glm::vec3(0.3f, 0.8f, 0.5f)), glm::vec3(1, 0, 0)}) {
    EXPECT_EQ(six->radiance(d), also_six->radiance(d));
    differs = std::max(differs, glm::length(six->radiance(d) - four->radiance(d)));
  }
  EXPECT_GT(differs, 1e-3f) << "orders 4 and 6 gave the same lighting";
  EXPECT_FALSE(EnvironmentLight::from_scene(scene, LightingKind::sh, 0).ok());
  EXPECT_FALSE(EnvironmentLight::from_scene(scene, LightingKind::sh, 9).ok());
}

}  // namespace
}  // namespace proxygi::ref
