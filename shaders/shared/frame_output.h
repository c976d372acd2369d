// frame_output.comp's push constants and bindings, shared by C++ and GLSL like layouts.h
// (include layouts.h first: its uint and PROXYGI_CONST).
#ifndef PROXYGI_SHADERS_SHARED_FRAME_OUTPUT_H
#define PROXYGI_SHADERS_SHARED_FRAME_OUTPUT_H

#ifdef __cplusplus
namespace proxygi::gpu_layout {
#endif

PROXYGI_CONST(uint, kOutputBindLdr, 0u);     // the frame: packed RGBA8, sRGB-encoded, source size
PROXYGI_CONST(uint, kOutputBindPixels, 1u);  // out: packed 8-bit texels of the caller's image, its size

struct FrameOutputPush {
  uint source_width, source_height;  // the frame
  uint target_width, target_height;  // the caller's image
  uint swap_red_blue;                // 1: B8G8R8A8 target
  uint linear_filtering;             // 1: sRGB target: filter decoded values (as a blit into it would)
  uint padding0, padding1;
};

#ifdef __cplusplus
static_assert(sizeof(FrameOutputPush) == 32);
}  // namespace proxygi::gpu_layout
#endif
#endif
