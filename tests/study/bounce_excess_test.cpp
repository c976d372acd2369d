// Issue 20, "the unexplained excess": the simplest bounce with a tight answer, computed four ways.
// One diffuse sphere (albedo ρ, centre 0.6 m above the ground, radius 0.5 m) over a ground point
// with normal +y, under a sky L(d) = 1 + 0.5 d_y (SH order 2 exactly). The sphere is a sender lit
// without shadows, as both bounce methods assume: E(q) = π + (π/3) q_y at its point of normal q,
// its radiance ρ E(q)/π. The bounce irradiance at the ground point p is then
//   E_b(p) = ∫_cap ρ E(q(ω))/π cos(ω, n) dω  (cap: the sphere as p sees it, fully above p's horizon),
// evaluated here by quadrature (the truth), by the path tracer's bounce reference (with minus
// without character senders, same seeds, unshadowed senders), by the proxies' CPU twin
// (render::accumulate_indirect after the shadow twin's visibility) and by VSGL's CPU twins (the
// sphere as VPLs: brute-force gathering, and one fitted VSGL).
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
#include "render/environment_lighting.h"
#include "scene/camera.h"
#include "scene/scene.h"
#include "study/chart_scenes.h"
#include "world/world.h"

namespace proxygi::study {
namespace {

constexpr double kPi = 3.14159265358979323846;
const glm::dvec3 kCentre(0.0, 0.6, 0.0);
constexpr double kRadius = 0.5;
constexpr double kAlbedo = 0.8;  // the sender's, every channel
const glm::dvec3 kUp(0.0, 1.0, 0.0);

// The sky's exact unshadowed irradiance at normal q: ∫ (1 + 0.5 d_y) max(q·d, 0) dω.
double sky_irradiance(const glm::dvec3& q) { return kPi + kPi / 3.0 * q.y; }

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
double quadrature_bounce(const glm::dvec3& p) {
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
      sum += kAlbedo * sky_irradiance(q) / kPi * std::max(glm::dot(w, kUp), 0.0) * std::sin(t);
    }
  }
  return sum * (half_angle / kAngles) * (2.0 * kPi / kAzimuths);
}

struct Estimate {
  double mean = 0.0;
  double standard_error = 0.0;
};

// The path tracer's bounce reference at p, as irradiance: π (with − without senders) / ρ_ground
// per sample (ground albedo 1), same seeds; the standard error from the samples' spread.
Estimate path_traced_bounce(const glm::dvec3& p, int samples) {
  const ref::SphereShape sphere{glm::vec3(kCentre), float(kRadius), ref::SurfaceMaterial{glm::vec3(float(kAlbedo)), nullptr}, true};
  auto scene = ref::EmbreeScene::build(ref::ground_meshes(scene::Ground{true, 40.0f, glm::vec3(1.0f)}),
                                       std::span<const ref::SphereShape>(&sphere, 1));
  EXPECT_TRUE(scene.ok()) << (scene.ok() ? "" : scene.message());
  const ref::EnvironmentLight light = ref::EnvironmentLight::spherical_harmonics(linear_sky());
  ref::PathTracerSettings with_settings, without_settings;
  with_settings.unshadowed_character_senders = without_settings.unshadowed_character_senders = true;
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

render::FrameTables linear_sky_tables() {
  settings::RenderSettings settings;
  settings.sh_order = 3;
  settings.sh_window = false;
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

std::vector<Bounces> all_bounces() {
  const render::FrameTables tables = linear_sky_tables();
  const std::vector<sh::VirtualPointLight> lights = sphere_lights(tables);
  sh::VsglSums sums;
  for (const sh::VirtualPointLight& light : lights) sh::add_light(sums, light, kCentre);
  const std::optional<sh::Vsgl> vsgl = sh::fit_vsgl(sums, kCentre);
  EXPECT_TRUE(vsgl.has_value());
  std::vector<Bounces> out;
  for (double x : {0.0, 0.4, 0.8, 1.5}) {
    const glm::dvec3 p(x, 0.0, 0.0);
    Bounces b{x};
    b.truth = quadrature_bounce(p);
    const Estimate traced = path_traced_bounce(p, 1 << 14);
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
  const std::vector<Bounces> bounces = all_bounces();
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

// The chart's `contact` scene at its first chart frame: the mannequin as the path tracer sees it
// (triangles, unshadowed senders) and as the methods see it (its rig's proxies; its triangles
// as VPLs, as vsgl_lights.comp forms them), under the default sky's unwindowed order-3 SH (the
// same lighting for all, so only the senders' geometry differs), at ground points around it.
struct MannequinBounces {
  double truth = 0.0, truth_error = 0.0;  // path traced, summed over the receivers
  double vpl_visible = 0.0;              // VPLs the receiver sees (a ray to the centroid)
  double vpl = 0.0, vsgl = 0.0;          // no visibility: brute force, one fitted VSGL
  double vpl_exposed = 0.0, vsgl_exposed = 0.0;  // the same without the buried triangles' VPLs
  double point = 0.0, averaged = 0.0, exact = 0.0;
  int receivers = 0;
};

std::pair<MannequinBounces, MannequinBounces> mannequin_bounces() {
  ChartSceneOptions options;
  options.size = 64;
  options.frame_count = 1;
  options.shared_dir = "/nonexistent";
  options.assets_dir = PROXYGI_SOURCE_DIR "/assets";
  options.rig_cache_dir = PROXYGI_TEST_OUTPUT_DIR "/bounce-excess-rigs";
  options.only = {"contact"};
  const std::pair<MannequinBounces, MannequinBounces> out;
  auto scenes = chart_scenes(options);
  EXPECT_TRUE(scenes.ok() && scenes->size() == 1u) << (scenes.ok() ? "" : scenes.message());
  if (!scenes.ok() || scenes->size() != 1u) return out;
  const ChartScene& chart = scenes->front();
  auto world = world::World::load(chart.scene, {.assets_dir = options.assets_dir, .load_rigs = true, .write_rig_cache = false});
  EXPECT_TRUE(world.ok()) << (world.ok() ? "" : world.message());
  if (!world.ok()) return out;
  world::WorldState state;
  EXPECT_TRUE((*world)->evaluate(scene::frame_time_s(chart.scene.output, chart.frames[0]), std::nullopt, state).ok());
  auto meshes = ref::world_meshes(**world, state, ref::make_scene_geometry(**world));
  EXPECT_TRUE(meshes.ok());
  if (!meshes.ok()) return out;

  auto environment = render::make_environment_lighting(chart.scene, 3);
  EXPECT_TRUE(environment.ok());
  if (!environment.ok()) return out;
  settings::RenderSettings settings = chart.scene.render;
  settings.sh_order = 3;
  settings.sh_window = false;
  const render::FrameTables tables = render::make_frame_tables(environment->lighting, settings);

  std::vector<sh::VirtualPointLight> lights;
  std::vector<glm::dvec3> faces;  // each light's triangle's geometric normal, on its normal's side
  glm::dvec3 low(1e9), high(-1e9);
  for (const ref::TriangleMesh& mesh : *meshes) {
    if (!mesh.character) continue;
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
      const glm::dvec3 p0(mesh.positions[mesh.indices[t]]), p1(mesh.positions[mesh.indices[t + 1]]),
          p2(mesh.positions[mesh.indices[t + 2]]);
      const glm::dvec3 face = glm::cross(p1 - p0, p2 - p0);
      const double area = 0.5 * glm::length(face);
      const glm::dvec3 summed = glm::dvec3(mesh.normals[mesh.indices[t]]) + glm::dvec3(mesh.normals[mesh.indices[t + 1]]) +
                                glm::dvec3(mesh.normals[mesh.indices[t + 2]]);
      if (!(area > 0.0) || glm::length(summed) <= 0.0) continue;
      const glm::dvec3 n = glm::normalize(summed);
      double basis[9];
      sh::evaluate_basis(3, n, std::span<double>(basis, 9));
      glm::dvec3 irradiance(0.0);
      for (int c = 0; c < 3; ++c)
        for (int k = 0; k < 9; ++k) irradiance[c] += basis[k] * double(tables.irradiance_order3[std::size_t(c)][std::size_t(k)]);
      const glm::dvec3 centroid = (p0 + p1 + p2) / 3.0;
      lights.push_back({centroid, n, glm::dvec3(mesh.material.albedo) * glm::max(irradiance, glm::dvec3(0.0)) * area});
      faces.push_back(glm::dot(face, n) >= 0.0 ? face / (2.0 * area) : -face / (2.0 * area));
      low = glm::min(low, centroid), high = glm::max(high, centroid);
    }
  }
  EXPECT_GT(lights.size(), 1000u);
  const glm::dvec3 origin = lights.front().position;
  sh::VsglSums sums;
  for (const sh::VirtualPointLight& light : lights) sh::add_light(sums, light, origin);
  const std::optional<sh::Vsgl> vsgl = sh::fit_vsgl(sums, origin);
  EXPECT_TRUE(vsgl.has_value());

  auto scene = ref::EmbreeScene::build(std::move(*meshes));
  EXPECT_TRUE(scene.ok());
  if (!scene.ok() || !vsgl) return out;
  const ref::EnvironmentLight light = ref::EnvironmentLight::spherical_harmonics(environment->lighting);
  ref::PathTracerSettings with_settings, without_settings;
  with_settings.unshadowed_character_senders = true;
  without_settings.character_senders = false;
  const ref::PathTracer with(*scene, light, light, with_settings), without(*scene, light, light, without_settings);

  // Receivers: ground points 0.3–1 m from the body's axis (not under a sole), and points on the
  // mannequin itself (every 97th triangle's centroid: its self-bounce).
  struct Receiver {
    glm::dvec3 position, normal, geometric_normal;
    bool character;
  };
  std::vector<Receiver> receivers;
  const glm::dvec3 axis = 0.5 * (low + high);
  for (double radius : {0.3, 0.45, 0.7, 1.0})
    for (int k = 0; k < 8; ++k) {
      const double angle = 2.0 * kPi * (k + 0.5) / 8.0;
      const glm::dvec3 p(axis.x + radius * std::cos(angle), 0.0, axis.z + radius * std::sin(angle));
      if (!scene->occluded(glm::vec3(p) + glm::vec3(0, 1e-3f, 0), glm::vec3(kUp), 0.05f)) receivers.push_back({p, kUp, kUp, false});
    }
  // The mannequin is one closed capsule or ellipsoid per body part, overlapping at the joints: a
  // triangle inside another part is buried (no camera or path sees it). Parity of the character
  // surfaces a ray along its normal crosses before it escapes: odd = inside another part.
  const auto buried = [&](std::size_t i) {
    glm::vec3 start = glm::vec3(lights[i].position + 1e-4 * faces[i]);
    const glm::vec3 direction = glm::vec3(faces[i]);
    int crossings = 0;
    for (int step = 0; step < 64; ++step) {
      const auto hit = scene->intersect(start, direction);
      if (!hit || !hit->character) break;
      ++crossings;
      start = hit->position + 1e-4f * direction;
    }
    return crossings % 2 == 1;
  };
  double buried_flux = 0.0, total_flux = 0.0;
  std::vector<bool> is_buried(lights.size());
  for (std::size_t i = 0; i < lights.size(); ++i) {
    is_buried[i] = buried(i);
    total_flux += sh::luminance(lights[i].flux);
    if (is_buried[i]) buried_flux += sh::luminance(lights[i].flux);
  }
  sh::VsglSums exposed_sums;
  for (std::size_t i = 0; i < lights.size(); ++i)
    if (!is_buried[i]) sh::add_light(exposed_sums, lights[i], origin);
  const std::optional<sh::Vsgl> exposed_vsgl = sh::fit_vsgl(exposed_sums, origin);
  EXPECT_TRUE(exposed_vsgl.has_value());
  if (!exposed_vsgl) return out;
  std::printf("mannequin: %zu of %zu triangles buried inside another part, %.1f %% of the VPLs' flux\n",
              std::size_t(std::count(is_buried.begin(), is_buried.end(), true)), lights.size(), 100.0 * buried_flux / total_flux);
  // The character receivers the chart scores: what the scene camera sees of it (every other pixel
  // of the 64² frame), at the hit's shading and geometric normals.
  for (int y = 0; y < 64; y += 2)
    for (int x = 0; x < 64; x += 2) {
      const scene::Ray ray = scene::ray_through_pixel(state.camera, 64, 64, float(x) + 0.5f, float(y) + 0.5f);
      const auto hit = scene->intersect(ray.origin, ray.direction);
      if (hit && hit->character)
        receivers.push_back({glm::dvec3(hit->position), glm::dvec3(hit->shading_normal), glm::dvec3(hit->geometric_normal), true});
    }

  MannequinBounces parts[2];
  double variance[2] = {0.0, 0.0};
  for (std::size_t r = 0; r < receivers.size(); ++r) {
    const Receiver& receiver = receivers[r];
    MannequinBounces& sum = parts[receiver.character ? 1 : 0];
    const glm::dvec3 p = receiver.position, n = receiver.normal;
    const glm::vec3 lifted = glm::vec3(p + 1e-4 * receiver.geometric_normal);
    ref::SurfaceHit hit;
    hit.position = glm::vec3(p);
    hit.geometric_normal = glm::vec3(receiver.geometric_normal);
    hit.shading_normal = glm::vec3(n);
    hit.albedo = glm::vec3(1.0f);
    hit.character = receiver.character;
    constexpr int kSamples = 4096;
    double traced = 0.0, square = 0.0;
    for (int i = 0; i < kSamples; ++i) {
      ref::SampleStream a(13, std::uint32_t(r), std::uint32_t(i)), b(13, std::uint32_t(r), std::uint32_t(i));
      const double x = kPi * sh::luminance(glm::dvec3(with.shade(hit, a).radiance - without.shade(hit, b).radiance));
      traced += x, square += x * x;
    }
    const double mean = traced / kSamples;
    sum.truth += mean;
    variance[receiver.character ? 1 : 0] += std::max(square / kSamples - mean * mean, 0.0) / kSamples;
    for (std::size_t i = 0; i < lights.size(); ++i) {
      const sh::VirtualPointLight& vpl = lights[i];
      const glm::dvec3 to = vpl.position - p;
      const double d = glm::length(to);
      if (d < 1e-6) continue;  // the receiver's own triangle
      const double seen = glm::dot(-to / d, vpl.normal), cosine = glm::dot(to / d, n);
      if (seen <= 0.0 || cosine <= 0.0) continue;
      const double e = sh::luminance(vpl.flux) * seen / kPi * cosine / (d * d);
      sum.vpl += e;
      if (!is_buried[i]) sum.vpl_exposed += e;
      if (!scene->occluded(lifted, glm::vec3(to / d), float(d * (1.0 - 2e-3)))) sum.vpl_visible += e;
    }
    sum.vsgl += sh::luminance(sh::vsgl_irradiance(*vsgl, p, n));
    sum.vsgl_exposed += sh::luminance(sh::vsgl_irradiance(*exposed_vsgl, p, n));
    const glm::vec3 position(p), normal(n);
    const std::vector<float> log_occlusion = render::accumulate_log_occlusion(tables, position, normal, state.spheres);
    const float dc = render::exponentiate_and_shade(tables, log_occlusion, settings.hyb_tau, position, normal).occlusion_dc;
    for (auto [op, total] : {std::pair{settings::IndirectOperator::point, &sum.point},
                             std::pair{settings::IndirectOperator::averaged, &sum.averaged},
                             std::pair{settings::IndirectOperator::exact, &sum.exact}})
      *total += sh::luminance(glm::dvec3(render::accumulate_indirect(tables, position, normal, state.spheres, dc, op).irradiance));
    ++sum.receivers;
  }
  for (int part = 0; part < 2; ++part) {
    MannequinBounces& b = parts[part];
    b.truth_error = std::sqrt(variance[part]);
    std::printf("mannequin, %d %s receivers, summed bounce over the path tracer's %.4f ± %.4f: visible VPLs %.3f, "
                "all VPLs %.3f, VSGL %.3f; without buried VPLs %.3f, VSGL %.3f; proxies point %.3f averaged %.3f exact %.3f\n",
                b.receivers, part == 0 ? "ground" : "character", b.truth, b.truth_error, b.vpl_visible / b.truth,
                b.vpl / b.truth, b.vsgl / b.truth, b.vpl_exposed / b.truth, b.vsgl_exposed / b.truth, b.point / b.truth, b.averaged / b.truth, b.exact / b.truth);
  }
  return {parts[0], parts[1]};
}

// The excess of the bounce chart, explained on its `contact` scene (measured, printed):
//  - ground 0.3–1 m from the body: VPLs the receiver sees 1.01 of the path tracer (so the VPLs'
//    flux and the reference agree), every VPL 1.74, VSGL 1.72: VSGL's excess on the ground is its
//    missing visibility: 31 % of the VPLs' flux comes from triangles buried inside another body
//    part (the mannequin's capsules overlap at the joints), and light shines through the body.
//    Without the buried VPLs: 1.29 (VPLs) and 1.19 (VSGL); the rest is light through the body.
//  - the character as the camera sees it: VSGL 4.1, every VPL 2.0, visible VPLs 0.84 (points
//    this close are a poor model of the neighbouring triangles); without the buried VPLs 1.29 and
//    VSGL 2.58 (the receivers lie inside the VSGL's Gaussian, ‖μ_v − p‖ ≲ σ_v); the proxies'
//    twins 0.95–1.05.
TEST(BounceExcess, TheMannequinOverTheGround) {
  const auto [ground, character] = mannequin_bounces();
  ASSERT_GT(ground.receivers, 16);
  ASSERT_GT(character.receivers, 30);
  ASSERT_GT(ground.truth, 0.0);
  ASSERT_GT(character.truth, 0.0);
  // The decomposition holds: with visibility, the VPLs give the path tracer's bounce on the
  // ground (4 standard errors of the reference, plus 2 % for the VPLs' centroids).
  EXPECT_NEAR(ground.vpl_visible, ground.truth, 4.0 * ground.truth_error + 0.02 * ground.truth);
  // Known, documented method errors (no visibility): every VPL and the VSGL fit of them are
  // more than 1.4× the bounce on the ground, and more than the visible VPLs on the character.
  EXPECT_GT(ground.vpl, 1.4 * ground.vpl_visible);
  EXPECT_GT(ground.vsgl, 1.4 * ground.truth);
  EXPECT_GT(character.vpl, 1.5 * character.vpl_visible);
  EXPECT_GT(character.vsgl, 1.5 * character.vpl);
  // Most of VSGL's excess on the ground is the buried triangles' light: without their VPLs it
  // drops by more than a quarter (measured 1.72 → 1.19 of the path tracer).
  EXPECT_LT(ground.vsgl_exposed, 0.75 * ground.vsgl);
  EXPECT_LT(ground.vpl_exposed, 0.8 * ground.vpl);
  // The proxies' twins are not too bright there: within 25 % of the path tracer on the camera's
  // character pixels, below it on the ground (their reach ends at η_indirect proxy radii).
  for (double proxy : {character.point, character.averaged, character.exact})
    EXPECT_NEAR(proxy, character.truth, 0.25 * character.truth);
  for (double proxy : {ground.point, ground.averaged, ground.exact}) EXPECT_LT(proxy, ground.truth);
}

}  // namespace
}  // namespace proxygi::study
