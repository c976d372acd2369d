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
layout(std140, set = 0, binding = kSplatBindFrame) uniform Frame { FrameConstants frame; };
layout(std430, set = 0, binding = kSplatBindReceivers) readonly buffer Receivers { Receiver receivers[]; };
layout(std430, set = 0, binding = kSplatBindLogTable) readonly buffer LogTable { float log_table[]; };
layout(push_constant) uniform Push { SplatPush push; };

layout(location = 0) flat in vec4 sphere;
layout(location = 1) flat in float weight;

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

// Coefficient i, 0 past the last one (the padding of the last target). Called with constant
// indices only, so f stays in registers (a dynamically indexed array spills on lavapipe).
#define COEFFICIENT(i) ((i) < SH_COUNT ? f[min((i), SH_COUNT - 1)] : 0.0)
#define TARGET_VALUE(first) \
  vec4(COEFFICIENT(first), COEFFICIENT((first) + 1), COEFFICIENT((first) + 2), COEFFICIENT((first) + 3))

// Writes the pass's targets from coefficient `first` (a constant) on.
#if TARGETS > 7
#define WRITE_TARGETS(first) target0 = TARGET_VALUE(first); target1 = TARGET_VALUE((first) + 4); \
  target2 = TARGET_VALUE((first) + 8); target3 = TARGET_VALUE((first) + 12); target4 = TARGET_VALUE((first) + 16); \
  target5 = TARGET_VALUE((first) + 20); target6 = TARGET_VALUE((first) + 24); target7 = TARGET_VALUE((first) + 28);
#elif TARGETS > 6
#define WRITE_TARGETS(first) target0 = TARGET_VALUE(first); target1 = TARGET_VALUE((first) + 4); \
  target2 = TARGET_VALUE((first) + 8); target3 = TARGET_VALUE((first) + 12); target4 = TARGET_VALUE((first) + 16); \
  target5 = TARGET_VALUE((first) + 20); target6 = TARGET_VALUE((first) + 24);
#elif TARGETS > 5
#define WRITE_TARGETS(first) target0 = TARGET_VALUE(first); target1 = TARGET_VALUE((first) + 4); \
  target2 = TARGET_VALUE((first) + 8); target3 = TARGET_VALUE((first) + 12); target4 = TARGET_VALUE((first) + 16); \
  target5 = TARGET_VALUE((first) + 20);
#elif TARGETS > 4
#define WRITE_TARGETS(first) target0 = TARGET_VALUE(first); target1 = TARGET_VALUE((first) + 4); \
  target2 = TARGET_VALUE((first) + 8); target3 = TARGET_VALUE((first) + 12); target4 = TARGET_VALUE((first) + 16);
#elif TARGETS > 3
#define WRITE_TARGETS(first) target0 = TARGET_VALUE(first); target1 = TARGET_VALUE((first) + 4); \
  target2 = TARGET_VALUE((first) + 8); target3 = TARGET_VALUE((first) + 12);
#elif TARGETS > 2
#define WRITE_TARGETS(first) target0 = TARGET_VALUE(first); target1 = TARGET_VALUE((first) + 4); \
  target2 = TARGET_VALUE((first) + 8);
#elif TARGETS > 1
#define WRITE_TARGETS(first) target0 = TARGET_VALUE(first); target1 = TARGET_VALUE((first) + 4);
#else
#define WRITE_TARGETS(first) target0 = TARGET_VALUE(first);
#endif

void main() {
  uvec2 pixel = uvec2(gl_FragCoord.xy);
  Receiver r = receivers[pixel.y * frame.receiver_width + pixel.x];
  vec3 p = r.position_depth.xyz;
  // The depth test kept receivers in front of the back surface; drop those outside η·r.
  vec3 offset = sphere.xyz - p;
  float reach = frame.shadow_eta * sphere.w;
  if (r.position_depth.w <= 0.0 || dot(offset, offset) >= reach * reach) discard;
  vec3 direction;
  float sine;
  if (!proxy_seen_from(p, r.normal.xyz, sphere.xyz, sphere.w, direction, sine) || sine <= 1.0 / frame.shadow_eta)
    discard;
  float basis[SH_COUNT];
  sh_eval_basis(direction, basis);
  int rows = int(frame.log_table_rows);
  for (int l = 0; l < SH_ORDER; ++l) {
    float zonal;
    ZONAL_LOOKUP(log_table, rows, SH_ORDER, sine, l, zonal);
    float scaled = zonal_scale(l) * zonal * weight;
    for (int m = -l; m <= l; ++m) f[l * (l + 1) + m] = scaled * basis[l * (l + 1) + m];
  }
#if PROXYGI_SPLAT_PASSES(SH_ORDER) == 1
  WRITE_TARGETS(0)
#else  // two passes (order 6)
  if (push.first_coefficient == 0u) {
    WRITE_TARGETS(0)
  } else {
    WRITE_TARGETS(4 * TARGETS)
  }
#endif
}
