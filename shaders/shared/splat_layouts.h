// Layout of the raster shadow splat (shadow_splat.vert/.frag, receiver_depth.frag,
// splat_resolve.comp; C++ side src/gpu/shadow_splat_pass.h), shared by C++ and GLSL like layouts.h.
// The n² log-occlusion coefficients are blended into RGBA32F colour targets, four coefficients a
// target (coefficient i in target i / 4, channel i % 4). At most kSplatMaxTargetsPerPass targets
// are bound per draw (lavapipe and most GPUs allow 8 colour attachments); order 6 (36
// coefficients, 9 targets) therefore splats in two passes of 5 targets, the last one half unused.
#ifndef PROXYGI_SHADERS_SHARED_SPLAT_LAYOUTS_H
#define PROXYGI_SHADERS_SHARED_SPLAT_LAYOUTS_H

// Preprocessor forms, so GLSL can declare exactly the outputs and images a pass uses.
#define PROXYGI_SPLAT_MAX_TARGETS_PER_PASS 8
#define PROXYGI_SPLAT_TARGETS(order) (((order) * (order) + 3) / 4)
#define PROXYGI_SPLAT_PASSES(order) \
  ((PROXYGI_SPLAT_TARGETS(order) + PROXYGI_SPLAT_MAX_TARGETS_PER_PASS - 1) / PROXYGI_SPLAT_MAX_TARGETS_PER_PASS)
#define PROXYGI_SPLAT_TARGETS_PER_PASS(order) \
  ((PROXYGI_SPLAT_TARGETS(order) + PROXYGI_SPLAT_PASSES(order) - 1) / PROXYGI_SPLAT_PASSES(order))

#ifdef __cplusplus
#include <cstdint>
namespace proxygi::gpu_layout {
using uint = std::uint32_t;  // as in layouts.h
#endif

// Push constants of shadow_splat.frag: the pass's first coefficient (0, or 4 × targets per pass).
struct SplatPush {
  uint first_coefficient;
  uint padding0;
  uint padding1;
  uint padding2;
};

#ifdef __cplusplus
static_assert(sizeof(SplatPush) == 16);
}  // namespace proxygi::gpu_layout
#endif

#endif
