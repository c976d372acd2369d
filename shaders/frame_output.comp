#version 460
// Frame output (step 9, image outputs): the packed RGBA8 frame resampled to the caller's image
// size and channel order, as packed texels a buffer-to-image copy lands unchanged. At the same
// size each texel is the frame's (exact); otherwise bilinear, as vkCmdBlitImage's LINEAR filter:
// source position (x + 0.5)·source/target − 0.5, edges clamped, weights on encoded values for a
// UNORM target and on decoded ones for an sRGB target. vkCmdBlitImage itself runs per texel on
// the CPU on lavapipe (8× a copy), the reason this pass exists. CPU twin: image::resample_rgba8.
#extension GL_GOOGLE_include_directive : require
#include "shared/layouts.h"
#include "shared/frame_output.h"

layout(local_size_x = kFrameLocalSize, local_size_y = kFrameLocalSize) in;
layout(std430, set = 0, binding = kOutputBindLdr) readonly buffer Ldr { uint ldr[]; };
layout(std430, set = 0, binding = kOutputBindPixels) writeonly buffer Pixels { uint pixels[]; };
layout(push_constant) uniform Push { FrameOutputPush push; };

vec4 decoded(uint x, uint y) {
  const vec4 c = unpackUnorm4x8(ldr[y * push.source_width + x]);
  if (push.linear_filtering == 0u) return c;
  const vec3 low = c.rgb / 12.92, high = pow((c.rgb + 0.055) / 1.055, vec3(2.4));
  return vec4(mix(high, low, lessThanEqual(c.rgb, vec3(0.04045))), c.a);
}

uint encoded(vec4 c) {
  if (push.linear_filtering != 0u) {
    const vec3 l = clamp(c.rgb, 0.0, 1.0);
    const vec3 low = l * 12.92, high = 1.055 * pow(l, vec3(1.0 / 2.4)) - 0.055;
    c.rgb = mix(high, low, lessThanEqual(l, vec3(0.0031308)));
  }
  return packUnorm4x8(c);
}

void main() {
  const uvec2 p = gl_GlobalInvocationID.xy;
  if (p.x >= push.target_width || p.y >= push.target_height) return;
  uint texel;
  if (push.source_width == push.target_width && push.source_height == push.target_height) {
    texel = ldr[p.y * push.source_width + p.x];
  } else {
    const vec2 scale = vec2(push.source_width, push.source_height) / vec2(push.target_width, push.target_height);
    const vec2 s = max((vec2(p) + 0.5) * scale - 0.5, vec2(0.0));
    const uvec2 last = uvec2(push.source_width - 1u, push.source_height - 1u);
    const uvec2 a = min(uvec2(s), last), b = min(a + 1u, last);
    const vec2 f = s - vec2(a);
    const vec4 top = mix(decoded(a.x, a.y), decoded(b.x, a.y), f.x);
    const vec4 bottom = mix(decoded(a.x, b.y), decoded(b.x, b.y), f.x);
    texel = encoded(mix(top, bottom, f.y));
  }
  if (push.swap_red_blue != 0u) texel = (texel & 0xff00ff00u) | ((texel & 0xffu) << 16) | ((texel >> 16) & 0xffu);
  pixels[p.y * push.target_width + p.x] = texel;
}
