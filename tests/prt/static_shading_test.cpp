// How static receivers combine PRT with the proxies (prt/static_shading.h): identities, and the
// derived L1 level (notes/prt-vsgl.md §2, [DER]) against the path tracer under band-limited light.
#include "prt/static_shading.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "prt/transfer.h"
#include "prt_scenes.h"
#include "ref/path_tracer.h"
#include "sh/basis.h"
#include "sh/convolution.h"

namespace proxygi::prt {
namespace {

constexpr int kOrder = 4;
constexpr std::size_t kN = 16;
constexpr float kPiF = 3.14159265f;

std::vector<float> unoccluded() {
  std::vector<float> o(kN, 0.0f);
  o[0] = float(sh::kSqrtFourPi);
  return o;
}

struct Receiver {
  std::vector<float> h, t;
  std::array<std::vector<float>, 3> t_di;
  StaticReceiverSh view() const { return {h, t, {t_di[0], t_di[1], t_di[2]}}; }
};

Receiver receiver_at(const StaticReceivers& r, const TransferSet& set, std::size_t s, std::size_t v) {
  Receiver out;
  out.h = test::to_float(sh::clamped_cosine_about(kOrder, glm::dvec3(r.surfaces[s].normals[v])));
  const SurfaceTransfer& t = set.surfaces[s];
  out.t.assign(t.shadowed.begin() + std::ptrdiff_t(v * kN), t.shadowed.begin() + std::ptrdiff_t((v + 1) * kN));
  for (std::size_t c = 0; c < 3; ++c)
    out.t_di[c].assign(t.interreflected.begin() + std::ptrdiff_t((3 * v + c) * kN),
                       t.interreflected.begin() + std::ptrdiff_t((3 * v + c + 1) * kN));
  return out;
}

TEST(PrtStaticShading, EveryLevelIsTodaysWhereNothingStaticBlocks) {
  // T_DS = T_DI = H(N): ratio and l1 must give l0's E for any proxy visibility.
  Receiver rc;
  rc.h = test::to_float(sh::clamped_cosine_about(kOrder, glm::normalize(glm::dvec3(0.2, 1.0, -0.3))));
  rc.t = rc.h;
  rc.t_di = {rc.h, rc.h, rc.h};
  const sh::RgbSh light = test::test_lighting(kOrder);
  const std::array<std::vector<float>, 3> l = {test::to_float(light.channels[0]), test::to_float(light.channels[1]),
                                               test::to_float(light.channels[2])};
  std::vector<float> o = unoccluded();
  o[1] = -0.8f, o[2] = 0.5f, o[6] = 0.3f;  // some proxy shadow
  const std::array<std::span<const float>, 3> lights = {l[0], l[1], l[2]};
  const glm::vec3 e0 = shade_static_receiver(kOrder, StaticTransferLevel::l0, rc.view(), lights, o);
  const glm::vec3 e_ratio = shade_static_receiver(kOrder, StaticTransferLevel::ratio, rc.view(), lights, o);
  const glm::vec3 e1 = shade_static_receiver(kOrder, StaticTransferLevel::l1, rc.view(), lights, o);
  EXPECT_GT(e0.x, 0.0f);
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(e_ratio[c], e0[c], 1e-5f * e0[c]);
    EXPECT_NEAR(e1[c], e0[c], 1e-5f * e0[c]);
  }
  EXPECT_EQ(unblocked_proxy_fraction(kOrder, rc.h, rc.t, o), 1.0f);
}

// Band-limited light L (order 4) on the wall corner, a black proxy sphere near the corner (so
// I_p = 0 and only the visibility combination is tested), O_p its exact visibility projected to
// order 4 (isolates the combination from the SHEXP error). The path tracer sees the same
// triangles and the sphere, multi-bounce.
TEST(PrtStaticShading, L1AgreesWithThePathTracerAtTheCorner) {
  const StaticReceivers r = test::wall_corner(0.2f);
  auto set = compute_transfer(r, {.order = kOrder, .directions = 2048, .bounces = 5});
  ASSERT_TRUE(set.ok()) << set.message();
  const sh::RgbSh light_sh = test::test_lighting(kOrder);
  const std::array<std::vector<float>, 3> l = {
      test::to_float(light_sh.channels[0]), test::to_float(light_sh.channels[1]), test::to_float(light_sh.channels[2])};
  const std::array<std::span<const float>, 3> lights = {l[0], l[1], l[2]};
  const ref::EnvironmentLight light = ref::EnvironmentLight::spherical_harmonics(light_sh);
  const ref::SphereShape sphere{{-0.45f, 0.35f, -0.45f}, 0.3f, ref::SurfaceMaterial{glm::vec3(0.0f), nullptr}};
  auto open_scene = ref::EmbreeScene::build(test::tracer_meshes(r));
  auto proxy_scene = ref::EmbreeScene::build(test::tracer_meshes(r), std::span(&sphere, 1));
  ASSERT_TRUE(open_scene.ok() && proxy_scene.ok());
  const ref::PathTracerSettings pt_settings{.transport = ref::LightTransport::multi_bounce};
  const ref::PathTracer open_tracer(*open_scene, light, light, pt_settings),
      proxy_tracer(*proxy_scene, light, light, pt_settings);
  const sh::SphereQuadrature quadrature = sh::make_sphere_quadrature(96, 192);

  struct Point {
    std::size_t surface;
    glm::vec3 p;
  };
  const Point points[] = {{0, {-0.8f, 0, -0.8f}}, {0, {-0.6f, 0, -0.2f}},    {0, {-0.2f, 0, -0.6f}},
                          {0, {0.0f, 0, 0.0f}},   {0, {-0.4f, 0, 0.2f}},     {0, {0.4f, 0, -0.8f}},
                          {0, {1.0f, 0, 1.0f}},   {1, {-1.0f, 0.4f, -0.2f}}, {2, {-0.2f, 0.6f, -1.0f}}};
  const int samples = 8192;
  double err_open = 0, err[3] = {0, 0, 0}, err_max_l1 = 0;
  int index = 0;
  for (const Point& point : points) {
    const StaticSurface& s = r.surfaces[point.surface];
    const std::size_t v = test::nearest_vertex(s, point.p);
    const glm::vec3 x = s.positions[v], n = s.normals[v];
    const Receiver rc = receiver_at(r, *set, point.surface, v);
    // O_p: exact sphere visibility from x, projected.
    const glm::dvec3 to_center = glm::dvec3(sphere.center - x);
    const double cos_cap = std::sqrt(1.0 - double(sphere.radius * sphere.radius) / glm::dot(to_center, to_center));
    const std::vector<float> o = test::to_float(sh::project_function(kOrder, quadrature, [&](const glm::dvec3& d) {
      return glm::dot(d, glm::normalize(to_center)) >= cos_cap ? 0.0 : 1.0;
    }));
    // Path-traced irradiance E = π L_out / albedo, with and without the sphere.
    ref::SurfaceHit hit;
    hit.position = x;
    hit.geometric_normal = hit.shading_normal = n;
    hit.albedo = s.albedo;
    glm::dvec3 sum_open(0.0), sum_proxy(0.0);
    double sum_sq_open = 0;  // of luminance, for the estimate's standard error
    for (int k = 0; k < samples; ++k) {
      ref::SampleStream a(11, std::uint32_t(index), std::uint32_t(k)), b(11, std::uint32_t(index), std::uint32_t(k));
      const glm::dvec3 open = glm::dvec3(open_tracer.shade(hit, a).radiance);
      sum_open += open;
      sum_sq_open += std::pow(0.2126 * open.x + 0.7152 * open.y + 0.0722 * open.z, 2);
      sum_proxy += glm::dvec3(proxy_tracer.shade(hit, b).radiance);
    }
    const glm::vec3 e_pt_open = glm::vec3(sum_open / double(samples)) * kPiF / s.albedo;
    const glm::vec3 e_pt = glm::vec3(sum_proxy / double(samples)) * kPiF / s.albedo;
    const glm::vec3 e_prt_open =
        shade_static_receiver(kOrder, StaticTransferLevel::l1, rc.view(), lights, unoccluded());
    const glm::vec3 e_levels[3] = {shade_static_receiver(kOrder, StaticTransferLevel::l0, rc.view(), lights, o),
                                   shade_static_receiver(kOrder, StaticTransferLevel::ratio, rc.view(), lights, o),
                                   shade_static_receiver(kOrder, StaticTransferLevel::l1, rc.view(), lights, o)};
    const auto lum = [](glm::vec3 e) { return 0.2126f * e.x + 0.7152f * e.y + 0.0722f * e.z; };
    const double rel_open = std::abs(lum(e_prt_open) / lum(e_pt_open) - 1.0f);
    err_open = std::max(err_open, rel_open);
    // Without the proxy L1 is T_DI · L, the transfer alone: it must match the path tracer within
    // the tracer's noise (4 standard errors, measured; Sobol paths are at most this noisy) plus
    // 0.5 % for the PRT's own estimate (2048 stratified directions per pass: 1/√2048 of a
    // blocked fraction ≤ 0.5 is ≤ 1.1 % per vertex before stratification; 5 bounces leave ρ⁶ < 0.1 %).
    const double mean_lum = (0.2126 * sum_open.x + 0.7152 * sum_open.y + 0.0722 * sum_open.z) / samples;
    const double std_error = std::sqrt(std::max(sum_sq_open / samples - mean_lum * mean_lum, 0.0) / samples) / mean_lum;
    EXPECT_LT(rel_open, 4 * std_error + 0.005) << s.name << " vertex " << v << " without the proxy";
    double rel[3];
    for (int level = 0; level < 3; ++level) {
      rel[level] = std::abs(lum(e_levels[level]) / lum(e_pt) - 1.0f);
      err[level] += rel[level] / double(std::size(points));
    }
    err_max_l1 = std::max(err_max_l1, rel[2]);
    std::printf(
        "point %d (%s %.1f %.1f %.1f): open pt %.4f ± %.2f%% prt %.4f (%.2f%%) | proxy pt %.4f l0 %.4f ratio %.4f l1 "
        "%.4f kappa %.3f\n",
        index, s.name.c_str(), x.x, x.y, x.z, lum(e_pt_open), 100 * std_error, lum(e_prt_open), 100 * rel_open,
        lum(e_pt), lum(e_levels[0]), lum(e_levels[1]), lum(e_levels[2]),
        unblocked_proxy_fraction(kOrder, rc.h, rc.t, o));
    ++index;
  }
  std::printf("max open error %.2f%%; mean error l0 %.2f%% ratio %.2f%% l1 %.2f%%; max l1 %.2f%%\n", 100 * err_open,
              100 * err[0], 100 * err[1], 100 * err[2], 100 * err_max_l1);
  // With the proxy: the notes' claim is L1 < ratio < L0 in error. L1's mean error is held to the
  // issue's 5 % radiance goal; single vertices in the corner exceed it (the order-4 truncated
  // product O_p ∗ (L ∗ T) of a sharp cap and a quarter hemisphere; see the printed table).
  EXPECT_LT(err[2], err[1]);
  EXPECT_LT(err[1], err[0]);
  EXPECT_LT(err[2], 0.05);
}

}  // namespace
}  // namespace proxygi::prt
