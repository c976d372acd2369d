// Issue 20, "the unexplained excess": the simplest bounce with a tight answer, computed four ways.
// One diffuse sphere (albedo ρ, centre 0.6 m above the ground, radius 0.5 m) over a ground point
// with normal +y, under a sky L(d) = 1 + 0.5 d_y (SH order 2 exactly). The sphere is a sender lit
// without shadows, as both bounce methods assume: E(q) = π + (π/3) q_y at its point of normal q,
// its radiance ρ E(q)/π. The bounce irradiance at the ground point p is then
//   E_b(p) = ∫_cap ρ E(q(ω))/π cos(ω, n) dω  (cap: the sphere as p sees it, fully above p's horizon),
// evaluated here by quadrature (the truth), by the path tracer's bounce reference (with minus
// without character senders, same seeds, unshadowed senders), by the proxies' CPU twin
// (render::accumulate_indirect after the shadow twin's visibility) and by VSGL's CPU twins (the
// sphere as VPLs: brute-force gathering, and one fitted VSGL). The chart's mannequin:
// bounce_excess_mannequin_test.cpp.
// The proxies' default sender light (render.mask_sender_light, sh/sender_light.h) drops that
// assumption: the ground blocks the sky below its horizon from the sender, as it does for a real
// sphere over a real ground. TheGroundBlocksTheSenderLightBelowTheHorizon checks the proxies with it
// against that truth and the path tracer with shadowed senders.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include <gtest/gtest.h>

#include "ref/embree_scene.h"
#include "ref/path_tracer.h"
#include "ref/scene_geometry.h"
#include "render/frame_tables.h"
#include "render/shading.h"
#include "sh/basis.h"
#include "sh/vsgl.h"

namespace proxygi::study {
namespace {

constexpr double kPi = 3.14159265358979323846;
const glm::dvec3 kCentre(0.0, 0.6, 0.0);
constexpr double kRadius = 0.5;
constexpr double kAlbedo = 0.8;  // the sender's, every channel
const glm::dvec3 kUp(0.0, 1.0, 0.0);

// The sky's exact unshadowed irradiance at normal q: ∫ (1 + 0.5 d_y) max(q·d, 0) dω.
double sky_irradiance(const glm::dvec3& q) { return kPi + kPi / 3.0 * q.y; }

// The same over the sky above the horizon only (a sender over an opaque, black ground):
// ∫_{d_y>0} (1 + 0.5 d_y) max(q·d, 0) dω, a function of q_y alone, tabulated over q_y ∈ [−1, 1]
// by midpoint quadrature and interpolated linearly.
double sky_irradiance_above_horizon(const glm::dvec3& q) {
  constexpr int kRows = 1025, kPolar = 256, kAzimuth = 512;
  static const std::vector<double> table = [] {
    std::vector<double> values(kRows);
    for (int row = 0; row < kRows; ++row) {
      const double qy = -1.0 + 2.0 * row / (kRows - 1), qx = std::sqrt(std::max(1.0 - qy * qy, 0.0));
      double sum = 0.0;
      for (int i = 0; i < kPolar; ++i) {
        const double theta = (i + 0.5) * 0.5 * kPi / kPolar;  // from +y, above the horizon
        for (int j = 0; j < kAzimuth; ++j) {
          const double phi = (j + 0.5) * 2.0 * kPi / kAzimuth;
          const glm::dvec3 d(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
          sum += (1.0 + 0.5 * d.y) * std::max(qx * d.x + qy * d.y, 0.0) * std::sin(theta);
        }
      }
      values[std::size_t(row)] = sum * (0.5 * kPi / kPolar) * (2.0 * kPi / kAzimuth);
    }
    return values;
  }();
  const double at = (std::clamp(q.y, -1.0, 1.0) + 1.0) * 0.5 * (kRows - 1);
  const int row = std::min(int(at), kRows - 2);
  return table[std::size_t(row)] + (at - row) * (table[std::size_t(row) + 1] - table[std::size_t(row)]);
}

// How the sender is lit: by the whole sky (the bounce methods' assumption) or by the sky above
// the ground's horizon (the ground opaque and black, so nothing bounces off it).
enum class SenderLight { unshadowed, above_horizon };

// L = 1 + 0.5 d_y in SH (order 3, the band-2 coefficients 0): y_00 = 1/√4π, and by the addition
// theorem d·up = (4π/3) Σ_m y_1m(d) y_1m(up).
sh::RgbSh linear_sky() {
  sh::RgbSh sky;
  sky.order = 3;
  double up[9];
  sh::evaluate_basis(3, kUp, std::span<double>(up, 9));
  for (auto& channel : sky.channels) {
    channel.assign(9, 0.0);
    channel[0] = sh::kSqrtFourPi;
    for (int i = 1; i < 4; ++i) channel[std::size_t(i)] = 0.5 * 4.0 * kPi / 3.0 * up[i];
  }
  return sky;
}

// E_b(p) by midpoint quadrature over the cap in (angle from the centre direction, azimuth).
double quadrature_bounce(const glm::dvec3& p, SenderLight light) {
  const glm::dvec3 to_centre = kCentre - p;
  const double distance = glm::length(to_centre);
  const glm::dvec3 axis = to_centre / distance;
  const double half_angle = std::asin(kRadius / distance);
  const glm::dvec3 tangent = glm::normalize(glm::cross(axis, std::abs(axis.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 0, 1)));
  const glm::dvec3 bitangent = glm::cross(axis, tangent);
  constexpr int kAngles = 1024, kAzimuths = 512;
  double sum = 0.0;
  for (int i = 0; i < kAngles; ++i) {
    const double t = (i + 0.5) * half_angle / kAngles;
    for (int j = 0; j < kAzimuths; ++j) {
      const double phi = (j + 0.5) * 2.0 * kPi / kAzimuths;
      const glm::dvec3 w = std::cos(t) * axis + std::sin(t) * (std::cos(phi) * tangent + std::sin(phi) * bitangent);
      // Nearest hit of p + s w on the sphere: s = b − √(b² − c), b = w·(c − p), c = |c − p|² − R².
      const double b = glm::dot(w, to_centre);
      const double s = b - std::sqrt(std::max(b * b - (distance * distance - kRadius * kRadius), 0.0));
      const glm::dvec3 q = (p + s * w - kCentre) / kRadius;
      const double irradiance = light == SenderLight::unshadowed ? sky_irradiance(q) : sky_irradiance_above_horizon(q);
      sum += kAlbedo * irradiance / kPi * std::max(glm::dot(w, kUp), 0.0) * std::sin(t);
    }
  }
  return sum * (half_angle / kAngles) * (2.0 * kPi / kAzimuths);
}

struct Estimate {
  double mean = 0.0;
  double standard_error = 0.0;
};

// The path tracer's bounce reference at p, as irradiance: π (with − without senders) / ρ_ground
// per sample (ground albedo 1), same seeds; the standard error from the samples' spread. One
// bounce: the sender's shadowed light is the sky the ground leaves it (SenderLight::above_horizon).
Estimate path_traced_bounce(const glm::dvec3& p, int samples, SenderLight sender) {
  const ref::SphereShape sphere{glm::vec3(kCentre), float(kRadius), ref::SurfaceMaterial{glm::vec3(float(kAlbedo)), nullptr}, true};
  auto scene = ref::EmbreeScene::build(ref::ground_meshes(scene::Ground{true, 40.0f, glm::vec3(1.0f)}),
                                       std::span<const ref::SphereShape>(&sphere, 1));
  EXPECT_TRUE(scene.ok()) << (scene.ok() ? "" : scene.message());
  const ref::EnvironmentLight light = ref::EnvironmentLight::spherical_harmonics(linear_sky());
  ref::PathTracerSettings with_settings, without_settings;
  with_settings.unshadowed_character_senders = without_settings.unshadowed_character_senders =
      sender == SenderLight::unshadowed;
  without_settings.character_senders = false;
  const ref::PathTracer with(*scene, light, light, with_settings), without(*scene, light, light, without_settings);
  ref::SurfaceHit ground;
  ground.position = glm::vec3(p);
  ground.geometric_normal = ground.shading_normal = glm::vec3(kUp);
  ground.albedo = glm::vec3(1.0f);
  double sum = 0.0, square = 0.0;
  for (int i = 0; i < samples; ++i) {
    ref::SampleStream a(11, 0, std::uint32_t(i)), b(11, 0, std::uint32_t(i));
    const double x = kPi * double(with.shade(ground, a).radiance.g - without.shade(ground, b).radiance.g);
    sum += x;
    square += x * x;
  }
  Estimate out;
  out.mean = sum / samples;
  out.standard_error = std::sqrt(std::max(square / samples - out.mean * out.mean, 0.0) / samples);
  return out;
}

render::FrameTables linear_sky_tables(SenderLight light) {
  settings::RenderSettings settings;
  settings.sh_order = 3;
  settings.sh_window = false;
  settings.mask_sender_light = light == SenderLight::above_horizon;
  return render::make_frame_tables(linear_sky(), settings);
}

// The proxy twin: the shadow twin's visibility DC (for ξ_p), then the indirect twin.
double proxy_bounce(const render::FrameTables& tables, const glm::dvec3& p, settings::IndirectOperator op) {
  const render::Sphere sphere{glm::vec3(kCentre), float(kRadius), glm::vec3(float(kAlbedo))};
  const std::span<const render::Sphere> spheres(&sphere, 1);
  const glm::vec3 position(p), normal(kUp);
  const std::vector<float> log_occlusion = render::accumulate_log_occlusion(tables, position, normal, spheres);
  const render::DirectResult direct =
      render::exponentiate_and_shade(tables, log_occlusion, tables.settings.hyb_tau, position, normal);
  return render::accumulate_indirect(tables, position, normal, spheres, direct.occlusion_dc, op).irradiance.g;
}

// The sphere as VPLs (latitude–longitude patches, as vsgl_lights.comp: flux ρ max(E(n), 0) A with
// E = Σ L̃_i y_i(n), the order-3 irradiance the frame uploads). Rings of equal angle, patches about
// square, so the patches under the sphere (0.1 m above the nearest receiver) are ~3 mm wide.
std::vector<sh::VirtualPointLight> sphere_lights(const render::FrameTables& tables) {
  constexpr int kRings = 512;
  std::vector<sh::VirtualPointLight> lights;
  for (int i = 0; i < kRings; ++i) {
    const double theta0 = kPi * i / kRings, theta1 = kPi * (i + 1) / kRings, theta = 0.5 * (theta0 + theta1);
    const int segments = std::max(8, int(std::lround(2.0 * kRings * std::sin(theta))));
    const double area = kRadius * kRadius * (std::cos(theta0) - std::cos(theta1)) * 2.0 * kPi / segments;
    for (int j = 0; j < segments; ++j) {
      const double phi = (j + 0.5) * 2.0 * kPi / segments;
      const glm::dvec3 n(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
      double basis[9];
      sh::evaluate_basis(3, n, std::span<double>(basis, 9));
      double irradiance = 0.0;
      for (int k = 0; k < 9; ++k) irradiance += basis[k] * double(tables.irradiance_order3[1][std::size_t(k)]);
      lights.push_back({kCentre + kRadius * n, n, glm::dvec3(kAlbedo * std::max(irradiance, 0.0) * area)});
    }
  }
  return lights;
}

struct Bounces {
  double x;  // ground point (x, 0, 0)
  double truth, path_traced, path_traced_error, point, averaged, exact, vpl, vsgl;
};

std::vector<Bounces> all_bounces(SenderLight sender) {
  const render::FrameTables tables = linear_sky_tables(sender);
  const std::vector<sh::VirtualPointLight> lights = sphere_lights(tables);
  sh::VsglSums sums;
  for (const sh::VirtualPointLight& light : lights) sh::add_light(sums, light, kCentre);
  const std::optional<sh::Vsgl> vsgl = sh::fit_vsgl(sums, kCentre);
  EXPECT_TRUE(vsgl.has_value());
  std::vector<Bounces> out;
  for (double x : {0.0, 0.4, 0.8, 1.5}) {
    const glm::dvec3 p(x, 0.0, 0.0);
    Bounces b{x};
    b.truth = quadrature_bounce(p, sender);
    const Estimate traced = path_traced_bounce(p, 1 << 14, sender);
    b.path_traced = traced.mean;
    b.path_traced_error = traced.standard_error;
    b.point = proxy_bounce(tables, p, settings::IndirectOperator::point);
    b.averaged = proxy_bounce(tables, p, settings::IndirectOperator::averaged);
    b.exact = proxy_bounce(tables, p, settings::IndirectOperator::exact);
    b.vpl = sh::gather_vpl_irradiance(lights, p, kUp).g;
    b.vsgl = vsgl ? sh::vsgl_irradiance(*vsgl, p, kUp).g : 0.0;
    std::printf("x=%.1f truth %.5f | path traced %.5f ± %.5f (%.3f) | point %.3f averaged %.3f exact %.3f | "
                "VPLs %.3f VSGL %.3f (ratios to the truth)\n",
                x, b.truth, b.path_traced, b.path_traced_error, b.path_traced / b.truth, b.point / b.truth,
                b.averaged / b.truth, b.exact / b.truth, b.vpl / b.truth, b.vsgl / b.truth);
    out.push_back(b);
  }
  return out;
}

// Measured (printed): path tracer / truth 1.001–1.015 (within 1.3 standard errors); point
// 0.88–0.98, averaged 0.91–1.00, exact 0.95–1.00 (the order-3 cap and cosine lose a little);
// VPLs 1.000; VSGL 0.55–0.83 (its Gaussian of position, σ = R, is poor this close). No method is
// too bright: the formulas carry no stray π, no albedo twice, the same E(n) convention.
TEST(BounceExcess, FourWaysOfOneSphereOverTheGround) {
  const std::vector<Bounces> bounces = all_bounces(SenderLight::unshadowed);
  ASSERT_EQ(bounces.size(), 4u);
  for (const Bounces& b : bounces) {
    ASSERT_GT(b.truth, 0.05) << "x=" << b.x;
    // The reference: unbiased, so within 4 standard errors of the quadrature.
    EXPECT_NEAR(b.path_traced, b.truth, 4.0 * b.path_traced_error) << "x=" << b.x;
    // The VPL discretization (~3 mm patches) against the quadrature.
    EXPECT_NEAR(b.vpl, b.truth, 0.01 * b.truth) << "x=" << b.x;
    // The proxies' operators are band-limited (order 3): never above the truth, the exact one
    // within 6 %, the approximations within 15 %.
    for (double proxy : {b.point, b.averaged, b.exact}) {
      EXPECT_LE(proxy, 1.01 * b.truth) << "x=" << b.x;
      EXPECT_GE(proxy, 0.85 * b.truth) << "x=" << b.x;
    }
    EXPECT_GE(b.exact, 0.94 * b.truth) << "x=" << b.x;
    // Known, documented: one VSGL is too dark near its sender (the closed form wants
    // ‖μ_v − p‖ ≫ σ_v; here 0.6–1.6 m against σ_v = R = 0.5 m), less so farther away.
    EXPECT_LT(b.vsgl, 0.9 * b.truth) << "x=" << b.x;
    EXPECT_GT(b.vsgl, 0.5 * b.truth) << "x=" << b.x;
  }
  EXPECT_LT(bounces[0].vsgl / bounces[0].truth, bounces[3].vsgl / bounces[3].truth) << "VSGL improves with distance";
}

// The default sender light: the proxies' sphere is lit by the sky above the ground plane of the
// receiver (N = +y: exactly the ground's horizon); the truth and the path tracer light the real
// sphere over an opaque black ground. The sender light cut at the horizon is projected to order 3,
// which the exact operator carries within 8 % of the truth wherever the bounce is not tiny (measured
// 0.93–1.02); every operator comes out at least twice as close to this truth as with the paper's
// unshadowed sender (the point operator, which reads the sphere's back point only, strictly closer),
// whose light from below the horizon is most of its total here (1.9–60× the truth).
TEST(BounceExcess, TheGroundBlocksTheSenderLightBelowTheHorizon) {
  const std::vector<Bounces> bounces = all_bounces(SenderLight::above_horizon);
  const std::vector<Bounces> unmasked = all_bounces(SenderLight::unshadowed);
  ASSERT_EQ(bounces.size(), 4u);
  for (std::size_t i = 0; i < bounces.size(); ++i) {
    const Bounces& b = bounces[i];
    const Bounces& paper = unmasked[i];
    ASSERT_GT(b.truth, 0.01) << "x=" << b.x;
    EXPECT_NEAR(b.path_traced, b.truth, 4.0 * b.path_traced_error) << "x=" << b.x;
    if (b.truth > 0.04) {
      EXPECT_NEAR(b.exact, b.truth, 0.08 * b.truth) << "x=" << b.x;
    }
    EXPECT_LT(std::abs(b.point - b.truth), std::abs(paper.point - b.truth)) << "x=" << b.x;
    EXPECT_LT(std::abs(b.averaged - b.truth), 0.5 * std::abs(paper.averaged - b.truth)) << "x=" << b.x;
    EXPECT_LT(std::abs(b.exact - b.truth), 0.5 * std::abs(paper.exact - b.truth)) << "x=" << b.x;
    EXPECT_GT(paper.averaged, 1.5 * b.truth) << "x=" << b.x;
  }
}

}  // namespace
}  // namespace proxygi::study
