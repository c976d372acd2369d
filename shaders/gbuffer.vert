#version 460
// G-buffer pass (frame step 2), vertex stage: pulls world-space positions and normals (the skin
// pass output, or static meshes uploaded in world space) and the static TEXCOORD_0 by
// gl_VertexIndex; applies the material's uv transform (affine, so it commutes with the
// rasterizer's interpolation). Compiled a second time with VERTEX_IRRADIANCE for the vertex
// method: it also passes on the vertex's shaded irradiance (E_direct + E_indirect of receiver
// receiver_offset + vertex) for interpolation.
#extension GL_GOOGLE_include_directive : require
#include "shared/layouts.h"

layout(std140, set = 0, binding = kGbufferBindFrame) uniform Frame { FrameConstants frame; };
layout(std430, set = 0, binding = kGbufferBindPositions) readonly buffer Positions { vec4 positions[]; };
layout(std430, set = 0, binding = kGbufferBindNormals) readonly buffer Normals { vec4 normals[]; };
layout(std430, set = 0, binding = kGbufferBindUvs) readonly buffer Uvs { vec2 uvs[]; };
layout(push_constant) uniform Push { GbufferPush push; };

layout(location = 0) out vec3 world_position;
layout(location = 1) out vec3 world_normal;
layout(location = 3) out vec2 texture_coordinate;
#ifdef VERTEX_IRRADIANCE
layout(std430, set = 0, binding = kGbufferBindShaded) readonly buffer Shaded { vec4 shaded[]; };
layout(location = 2) out vec3 vertex_irradiance;
#endif

void main() {
  vec3 position = positions[gl_VertexIndex].xyz;
  world_position = position;
  world_normal = normals[gl_VertexIndex].xyz;
  vec3 uv = vec3(push.has_uvs != 0u ? uvs[gl_VertexIndex] : vec2(0.0), 1.0);
  texture_coordinate = vec2(dot(push.uv_transform_u.xyz, uv), dot(push.uv_transform_v.xyz, uv));
#ifdef VERTEX_IRRADIANCE
  vertex_irradiance = shaded[push.receiver_offset + uint(gl_VertexIndex)].rgb;
#endif
  gl_Position = frame.view_projection * vec4(position, 1.0);
}
