#version 460
// Raster shadow splat, resolve: copies the blended colour targets (coefficient i in target i / 4,
// channel i % 4; shared/splat_layouts.h) into the receiver-major log-occlusion buffer that
// exponentiate.comp reads (receiver index × n² + i), the gather's output layout.
#extension GL_GOOGLE_include_directive : require
#include "shared/layouts.h"
#include "shared/splat_layouts.h"

#define SH_COUNT (SH_ORDER * SH_ORDER)
#define IMAGES PROXYGI_SPLAT_TARGETS(SH_ORDER)  // a last, all-padding target is not read

layout(local_size_x = kFrameLocalSize, local_size_y = kFrameLocalSize) in;
layout(std140, set = 0, binding = kResolveBindFrame) uniform Frame { FrameConstants frame; };
layout(std430, set = 0, binding = kResolveBindLogOcclusion) writeonly buffer LogOcclusion { float log_occlusion[]; };
layout(set = 0, binding = kResolveBindFirstTarget + 0u, rgba32f) uniform readonly image2D target0;
#if IMAGES > 1
layout(set = 0, binding = kResolveBindFirstTarget + 1u, rgba32f) uniform readonly image2D target1;
#endif
#if IMAGES > 2
layout(set = 0, binding = kResolveBindFirstTarget + 2u, rgba32f) uniform readonly image2D target2;
#endif
#if IMAGES > 3
layout(set = 0, binding = kResolveBindFirstTarget + 3u, rgba32f) uniform readonly image2D target3;
#endif
#if IMAGES > 4
layout(set = 0, binding = kResolveBindFirstTarget + 4u, rgba32f) uniform readonly image2D target4;
#endif
#if IMAGES > 5
layout(set = 0, binding = kResolveBindFirstTarget + 5u, rgba32f) uniform readonly image2D target5;
#endif
#if IMAGES > 6
layout(set = 0, binding = kResolveBindFirstTarget + 6u, rgba32f) uniform readonly image2D target6;
#endif
#if IMAGES > 7
layout(set = 0, binding = kResolveBindFirstTarget + 7u, rgba32f) uniform readonly image2D target7;
#endif
#if IMAGES > 8
layout(set = 0, binding = kResolveBindFirstTarget + 8u, rgba32f) uniform readonly image2D target8;
#endif
#if IMAGES > 9
layout(set = 0, binding = kResolveBindFirstTarget + 9u, rgba32f) uniform readonly image2D target9;
#endif

uint base;
ivec2 texel;
#define RESOLVE(j)                                                       \
  {                                                                      \
    vec4 value = imageLoad(target##j, texel);                            \
    for (uint c = 0u; c < 4u; ++c)                                       \
      if (4u * uint(j) + c < uint(SH_COUNT)) log_occlusion[base + 4u * uint(j) + c] = value[c]; \
  }

void main() {
  uvec2 receiver = gl_GlobalInvocationID.xy;
  if (any(greaterThanEqual(receiver, uvec2(frame.receiver_width, frame.receiver_height)))) return;
  texel = ivec2(receiver);
  base = (receiver.y * frame.receiver_width + receiver.x) * uint(SH_COUNT);
  RESOLVE(0)
#if IMAGES > 1
  RESOLVE(1)
#endif
#if IMAGES > 2
  RESOLVE(2)
#endif
#if IMAGES > 3
  RESOLVE(3)
#endif
#if IMAGES > 4
  RESOLVE(4)
#endif
#if IMAGES > 5
  RESOLVE(5)
#endif
#if IMAGES > 6
  RESOLVE(6)
#endif
#if IMAGES > 7
  RESOLVE(7)
#endif
#if IMAGES > 8
  RESOLVE(8)
#endif
#if IMAGES > 9
  RESOLVE(9)
#endif
}
