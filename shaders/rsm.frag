#version 460
// Sun map of the VSGL sun variant, fragment stage: the nearest sender surface along the sun ray
// of each texel (depth test): its world position (w = light + 1), unit normal, and reflected
// flux Φ R = ρ E_s a_t (0 where n·s ≤ 0: the sun does not light the back of the normal).
// CPU twin: sh::rsm_texel_light (sh/vsgl_sun.h).
#extension GL_GOOGLE_include_directive : require
#include "shared/layouts.h"

layout(std140, set = 0, binding = kRsmBindFrame) uniform Frame { FrameConstants frame; };
layout(push_constant) uniform Push { RsmPush push; };

layout(location = 0) in vec3 world_position;
layout(location = 1) in vec3 world_normal;
layout(location = 0) out vec4 out_position;
layout(location = 1) out vec4 out_normal;
layout(location = 2) out vec4 out_flux;

void main() {
  float len = length(world_normal);
  vec3 normal = len > 0.0 ? world_normal / len : frame.rsm_toward_sun.xyz;
  bool lit = dot(normal, frame.rsm_toward_sun.xyz) > 0.0;
  out_position = vec4(world_position, float(push.light + 1u));
  out_normal = vec4(normal, 0.0);
  out_flux = vec4(lit ? push.base_color.rgb * frame.rsm_texel_flux.rgb : vec3(0.0), 0.0);
}
