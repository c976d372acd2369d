// The sun variant of VSGL (sh/vsgl_sun.h): RSM texels as VPLs, K = number of texels against
// brute-force gathering, a sun below the horizon, the orthographic fit, and the variant against
// the environment variant on a sender nothing shadows.
#include <cmath>
#include <numbers>
#include <optional>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "sh/basis.h"
#include "sh/convolution.h"
#include "sh/environment.h"
#include "sh/spherical_gaussian.h"
#include "tests/sh/vsgl_lobe_bound.h"
#include "sh/vsgl_sun.h"

namespace proxygi::sh {
namespace {

constexpr double kPi = std::numbers::pi;

// The RSM of a sphere, by casting each texel's centre ray (what the rasterizer samples).
std::vector<RsmTexel> sphere_rsm(const RsmView& view, const glm::dvec3& center, double radius, const glm::dvec3& albedo) {
  std::vector<RsmTexel> out;
  for (int y = 0; y < view.size; ++y)
    for (int x = 0; x < view.size; ++x) {
      const double u = view.u_min + (x + 0.5) * view.u_extent / view.size;
      const double v = view.v_min + (y + 0.5) * view.v_extent / view.size;
      const glm::dvec3 origin = u * view.right + v * view.up + view.s_max * view.toward_sun;
      const glm::dvec3 offset = origin - center;  // ray origin + t (−s)
      const double b = glm::dot(offset, view.toward_sun), c = glm::dot(offset, offset) - radius * radius;
      const double disc = b * b - c;
      if (disc < 0.0) continue;
      const double t = b - std::sqrt(disc);  // the first hit along −s
      RsmTexel texel;
      texel.position = origin - t * view.toward_sun;
      texel.normal = glm::normalize(texel.position - center);
      texel.albedo = albedo;
      out.push_back(texel);
    }
  return out;
}

SunLight test_sun() {
  SunLight sun;
  sun.direction = glm::normalize(glm::dvec3(0.4, 0.8, -0.3));
  sun.irradiance = glm::dvec3(3.0, 2.5, 2.0);
  return sun;
}

TEST(VsglSun, TexelsCarryTheSunsPowerOnTheSilhouette) {
  // Φ R = ρ E_s a_t per texel: the map's total is ρ E_s × (texels × a_t), the sphere's projected
  // area π R² up to the texels along its outline, |count a_t − π R²| ≤ 2π R × texel diagonal.
  const SunLight sun = test_sun();
  const glm::dvec3 center(1.0, 1.2, -0.5), albedo(0.5, 0.3, 0.2);
  const double radius = 0.4;
  const RsmView view = fit_rsm_view(sun.direction, center - radius, center + radius, 128, 0.05);
  const auto texels = sphere_rsm(view, center, radius, albedo);
  ASSERT_GT(texels.size(), 1000u);
  VsglSums sums;
  add_vsgl_sun(sums, texels, sun, view.texel_area(), center);
  const double diagonal = std::sqrt(2.0 * view.texel_area());
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(sums.flux[c], albedo[c] * sun.irradiance[c] * kPi * radius * radius,
                albedo[c] * sun.irradiance[c] * 2.0 * kPi * radius * diagonal) << c;
  // Only sunlit normals are in the map: every texel's VPL faces the sun.
  for (const RsmTexel& texel : texels) ASSERT_GT(glm::dot(texel.normal, sun.direction), 0.0);
  // A normal turned away from the sun sends nothing.
  RsmTexel back = texels.front();
  back.normal = -sun.direction;
  EXPECT_EQ(rsm_texel_light(back, sun, view.texel_area()).flux, glm::dvec3(0.0));
}

TEST(VsglSun, OrthographicFitMapsTheBoxIntoTheClipVolume) {
  const SunLight sun = test_sun();
  const glm::dvec3 low(-1.0, 0.0, -0.5), high(2.0, 1.8, 0.5);
  const RsmView view = fit_rsm_view(sun.direction, low, high, 64, 0.1);
  const glm::dmat4 clip = view.view_projection();
  for (int corner = 0; corner < 8; ++corner) {
    const glm::dvec3 p((corner & 1) ? high.x : low.x, (corner & 2) ? high.y : low.y, (corner & 4) ? high.z : low.z);
    const glm::dvec4 q = clip * glm::dvec4(p, 1.0);
    EXPECT_EQ(q.w, 1.0);
    EXPECT_GT(q.x, -1.0);
    EXPECT_LT(q.x, 1.0);
    EXPECT_GT(q.y, -1.0);
    EXPECT_LT(q.y, 1.0);
    EXPECT_GT(q.z, 0.0);
    EXPECT_LT(q.z, 1.0);
  }
  // Nearer the sun is nearer the camera (smaller depth); moving across u moves x.
  const glm::dvec3 mid = 0.5 * (low + high);
  EXPECT_LT((clip * glm::dvec4(mid + 0.1 * sun.direction, 1.0)).z, (clip * glm::dvec4(mid, 1.0)).z);
  EXPECT_NEAR((clip * glm::dvec4(mid + view.right * view.u_extent * 0.5, 1.0)).x -
                  (clip * glm::dvec4(mid, 1.0)).x, 1.0, 1e-12);
  EXPECT_NEAR(glm::dot(view.right, sun.direction), 0.0, 1e-12);
  EXPECT_NEAR(glm::dot(view.up, sun.direction), 0.0, 1e-12);
  EXPECT_NEAR(view.texel_area(), view.u_extent * view.v_extent / (64.0 * 64.0), 1e-15);
}

TEST(VsglSun, SunBelowTheHorizonAddsNothing) {
  SunLight sun = test_sun();
  const glm::dvec3 center(0.0, 1.0, 0.0);
  const RsmView view = fit_rsm_view(sun.direction, center - 0.3, center + 0.3, 32, 0.05);
  const auto texels = sphere_rsm(view, center, 0.3, glm::dvec3(0.6));
  ASSERT_FALSE(texels.empty());
  VsglSums above;
  add_vsgl_sun(above, texels, sun, view.texel_area(), center);
  EXPECT_GT(above.weight, 0.0);  // the same texels count with the sun up
  sun.direction.y = -sun.direction.y;
  VsglSums below;
  add_vsgl_sun(below, texels, sun, view.texel_area(), center);
  EXPECT_EQ(below.weight, 0.0);
  EXPECT_EQ(below.flux, glm::dvec3(0.0));
  EXPECT_FALSE(fit_vsgl(below, center));
}

TEST(VsglSun, OneLightPerTexelEqualsBruteForceGathering) {
  // K = number of texels: as Vsgl.OneLightPerVplEqualsBruteForceGathering (sh/vsgl_test.cpp),
  // the only approximation is the pair of clamped cosines replaced by eq. 1's lobe (bound e).
  const double pair_bound = testing::diffuse_lobe_pair_bound();
  const SunLight sun = test_sun();
  const glm::dvec3 center(0.0, 1.0, 0.0);
  const RsmView view = fit_rsm_view(sun.direction, center - 0.3, center + 0.3, 16, 0.02);
  const auto texels = sphere_rsm(view, center, 0.3, glm::dvec3(0.7, 0.5, 0.3));
  ASSERT_GT(texels.size(), 50u);
  std::vector<VirtualPointLight> lights;
  std::vector<Vsgl> vsgls;
  for (const RsmTexel& texel : texels) {
    lights.push_back(rsm_texel_light(texel, sun, view.texel_area()));
    VsglSums sums;
    add_vsgl_sun(sums, std::span(&texel, 1), sun, view.texel_area(), texel.position);
    vsgls.push_back(*fit_vsgl(sums, texel.position));
  }
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int r = 0; r < 40; ++r) {
    const glm::dvec3 p(1.5 * u(rng), 0.2 + 0.2 * u(rng), 1.5 * u(rng));  // around the sphere, near the ground
    const glm::dvec3 n = glm::normalize(glm::dvec3(0.3 * u(rng), 1.0, 0.3 * u(rng)));
    const glm::dvec3 brute = gather_vpl_irradiance(lights, p, n);
    glm::dvec3 summed(0.0), bound(0.0);
    for (std::size_t i = 0; i < lights.size(); ++i) {
      summed += vsgl_irradiance(vsgls[i], p, n);
      const glm::dvec3 offset = lights[i].position - p;
      bound += kPi * lights[i].flux / glm::dot(offset, offset) * pair_bound;
    }
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(summed[c], brute[c], bound[c] + 1e-5 * brute[c]) << r << " " << c;
  }
}

// E(n) = Σ L̃_i y_i(n) of one channel's SH lighting (order 3, clamped cosine).
double sh_irradiance(std::vector<double> lighting, const glm::dvec3& n) {
  lighting.resize(9);
  convolve_zonal(3, clamped_cosine_zonal(3), lighting);
  std::vector<double> basis(9);
  evaluate_basis(3, n, basis);
  double sum = 0.0;
  for (int i = 0; i < 9; ++i) sum += lighting[std::size_t(i)] * basis[std::size_t(i)];
  return sum;
}

TEST(VsglSun, DiffersFromTheEnvironmentVariantOnlyByTheSunsShare) {
  // A flat sunlit patch (nothing shadows it) of N × N quads of side h, normal +Y; the aligned
  // orthographic map's texel over quad i hits its centre with a_t = h² (n·s). Environment
  // variant: flux ρ E(n) h² per quad; sun variant: ρ E'(n) h² (sun taken off the SH) plus the
  // texel's ρ E_s a_t. Same geometry, so the two lights differ by the amplitude factor
  // (E' + E_s n·s)/E = 1 + (E_s n·s − E_sun(n))/E, E_sun the SH sun share; and |E_s n·s −
  // E_sun(n)| is the order-3 clamped cosine's error, ≤ 3/32 E_s for a point sun (at n·s = 0:
  // 1/4 − 5/32) plus the disc's O(r²).
  AnalyticSky sky;
  sky.sun_direction = glm::normalize(glm::dvec3(0.3, 0.7, 0.2));
  sky.sun_radius_radians = 0.035;
  const double sun_radiance = 800.0;
  sky.sun_radiance = glm::dvec3(sun_radiance);
  const double sun_irradiance = sun_radiance * kPi * std::sin(sky.sun_radius_radians) * std::sin(sky.sun_radius_radians);
  const glm::dvec3 n(0.0, 1.0, 0.0), albedo(0.6, 0.5, 0.4);
  const double cosine = glm::dot(n, sky.sun_direction);
  const RgbSh full = project_sky(3, sky), sun_share = project_sun_disc(3, sky);
  glm::dvec3 with_sun, without_sun, share;
  for (int c = 0; c < 3; ++c) {
    std::vector<double> rest = full.channels[std::size_t(c)];
    for (int i = 0; i < 9; ++i) rest[std::size_t(i)] -= sun_share.channels[std::size_t(c)][std::size_t(i)];
    with_sun[c] = sh_irradiance(full.channels[std::size_t(c)], n);
    without_sun[c] = sh_irradiance(rest, n);
    share[c] = sh_irradiance(sun_share.channels[std::size_t(c)], n);
    EXPECT_NEAR(with_sun[c] - without_sun[c], share[c], 1e-9 * with_sun[c]);
    EXPECT_LE(std::abs(share[c] - sun_irradiance * cosine), (3.0 / 32.0 + 0.01) * sun_irradiance);
  }
  const SunLight sun{sky.sun_direction, glm::dvec3(sun_irradiance)};
  const int count = 16;
  const double h = 0.05;
  const glm::dvec3 origin(0.0, 0.0, 0.0);
  VsglSums environment, sunlit;
  std::vector<RsmTexel> texels;
  for (int i = 0; i < count; ++i)
    for (int j = 0; j < count; ++j) {
      const glm::dvec3 x((i + 0.5) * h - 0.4, 0.3, (j + 0.5) * h - 0.4);
      add_light(environment, {x, n, albedo * with_sun * h * h}, origin);
      add_light(sunlit, {x, n, albedo * without_sun * h * h}, origin);
      texels.push_back({x, n, albedo});
    }
  add_vsgl_sun(sunlit, texels, sun, h * h * cosine, origin);
  const auto env_light = fit_vsgl(environment, origin), sun_light = fit_vsgl(sunlit, origin);
  ASSERT_TRUE(env_light && sun_light);
  for (const glm::dvec3& p : {glm::dvec3(1.5, 0.0, 0.2), glm::dvec3(-0.3, 0.8, 1.7), glm::dvec3(0.0, 2.5, 0.0)}) {
    const glm::dvec3 receiver_normal = glm::normalize(glm::dvec3(0.0, 0.3, 0.0) - p);
    const glm::dvec3 env_e = vsgl_irradiance(*env_light, p, receiver_normal);
    const glm::dvec3 sun_e = vsgl_irradiance(*sun_light, p, receiver_normal);
    for (int c = 0; c < 3; ++c) {
      ASSERT_GT(env_e[c], 0.0);
      const double expected = env_e[c] * (sun_irradiance * cosine - share[c]) / with_sun[c];
      // The luminance weights differ per channel mix, not per geometry: the fits match to rounding.
      EXPECT_NEAR(sun_e[c] - env_e[c], expected, 1e-9 * env_e[c]) << c;
    }
  }
}

}  // namespace
}  // namespace proxygi::sh
