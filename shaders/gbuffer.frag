#version 460
// G-buffer pass (frame step 2), fragment stage: world position + eye depth, unit normal facing
// the viewer (surfaces are treated as double-sided), linear albedo = base color factor × base
// color texture (an sRGB image, decoded to linear by the sampler before filtering; CPU twin:
// render/texture_sampling.h) in the BASE_COLOR_TEXTURE variants, the factor alone otherwise. With VERTEX_IRRADIANCE
// (the vertex method) the second target holds the interpolated vertex irradiance E instead of
// the normal (upsample_composite reads it there when frame.composite_mode == kCompositeDisplayIrradiance).
#extension GL_GOOGLE_include_directive : require
#include "shared/layouts.h"

layout(std140, set = 0, binding = kGbufferBindFrame) uniform Frame { FrameConstants frame; };
#ifdef BASE_COLOR_TEXTURE
layout(set = 0, binding = kGbufferBindBaseColorTexture) uniform sampler2D base_color_texture;
#endif
layout(push_constant) uniform Push { GbufferPush push; };

layout(location = 0) in vec3 world_position;
layout(location = 1) in vec3 world_normal;
#ifdef VERTEX_IRRADIANCE
layout(location = 2) in vec3 vertex_irradiance;
#endif
layout(location = 3) in vec2 texture_coordinate;
layout(location = 0) out vec4 out_position_depth;
layout(location = 1) out vec4 out_normal;
layout(location = 2) out vec4 out_albedo;

void main() {
  vec3 normal = normalize(world_normal);
  vec3 to_eye = frame.eye_position.xyz - world_position;
  if (dot(normal, to_eye) < 0.0) normal = -normal;
  float eye_depth = dot(world_position - frame.eye_position.xyz, frame.eye_forward.xyz);
  out_position_depth = vec4(world_position, max(eye_depth, 1e-6));
#ifdef VERTEX_IRRADIANCE
  out_normal = vec4(max(vertex_irradiance, vec3(0.0)), 1.0);
#else
  out_normal = vec4(normal, 1.0);
#endif
#ifdef BASE_COLOR_TEXTURE
  out_albedo = vec4(push.base_color.rgb * texture(base_color_texture, texture_coordinate).rgb, 1.0);
#else
  out_albedo = vec4(push.base_color.rgb, 1.0);
#endif
}
