#version 460
// Supersampling resolve (render.antialiasing, after step 8): each display pixel is the box mean of
// its f × f shading samples, the box the path-traced reference integrates a pixel over.
// HDR out: the mean linear radiance. 8-bit out: the mean of the samples' displayed colours (their
// sRGB bytes decoded to linear, averaged, encoded again): the tonemap ran per sample, as without
// anti-aliasing, so one bright sample cannot swamp an edge (a resolve after the tonemap).
// The debug views resolve the same way. CPU twin: render::resolve_supersampled.
#extension GL_GOOGLE_include_directive : require
#include "shared/layouts.h"

layout(local_size_x = kFrameLocalSize, local_size_y = kFrameLocalSize) in;
layout(std430, set = 0, binding = kSupersampleBindSampleHdr) readonly buffer SampleHdr { vec4 sample_hdr[]; };
layout(std430, set = 0, binding = kSupersampleBindSampleLdr) readonly buffer SampleLdr { uint sample_ldr[]; };
layout(std430, set = 0, binding = kSupersampleBindHdr) writeonly buffer Hdr { vec4 hdr[]; };
layout(std430, set = 0, binding = kSupersampleBindLdr) writeonly buffer Ldr { uint ldr[]; };
layout(push_constant) uniform Push { SupersamplePush push; };

float srgb_to_linear(float value) {
  return value <= 0.04045 ? value / 12.92 : pow((value + 0.055) / 1.055, 2.4);
}

float linear_to_srgb(float value) {
  return value <= 0.0031308 ? 12.92 * value : 1.055 * pow(value, 1.0 / 2.4) - 0.055;
}

void main() {
  uvec2 pixel = gl_GlobalInvocationID.xy;
  if (any(greaterThanEqual(pixel, uvec2(push.width, push.height)))) return;
  uint f = push.factor;
  uint samples_per_row = push.width * f;
  vec4 radiance = vec4(0.0);
  vec3 display = vec3(0.0);
  for (uint y = 0u; y < f; ++y) {
    for (uint x = 0u; x < f; ++x) {
      uint i = (pixel.y * f + y) * samples_per_row + pixel.x * f + x;
      radiance += sample_hdr[i];
      uint packed = sample_ldr[i];  // RGBA byte order (the composite writes it unswapped here)
      vec3 encoded = vec3(float(packed & 255u), float((packed >> 8) & 255u), float((packed >> 16) & 255u)) / 255.0;
      display += vec3(srgb_to_linear(encoded.r), srgb_to_linear(encoded.g), srgb_to_linear(encoded.b));
    }
  }
  float count = float(f * f);
  uint index = pixel.y * push.width + pixel.x;
  hdr[index] = radiance / count;
  display /= count;
  uvec3 encoded = uvec3(clamp(vec3(linear_to_srgb(display.r), linear_to_srgb(display.g), linear_to_srgb(display.b)), 0.0, 1.0) * 255.0 + 0.5);
  if (push.ldr_swap_red_blue != 0u) encoded = encoded.bgr;
  ldr[index] = encoded.r | (encoded.g << 8) | (encoded.b << 16) | (255u << 24);
}
