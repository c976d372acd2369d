#version 460
// Sun map sums of the VSGL sun variant (render.vsgl_sun): one dispatch per light; workgroup g
// sums the texels [g, g + 1) × kVsglGroupSize × kRsmTexelsPerInvocation (row-major) whose
// position.w is light + 1 as diffuse VPLs (sh::add_vsgl_sun), serially per invocation then in a
// fixed tree (deterministic), into VsglPartial push.partial_offset + g, positions relative to
// the group's rows' centre at mid depth. vsgl_lights.comp's fit adds them to the light's sums.
// CPU twin: sh::add_vsgl_sun (src/sh/vsgl_sun.h).
#extension GL_GOOGLE_include_directive : require
#include "shared/layouts.h"

layout(local_size_x = kVsglGroupSize) in;
layout(std140, set = 0, binding = kRsmSumsBindFrame) uniform Frame { FrameConstants frame; };
layout(set = 0, binding = kRsmSumsBindPosition, rgba32f) uniform readonly image2D position_image;
layout(set = 0, binding = kRsmSumsBindNormal, rgba32f) uniform readonly image2D normal_image;
layout(set = 0, binding = kRsmSumsBindFlux, rgba32f) uniform readonly image2D flux_image;
layout(std430, set = 0, binding = kRsmSumsBindPartials) buffer Partials { VsglPartial partials[]; };
layout(push_constant) uniform Push { RsmSumsPush push; };

shared vec4 shared_a[kVsglGroupSize];  // (w, w ξ̄)
shared vec4 shared_b[kVsglGroupSize];  // (w (x − o), w ‖x − o‖²)
shared vec4 shared_c[kVsglGroupSize];  // (flux, 0)

const vec3 kLuminance = vec3(0.2126, 0.7152, 0.0722);
const uint kGroupTexels = kVsglGroupSize * kRsmTexelsPerInvocation;

void main() {
  uint local = gl_LocalInvocationID.x;
  uint first = gl_WorkGroupID.x * kGroupTexels;
  // Origin: the middle of the group's texel rows, halfway through the map's depth.
  float middle_row = (float(first) + 0.5 * float(kGroupTexels)) / float(kRsmSize);
  vec4 clip = vec4(0.0, 2.0 * middle_row / float(kRsmSize) - 1.0, 0.5, 1.0);
  vec4 world = frame.rsm_inverse_view_projection * clip;
  vec3 origin = world.xyz / world.w;
  float tag = float(push.light + 1u);
  vec4 a = vec4(0.0), b = vec4(0.0), c = vec4(0.0);
  for (uint j = 0u; j < kRsmTexelsPerInvocation; ++j) {
    uint t = first + j * kVsglGroupSize + local;
    ivec2 texel = ivec2(int(t % kRsmSize), int(t / kRsmSize));
    vec4 position = imageLoad(position_image, texel);
    if (position.w != tag) continue;
    vec3 normal = imageLoad(normal_image, texel).xyz;
    vec3 flux = imageLoad(flux_image, texel).rgb;
    float w = dot(flux, kLuminance);
    vec3 relative = position.xyz - origin;
    a += vec4(w, w * (kVsglDiffuseSharpness / (kVsglDiffuseSharpness + 1.0)) * normal);
    b += vec4(w * relative, w * dot(relative, relative));
    c += vec4(flux, 0.0);
  }
  shared_a[local] = a;
  shared_b[local] = b;
  shared_c[local] = c;
  barrier();
  for (uint stride = kVsglGroupSize / 2u; stride > 0u; stride /= 2u) {
    if (local < stride) {
      shared_a[local] += shared_a[local + stride];
      shared_b[local] += shared_b[local + stride];
      shared_c[local] += shared_c[local + stride];
    }
    barrier();
  }
  if (local == 0u) {
    VsglPartial partial;
    partial.origin_light = vec4(origin, float(push.light));
    partial.weight_axis = shared_a[0];
    partial.position_square = shared_b[0];
    partial.flux = shared_c[0];
    partials[push.partial_offset + gl_WorkGroupID.x] = partial;
  }
}
