// Issue 20, "the unexplained excess", on a real character: the bounce chart's `contact` scene
// computed by the path tracer's bounce reference (unshadowed senders, and the physical one with
// shadowed senders) and by the methods' CPU twins (the proxies with both sender lights), with the VPLs split by visibility and by whether their triangle is buried inside
// another body part (bounce_excess_test.cpp has the one-sphere case with a closed answer).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <optional>
#include <tuple>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "ref/embree_scene.h"
#include "ref/path_tracer.h"
#include "ref/sender_exposure.h"
#include "ref/scene_geometry.h"
#include "render/environment_lighting.h"
#include "render/frame_tables.h"
#include "render/shading.h"
#include "scene/camera.h"
#include "scene/scene.h"
#include "sh/basis.h"
#include "sh/vsgl.h"
#include "study/chart_scenes.h"
#include "world/world.h"

namespace proxygi::study {
namespace {

constexpr double kPi = 3.14159265358979323846;
const glm::dvec3 kUp(0.0, 1.0, 0.0);

// The chart's `contact` scene at its first chart frame: the mannequin as the path tracer sees it
// (triangles, unshadowed senders) and as the methods see it (its rig's proxies; its triangles
// as VPLs, as vsgl_lights.comp forms them), under the default sky's unwindowed order-3 SH (the
// same lighting for all, so only the senders' geometry differs), at ground points around it.
struct MannequinBounces {
  double truth = 0.0, truth_error = 0.0;  // path traced, summed over the receivers
  double vpl_visible = 0.0;              // VPLs the receiver sees (a ray to the centroid)
  double vpl = 0.0, vsgl = 0.0;          // no visibility: brute force, one fitted VSGL
  double vpl_exposed = 0.0, vsgl_exposed = 0.0;  // the same without the buried triangles' VPLs
  // Each VPL weighted by its triangle's sender exposure (ref/sender_exposure.h), as the renderer's
  // vsgl_lights.comp does: brute force and one fitted VSGL.
  double vpl_weighted = 0.0, vsgl_weighted = 0.0;
  double point = 0.0, averaged = 0.0, exact = 0.0;  // the proxies with the paper's unshadowed senders
  // The physical one-bounce reference (senders lit with shadows: the ground and the body block
  // their light) and the proxies with their default sender light, the light above the receiver's
  // plane (render.mask_sender_light, sh/sender_light.h).
  double shadowed_truth = 0.0, shadowed_truth_error = 0.0;
  double masked_point = 0.0, masked_averaged = 0.0, masked_exact = 0.0;
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
  settings.mask_sender_light = false;
  const render::FrameTables tables = render::make_frame_tables(environment->lighting, settings);
  settings.mask_sender_light = true;
  const render::FrameTables masked_tables = render::make_frame_tables(environment->lighting, settings);

  // Sender exposures of the model in its rest pose, per primitive in pose order (world_meshes
  // lists the character's primitives in that order).
  EXPECT_EQ((*world)->instances().size(), 1u);
  const auto started = std::chrono::steady_clock::now();
  auto exposure = ref::rest_pose_sender_exposure((*world)->instances().front().model->character);
  EXPECT_TRUE(exposure.ok()) << (exposure.ok() ? "" : exposure.message());
  if (!exposure.ok()) return out;
  std::printf("mannequin: sender exposure (%d directions per vertex) in %.0f ms\n", ref::kSenderExposureDirections,
              std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - started).count());
  std::vector<sh::VirtualPointLight> lights, weighted_lights;
  std::vector<glm::dvec3> faces;  // each light's triangle's geometric normal, on its normal's side
  glm::dvec3 low(1e9), high(-1e9);
  std::size_t primitive = 0;
  for (const ref::TriangleMesh& mesh : *meshes) {
    if (!mesh.character) continue;
    EXPECT_LT(primitive, exposure->size());
    if (primitive >= exposure->size() || (*exposure)[primitive].size() != mesh.positions.size()) return out;
    const std::vector<float>& exposed = (*exposure)[primitive++];
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
      glm::dvec3 x[3], n[3], e;
      for (int k = 0; k < 3; ++k) {
        const std::uint32_t v = mesh.indices[t + std::size_t(k)];
        x[k] = glm::dvec3(mesh.positions[v]), n[k] = glm::dvec3(mesh.normals[v]), e[k] = exposed[v];
      }
      const glm::dvec3 face = glm::cross(x[1] - x[0], x[2] - x[0]);
      const double area = 0.5 * glm::length(face);
      if (!(area > 0.0) || glm::length(n[0] + n[1] + n[2]) <= 0.0) continue;
      const glm::dvec3 albedo(mesh.material.albedo);
      lights.push_back(sh::triangle_light(x, n, albedo, tables.irradiance_order3));
      weighted_lights.push_back(sh::triangle_light(x, n, albedo, tables.irradiance_order3, e));
      const glm::dvec3& centroid = lights.back().position;
      faces.push_back(glm::dot(face, lights.back().normal) >= 0.0 ? face / (2.0 * area) : -face / (2.0 * area));
      low = glm::min(low, centroid), high = glm::max(high, centroid);
    }
  }
  EXPECT_GT(lights.size(), 1000u);
  const glm::dvec3 origin = lights.front().position;
  sh::VsglSums sums;
  for (const sh::VirtualPointLight& light : lights) sh::add_light(sums, light, origin);
  const std::optional<sh::Vsgl> vsgl = sh::fit_vsgl(sums, origin);
  EXPECT_TRUE(vsgl.has_value());
  sh::VsglSums weighted_sums;
  for (const sh::VirtualPointLight& light : weighted_lights) sh::add_light(weighted_sums, light, origin);
  const std::optional<sh::Vsgl> weighted_vsgl = sh::fit_vsgl(weighted_sums, origin);
  EXPECT_TRUE(weighted_vsgl.has_value());

  auto scene = ref::EmbreeScene::build(std::move(*meshes));
  EXPECT_TRUE(scene.ok());
  if (!scene.ok() || !vsgl || !weighted_vsgl) return out;
  const ref::EnvironmentLight light = ref::EnvironmentLight::spherical_harmonics(environment->lighting);
  ref::PathTracerSettings with_settings, without_settings, shadowed_settings;
  with_settings.unshadowed_character_senders = true;
  without_settings.character_senders = false;
  const ref::PathTracer with(*scene, light, light, with_settings), without(*scene, light, light, without_settings);
  const ref::PathTracer shadowed(*scene, light, light, shadowed_settings);

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
  double buried_flux = 0.0, total_flux = 0.0, weighted_flux = 0.0, buried_weighted_flux = 0.0;
  std::vector<bool> is_buried(lights.size());
  for (std::size_t i = 0; i < lights.size(); ++i) {
    is_buried[i] = buried(i);
    total_flux += sh::luminance(lights[i].flux);
    weighted_flux += sh::luminance(weighted_lights[i].flux);
    if (is_buried[i]) buried_flux += sh::luminance(lights[i].flux), buried_weighted_flux += sh::luminance(weighted_lights[i].flux);
  }
  sh::VsglSums exposed_sums;
  for (std::size_t i = 0; i < lights.size(); ++i)
    if (!is_buried[i]) sh::add_light(exposed_sums, lights[i], origin);
  const std::optional<sh::Vsgl> exposed_vsgl = sh::fit_vsgl(exposed_sums, origin);
  EXPECT_TRUE(exposed_vsgl.has_value());
  if (!exposed_vsgl) return out;
  std::printf("mannequin: %zu of %zu triangles buried inside another part, %.1f %% of the VPLs' flux; weighted by "
              "exposure the VPLs keep %.1f %% of it, the buried ones %.2f %% of theirs\n",
              std::size_t(std::count(is_buried.begin(), is_buried.end(), true)), lights.size(), 100.0 * buried_flux / total_flux,
              100.0 * weighted_flux / total_flux, 100.0 * buried_weighted_flux / std::max(buried_flux, 1e-30));
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
  double variance[2] = {0.0, 0.0}, shadowed_variance[2] = {0.0, 0.0};
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
    double traced = 0.0, square = 0.0, shadowed_traced = 0.0, shadowed_square = 0.0;
    for (int i = 0; i < kSamples; ++i) {
      ref::SampleStream a(13, std::uint32_t(r), std::uint32_t(i)), b(13, std::uint32_t(r), std::uint32_t(i)),
          c(13, std::uint32_t(r), std::uint32_t(i));
      const glm::vec3 alone = without.shade(hit, b).radiance;
      const double x = kPi * sh::luminance(glm::dvec3(with.shade(hit, a).radiance - alone));
      const double y = kPi * sh::luminance(glm::dvec3(shadowed.shade(hit, c).radiance - alone));
      traced += x, square += x * x;
      shadowed_traced += y, shadowed_square += y * y;
    }
    const double mean = traced / kSamples, shadowed_mean = shadowed_traced / kSamples;
    sum.truth += mean;
    sum.shadowed_truth += shadowed_mean;
    variance[receiver.character ? 1 : 0] += std::max(square / kSamples - mean * mean, 0.0) / kSamples;
    shadowed_variance[receiver.character ? 1 : 0] +=
        std::max(shadowed_square / kSamples - shadowed_mean * shadowed_mean, 0.0) / kSamples;
    for (std::size_t i = 0; i < lights.size(); ++i) {
      const sh::VirtualPointLight& vpl = lights[i];
      const glm::dvec3 to = vpl.position - p;
      const double d = glm::length(to);
      if (d < 1e-6) continue;  // the receiver's own triangle
      const double seen = glm::dot(-to / d, vpl.normal), cosine = glm::dot(to / d, n);
      if (seen <= 0.0 || cosine <= 0.0) continue;
      const double e = sh::luminance(vpl.flux) * seen / kPi * cosine / (d * d);
      sum.vpl += e;
      sum.vpl_weighted += sh::luminance(weighted_lights[i].flux) * seen / kPi * cosine / (d * d);
      if (!is_buried[i]) sum.vpl_exposed += e;
      if (!scene->occluded(lifted, glm::vec3(to / d), float(d * (1.0 - 2e-3)))) sum.vpl_visible += e;
    }
    sum.vsgl += sh::luminance(sh::vsgl_irradiance(*vsgl, p, n));
    sum.vsgl_exposed += sh::luminance(sh::vsgl_irradiance(*exposed_vsgl, p, n));
    sum.vsgl_weighted += sh::luminance(sh::vsgl_irradiance(*weighted_vsgl, p, n));
    const glm::vec3 position(p), normal(n);
    const std::vector<float> log_occlusion = render::accumulate_log_occlusion(tables, position, normal, state.spheres);
    const float dc = render::exponentiate_and_shade(tables, log_occlusion, settings.hyb_tau, position, normal).occlusion_dc;
    for (auto [op, total, masked] : {std::tuple{settings::IndirectOperator::point, &sum.point, &sum.masked_point},
                                     std::tuple{settings::IndirectOperator::averaged, &sum.averaged, &sum.masked_averaged},
                                     std::tuple{settings::IndirectOperator::exact, &sum.exact, &sum.masked_exact}}) {
      *total += sh::luminance(glm::dvec3(render::accumulate_indirect(tables, position, normal, state.spheres, dc, op).irradiance));
      *masked +=
          sh::luminance(glm::dvec3(render::accumulate_indirect(masked_tables, position, normal, state.spheres, dc, op).irradiance));
    }
    ++sum.receivers;
  }
  for (int part = 0; part < 2; ++part) {
    MannequinBounces& b = parts[part];
    b.truth_error = std::sqrt(variance[part]);
    b.shadowed_truth_error = std::sqrt(shadowed_variance[part]);
    std::printf("mannequin, %d %s receivers, summed bounce over the path tracer's %.4f ± %.4f: visible VPLs %.3f, "
                "all VPLs %.3f, VSGL %.3f; without buried VPLs %.3f, VSGL %.3f; weighted by exposure VPLs %.3f, VSGL %.3f; "
                "proxies point %.3f averaged %.3f exact %.3f\n",
                b.receivers, part == 0 ? "ground" : "character", b.truth, b.truth_error, b.vpl_visible / b.truth,
                b.vpl / b.truth, b.vsgl / b.truth, b.vpl_exposed / b.truth, b.vsgl_exposed / b.truth, b.vpl_weighted / b.truth,
                b.vsgl_weighted / b.truth, b.point / b.truth, b.averaged / b.truth, b.exact / b.truth);
    std::printf("mannequin, %d %s receivers, shadowed senders: path tracer %.4f ± %.4f (%.3f of unshadowed); proxies with "
                "the masked sender light point %.3f averaged %.3f exact %.3f of it, unmasked averaged %.3f of it\n",
                b.receivers, part == 0 ? "ground" : "character", b.shadowed_truth, b.shadowed_truth_error,
                b.shadowed_truth / b.truth, b.masked_point / b.shadowed_truth, b.masked_averaged / b.shadowed_truth,
                b.masked_exact / b.shadowed_truth, b.averaged / b.shadowed_truth);
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
//  - the fix (ref/sender_exposure.h, applied by vsgl_lights.comp): each VPL weighted by its
//    triangle's exposure keeps 54 % of the flux (the buried triangles 7 % of theirs); VSGL then
//    gives 0.92 of the path tracer on the ground (the weighted VPLs 0.99) and 1.95 on the character
//    (from 4.06).
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
  // The renderer's fix, sender exposure: the weighted VPLs give the path tracer's bounce on the
  // ground (as the visible ones do), and VSGL of them is within 10 % of it (measured 0.92), half
  // of its excess on the character gone (4.06 → 1.95).
  EXPECT_NEAR(ground.vpl_weighted, ground.truth, 4.0 * ground.truth_error + 0.02 * ground.truth);
  EXPECT_NEAR(ground.vsgl_weighted, ground.truth, 0.1 * ground.truth);
  EXPECT_LT(character.vsgl_weighted, 0.5 * character.vsgl);
  // The proxies' twins are not too bright there: within 25 % of the path tracer on the camera's
  // character pixels, below it on the ground (their reach ends at η_indirect proxy radii).
  for (double proxy : {character.point, character.averaged, character.exact})
    EXPECT_NEAR(proxy, character.truth, 0.25 * character.truth);
  for (double proxy : {ground.point, ground.averaged, ground.exact}) EXPECT_LT(proxy, ground.truth);
  // Against the physical one-bounce reference (senders shadowed by the ground and the body:
  // measured 0.58 of the unshadowed bounce on the ground, 0.33 on the character), the paper's
  // unshadowed proxies are 3× too bright on the character (measured 2.96); the default sender light
  // (the light above the receiver's plane) cuts the absolute error there to a third (measured
  // 0.33 of the truth, the plane blocks more than the finite body part does), and on the ground
  // it stays below the truth (measured 0.44; unmasked 0.85).
  EXPECT_LT(ground.shadowed_truth, 0.8 * ground.truth);
  EXPECT_LT(character.shadowed_truth, 0.5 * character.truth);
  EXPECT_GT(character.averaged, 2.0 * character.shadowed_truth);
  EXPECT_LT(std::abs(character.masked_averaged - character.shadowed_truth),
            0.5 * std::abs(character.averaged - character.shadowed_truth));
  EXPECT_LT(std::abs(character.masked_exact - character.shadowed_truth),
            0.5 * std::abs(character.exact - character.shadowed_truth));
  for (double proxy : {ground.masked_point, ground.masked_averaged, ground.masked_exact})
    EXPECT_LT(proxy, ground.shadowed_truth);
}

}  // namespace
}  // namespace proxygi::study
