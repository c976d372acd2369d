#version 460
// Exponentiation and direct shading (frame step 5): O_p = exp*(f) by HYB (DC isolation, OL on
// f̂/2^s, blended toward OL(f̂/2^(s+1))² near the next squaring count so O_p is continuous in f,
// s squarings; sh/exponential.h), then E_direct = O_p · LH(N) per colour from the LH cube maps (the
// ground-lit set for receivers above the ground, lighting_cube_set).
// E is clamped to [0, E_unshadowed] per channel (ringing, notes F4).
// Output per receiver: (E_r, E_g, E_b, (O_p)_0). CPU twin: render::exponentiate_and_shade.
// STATIC_TRANSFER 1 (ratio) or 2 (l1), render.static_transfer: receivers on a PRT triangle take
// the static-transfer E of static_transfer.glsl instead (CPU twin: prt::static_receiver_direct),
// other receivers in the static meshes' visibility grid (O_p ∗ V_s) · LH(N) (static geometry
// shadowing the characters; CPU twin: prt::character_receiver_direct).
#extension GL_GOOGLE_include_directive : require
#include "frame_common.glsl"
#include "sh/sh_product.glsl"

#define SH_COUNT (SH_ORDER * SH_ORDER)
#ifndef STATIC_TRANSFER
#define STATIC_TRANSFER 0
#endif
#define SH_JOIN(a, b) a##b
#define SH_EXPAND_JOIN(a, b) SH_JOIN(a, b)
#define sh_square SH_EXPAND_JOIN(sh_square_, SH_ORDER)

layout(local_size_x = kFrameLocalSize, local_size_y = kFrameLocalSize) in;
layout(std140, set = 0, binding = kExponentiateBindFrame) uniform Frame { FrameConstants frame; };
layout(std430, set = 0, binding = kExponentiateBindReceivers) readonly buffer Receivers { Receiver receivers[]; };
layout(std430, set = 0, binding = kExponentiateBindLogOcclusion) readonly buffer LogOcclusion { float log_occlusion[]; };
layout(std430, set = 0, binding = kExponentiateBindOptimalLinear) readonly buffer OptimalLinear { vec2 optimal_linear[]; };  // (a, b) rows
layout(std430, set = 0, binding = kExponentiateBindLightingCube) readonly buffer LightingCube { float lighting_cube[]; };   // r, g, b cubes, twice
layout(std430, set = 0, binding = kExponentiateBindDirect) writeonly buffer Direct { vec4 direct[]; };
#if STATIC_TRANSFER
layout(std430, set = 0, binding = kExponentiateBindStaticPositions) readonly buffer StaticPositions { vec4 static_positions[]; };
layout(std430, set = 0, binding = kExponentiateBindStaticTriangles) readonly buffer StaticTriangles { StaticTriangle static_triangles[]; };
layout(std430, set = 0, binding = kExponentiateBindStaticGrid) readonly buffer StaticGrid { uint static_grid[]; };
layout(std430, set = 0, binding = kExponentiateBindStaticRecords) readonly buffer StaticRecords { float static_records[]; };
layout(std430, set = 0, binding = kExponentiateBindStaticVisibility) readonly buffer StaticVisibility { float static_visibility[]; };
#endif

vec2 optimal_linear_lookup(float norm) {
  int rows = int(frame.optimal_linear_rows);
  float position = clamp(norm / frame.optimal_linear_max_norm, 0.0, 1.0) * float(rows - 1);
  int row = min(int(position), rows - 2);
  float t = position - float(row);
  return optimal_linear[row] + t * (optimal_linear[row + 1] - optimal_linear[row]);
}

#include "lighting_cube.glsl"
#if STATIC_TRANSFER
#include "static_transfer.glsl"
#endif

void main() {
  uvec2 receiver = gl_GlobalInvocationID.xy;
  uvec2 receiver_size = uvec2(frame.receiver_width, frame.receiver_height);
  if (any(greaterThanEqual(receiver, receiver_size))) return;
  uint index = receiver.y * receiver_size.x + receiver.x;
  Receiver r = receivers[index];
  if (r.position_depth.w <= 0.0) {
    direct[index] = vec4(0.0, 0.0, 0.0, kSqrtFourPi);
    return;
  }
  float f[SH_COUNT];
  float norm_squared = 0.0;
  for (int i = 0; i < SH_COUNT; ++i) {
    f[i] = log_occlusion[index * SH_COUNT + i];
    if (i > 0) norm_squared += f[i] * f[i];
  }
#if STATIC_TRANSFER
  StaticHit hit;
  bool on_static = find_static_hit(r.position_depth.xyz, r.normal.xyz, hit);
#endif
  if (norm_squared == 0.0 && f[0] == 0.0) {
    // No proxy reaches this receiver: O_p = a(0)·1, so only LH's DC coefficient matters.
    float g0 = optimal_linear_lookup(0.0).x * kSqrtFourPi;
#if STATIC_TRANSFER
    if (on_static) {
      float g_static[SH_COUNT];
      g_static[0] = g0;
      for (int i = 1; i < SH_COUNT; ++i) g_static[i] = 0.0;
      direct[index] = vec4(shade_static_direct(hit, r.normal.xyz, g_static), g0);
      return;
    }
    float v_static[SH_COUNT];
    if (sample_static_visibility(r.position_depth.xyz, v_static)) {
      float g_open[SH_COUNT];
      g_open[0] = g0;
      for (int i = 1; i < SH_COUNT; ++i) g_open[i] = 0.0;
      direct[index] = vec4(shade_character_direct(r.position_depth.xyz, r.normal.xyz, g_open, v_static), g0);
      return;
    }
#endif
    int set = lighting_cube_set(r.position_depth.xyz);
    vec3 unshadowed = vec3(lighting_lookup_dc(set, r.normal.xyz), lighting_lookup_dc(set + 1, r.normal.xyz),
                           lighting_lookup_dc(set + 2, r.normal.xyz));
    direct[index] = vec4(max(g0 * unshadowed, vec3(0.0)), g0);
    return;
  }
  float dc = exp(0.28209479177387814 * f[0]);
  float norm = sqrt(norm_squared);
  float tau = frame.hybrid_tau;
  int squarings = 0;
  float scale = 1.0;
  while (norm * scale > tau && squarings < 16) {
    scale *= 0.5;
    ++squarings;
  }
  vec2 ab = optimal_linear_lookup(norm * scale);
  float g[SH_COUNT];
  g[0] = ab.x * kSqrtFourPi;
  for (int i = 1; i < SH_COUNT; ++i) g[i] = ab.y * scale * f[i];
  // Continuity (sh::hybrid_blend): toward OL(f̂/2^(s+1))², which the s squarings below turn into
  // HYB with s + 1 at x = τ, what the norms above τ·2^s use.
  float blend_t = clamp((norm * scale / tau - kHybridBlendStart) / (1.0 - kHybridBlendStart), 0.0, 1.0);
  if (blend_t > 0.0) {
    float blend = blend_t * blend_t * (3.0 - 2.0 * blend_t);
    vec2 half_ab = optimal_linear_lookup(0.5 * norm * scale);
    float h[SH_COUNT];
    h[0] = half_ab.x * kSqrtFourPi;
    for (int i = 1; i < SH_COUNT; ++i) h[i] = half_ab.y * 0.5 * scale * f[i];
    float squared[SH_COUNT];
    sh_square(h, squared);
    for (int i = 0; i < SH_COUNT; ++i) g[i] += blend * (squared[i] - g[i]);
  }
  for (int k = 0; k < squarings; ++k) {
    float squared[SH_COUNT];
    sh_square(g, squared);
    g = squared;
  }
  for (int i = 0; i < SH_COUNT; ++i) g[i] *= dc;
#if STATIC_TRANSFER
  if (on_static) {
    direct[index] = vec4(shade_static_direct(hit, r.normal.xyz, g), g[0]);
    return;
  }
  float v_static[SH_COUNT];
  if (sample_static_visibility(r.position_depth.xyz, v_static)) {
    direct[index] = vec4(shade_character_direct(r.position_depth.xyz, r.normal.xyz, g, v_static), g[0]);
    return;
  }
#endif

  vec3 irradiance;
  int set = lighting_cube_set(r.position_depth.xyz);
  for (int channel = 0; channel < 3; ++channel) {
    float lh[SH_COUNT];
    lighting_lookup(set + channel, r.normal.xyz, lh);
    float sum = 0.0;
    for (int i = 0; i < SH_COUNT; ++i) sum += g[i] * lh[i];
    // F4: band-limited visibility rings (overshoots 1 beside large, overlapping caps), so bound
    // E by [0, unshadowed]: a blocker can only take light away. Unshadowed = O ≡ 1 = √4π y_0.
    irradiance[channel] = clamp(sum, 0.0, max(kSqrtFourPi * lh[0], 0.0));
  }
  direct[index] = vec4(irradiance, g[0]);
}
