#pragma once
#include <array>
// CPU twins of the frame's per-receiver formulas. Each function mirrors one shader, formula for
// formula and in the same float order where it matters; GPU tests compare them at sample pixels.
//   accumulate_log_occlusion  ↔ shadow_gather.comp   f = Σ_i rot(O_log(s_i), d_i)
//   exponentiate_and_shade    ↔ exponentiate.comp    O_p = HYB(f), E_direct = O_p · LH(N)
//   accumulate_indirect       ↔ indirect.comp        E_ind = ξ_p Σ_i (a_i/π) max(I_i · H(N), 0) per operator
//   select_receiver           ↔ receivers.comp       which display texel a receiver stands for
//   upsample                  ↔ upsample_composite.comp  eq. 11 with the all-weights-vanish fallback
//   tonemap                   ↔ upsample_composite.comp  (with the sRGB encoding)
// Irradiance E = ∫ L max(N·s, 0) ds (not divided by π); the receiver's radiance is albedo/π · E.
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "render/frame_tables.h"
#include "settings/render_settings.h"

namespace proxygi::render {

// One streamed proxy. `weight` scales everything the sphere adds to a receiver's sums (its log
// occlusion, its bounce light and its solid angle ω_i; AO: the factor (1 − a_i)^weight), so a
// cross-fade between two levels of detail A and B streams A with weight 1 − t and B with t and
// the log sum is exactly (1 − t) Σ_A + t Σ_B (proxies/lod.h). 1 everywhere without proxy_lod:
// × 1 is exact, so frames are what they were before weights existed.
struct Sphere {
  glm::vec3 center{0.0f};  // world space, m
  float radius = 0.0f;     // m
  glm::vec3 albedo{0.0f};  // linear rgb
  float weight = 1.0f;     // in [0, 1]
};

// Log occlusion at receiver (p, N) summed over every proxy (order = tables' order; n² floats).
// Proxies with s ≤ 1/η_shadow contribute 0 through the faded table (the coverage oracle).
std::vector<float> accumulate_log_occlusion(const FrameTables& tables, const glm::vec3& p, const glm::vec3& normal,
                                            std::span<const Sphere> spheres);

struct DirectResult {
  glm::vec3 irradiance{0.0f};   // shadowed direct E, rgb
  float occlusion_dc = 0.0f;    // (O_p)_0, the DC of the environment visibility
  int squarings = 0;            // HYB squarings used
};
// LH(N) from the cube set of receiver point p (lighting_cube_set: ground-lit above the ground).
// E is clamped per channel to [0, E_unshadowed = √4π LH_0]: SH ringing must never brighten (F4).
DirectResult exponentiate_and_shade(const FrameTables& tables, std::span<const float> log_occlusion, float tau,
                                    const glm::vec3& p, const glm::vec3& normal);

// LH(N) of one channel from the cube map, bilinear within the face that N hits (clamped at the
// face edges). out holds n² values.
void lookup_lighting_cube(const sh::LightingCubeMap& cube, const glm::vec3& normal, std::span<float> out);

// The proxies' sender light for a receiver with unit normal N: L̃_N per channel (order 3) from
// tables.sender_light_cube, bilinear like lookup_lighting_cube (sh/sender_light.h).
std::array<std::array<float, 9>, 3> sender_light(const FrameTables& tables, const glm::vec3& normal);

// How a proxy's radiance I_i is formed from the order-3 sender light L̃_N (paper §5 with L̃;
// sh/indirect.h, sh/sender_light.h).
// Each is its own compiled variant of indirect.comp ("indirect.comp:<name>").
//   point     eq. 13: I_i = κ_i V_i, κ_i = L̃ · y(−d̂_i)           (radiance at the proxy centre's back)
//   averaged  eq. 15: I_i = κ_i V_i, κ_i = rot(D(s_i), d̂_i) · L̃   (D by the paper's polynomial fit)
//   exact     eq. 17: I_i = R⁻¹ M(s_i) R L̃                        (M tabulated, render/exact_indirect.h)
// point and averaged shade max(κ_i, 0) max(V_i · H(N), 0); exact shades max(I_i · H(N), 0).

struct IndirectResult {
  glm::vec3 irradiance{0.0f};   // normalized indirect E, rgb
  float summed_solid_angle = 0; // ω_p (after the influence fade)
};
IndirectResult accumulate_indirect(const FrameTables& tables, const glm::vec3& p, const glm::vec3& normal,
                                   std::span<const Sphere> spheres, float occlusion_dc,
                                   settings::IndirectOperator op = settings::IndirectOperator::averaged);

// The display texel that receiver (rx, ry) stands for (receivers.comp): the center of its k×k
// block, or, when that is background (eye depth ≤ 0), the first covered texel of the block in
// row-major order; {-1, -1} when the whole block is background. `depth(x, y)` reads the
// G-buffer's eye depth.
template <class DepthAt>
glm::ivec2 select_receiver(int rx, int ry, int k, int width, int height, DepthAt depth) {
  const glm::ivec2 origin(rx * k, ry * k);
  const glm::ivec2 center = glm::min(origin + glm::ivec2(k / 2), glm::ivec2(width - 1, height - 1));
  if (depth(center.x, center.y) > 0.0f) return center;
  for (int y = 0; y < k; ++y)
    for (int x = 0; x < k; ++x) {
      const glm::ivec2 texel = origin + glm::ivec2(x, y);
      if (texel.x < width && texel.y < height && depth(texel.x, texel.y) > 0.0f) return texel;
    }
  return {-1, -1};
}

// Bilateral upsampling weights of paper eq. 11 for one display pixel from its 2×2 receivers:
// w = w^b · max(N·N_i, 0)^32 · ε/(ε + |N·(P_i − P)|/z), where P, N, z are the pixel's world
// position, normal and eye depth and P_i the receiver's position: the depth term measures the tap's
// distance to the pixel's tangent plane relative to eye depth (F8: scale-invariant, so a ground
// plane at a grazing angle interpolates bilinearly); ε (bilateral_depth_epsilon) is dimensionless.
struct UpsampleTap {
  glm::vec3 value{0.0f};
  glm::vec3 position{0.0f};      // world space, m
  float depth = 0.0f;            // eye depth; 0 = no receiver there
  glm::vec3 normal{0.0f, 1.0f, 0.0f};
  float bilinear_weight = 0.0f;  // w^b
};
// The composite's gather footprint of display pixel (x, y) at receiver scale k over a grid of
// `receivers` (receiver i's center at (i + 0.5) k display pixels): the four receivers of the
// bilinear cell, clamped at the edges, in the order (0,0), (1,0), (0,1), (1,1), and their w^b.
struct UpsampleFootprint {
  std::array<glm::ivec2, 4> source{};
  std::array<float, 4> bilinear_weight{};
};
UpsampleFootprint upsample_footprint(int x, int y, int k, glm::ivec2 receivers);
// Returns the interpolated value; when every weight vanishes (< 1e-6 of the bilinear total),
// falls back to interpolating by w^b × the tangent-plane term alone, and only when that is 0 too
// to the valid tap with the closest depth.
glm::vec3 upsample(std::span<const UpsampleTap, 4> taps, const glm::vec3& position, float depth, const glm::vec3& normal,
                   settings::Upsampling mode, float depth_epsilon);
// The same, also saying how well the best tap matches the pixel's surface: the largest eq. 11
// factor max(N·N_i, 0)^32 · ε/(ε + |N·(P_i − P)|/z) over the taps with a receiver (bilateral;
// 1 for bilinear, 0 with no receiver). The stability study counts pixels whose best factor is
// under kUpsampleMatchFactor as "no-match" (notes F8/F9: the value comes from other surfaces).
inline constexpr float kUpsampleMatchFactor = 0.5f;
struct Upsampled {
  glm::vec3 value{0.0f};
  float best_match = 1.0f;
};
Upsampled upsample_with_match(std::span<const UpsampleTap, 4> taps, const glm::vec3& position, float depth, const glm::vec3& normal,
                              settings::Upsampling mode, float depth_epsilon);

// Linear radiance × exposure → display-referred linear [0, 1] (before the sRGB encoding).
glm::vec3 tonemap(const glm::vec3& radiance, float exposure, settings::Tonemap curve);

}  // namespace proxygi::render
