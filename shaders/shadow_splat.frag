#version 460
// Raster shadow splat (frame step 4), fragment stage: one fragment per (receiver, proxy) pair
// that passed the coverage oracle's depth test. Computes the same rotated log-occlusion vector
// as shadow_gather.comp (same table, tangent-plane rules and fade) and writes its coefficients
// [first_coefficient, first_coefficient + 4 · targets) to the colour targets, which blend
// additively: the targets hold f = Σ_i rot(O_log(s_i), d_i). CPU twin: render::accumulate_log_occlusion.
#extension GL_GOOGLE_include_directive : require
#include "frame_common.glsl"
#include "sh/sh_basis.glsl"
#include "shared/splat_layouts.h"

#define SH_COUNT (SH_ORDER * SH_ORDER)
#define SH_JOIN(a, b) a##b
#define SH_EXPAND_JOIN(a, b) SH_JOIN(a, b)
#define sh_eval_basis SH_EXPAND_JOIN(sh_eval_basis_, SH_ORDER)
#define TARGETS PROXYGI_SPLAT_TARGETS_PER_PASS(SH_ORDER)

// Depth and stencil are read only: the depth test may run before the shader even with discard.
layout(early_fragment_tests) in;
layout(std140, set = 0, binding = 0) uniform Frame { FrameConstants frame; };
layout(std430, set = 0, binding = 1) readonly buffer Receivers { Receiver receivers[]; };
layout(std430, set = 0, binding = 3) readonly buffer LogTable { float log_table[]; };
layout(push_constant) uniform Push { SplatPush push; };

layout(location = 0) flat in vec4 sphere;

layout(location = 0) out vec4 target0;
#if TARGETS > 1
layout(location = 1) out vec4 target1;
#endif
#if TARGETS > 2
layout(location = 2) out vec4 target2;
#endif
#if TARGETS > 3
layout(location = 3) out vec4 target3;
#endif
#if TARGETS > 4
layout(location = 4) out vec4 target4;
#endif
#if TARGETS > 5
layout(location = 5) out vec4 target5;
#endif
#if TARGETS > 6
layout(location = 6) out vec4 target6;
#endif
#if TARGETS > 7
layout(location = 7) out vec4 target7;
#endif

float f[SH_COUNT];

float coefficient(uint i) { return i < uint(SH_COUNT) ? f[min(i, uint(SH_COUNT - 1))] : 0.0; }
vec4 target_value(uint target) {
  uint first = push.first_coefficient + 4u * target;
  return vec4(coefficient(first), coefficient(first + 1u), coefficient(first + 2u), coefficient(first + 3u));
}

void main() {
  uvec2 pixel = uvec2(gl_FragCoord.xy);
  Receiver r = receivers[pixel.y * frame.sizes.z + pixel.x];
  vec3 p = r.position_depth.xyz;
  // The depth test kept receivers in front of the back surface; drop those outside η·r.
  vec3 offset = sphere.xyz - p;
  float reach = frame.shadow.x * sphere.w;
  if (r.position_depth.w <= 0.0 || dot(offset, offset) >= reach * reach) discard;
  vec3 direction;
  float sine;
  if (!proxy_seen_from(p, r.normal.xyz, sphere.xyz, sphere.w, direction, sine) || sine <= 1.0 / frame.shadow.x)
    discard;
  float basis[SH_COUNT];
  sh_eval_basis(direction, basis);
  int rows = int(frame.shadow.w);
  for (int l = 0; l < SH_ORDER; ++l) {
    float zonal;
    ZONAL_LOOKUP(log_table, rows, SH_ORDER, sine, l, zonal);
    float scaled = zonal_scale(l) * zonal;
    for (int m = -l; m <= l; ++m) f[l * (l + 1) + m] = scaled * basis[l * (l + 1) + m];
  }
  target0 = target_value(0u);
#if TARGETS > 1
  target1 = target_value(1u);
#endif
#if TARGETS > 2
  target2 = target_value(2u);
#endif
#if TARGETS > 3
  target3 = target_value(3u);
#endif
#if TARGETS > 4
  target4 = target_value(4u);
#endif
#if TARGETS > 5
  target5 = target_value(5u);
#endif
#if TARGETS > 6
  target6 = target_value(6u);
#endif
#if TARGETS > 7
  target7 = target_value(7u);
#endif
}
