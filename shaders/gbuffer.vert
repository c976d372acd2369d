#version 460
// G-buffer pass (frame step 2), vertex stage: pulls world-space positions and normals (the skin
// pass output, or static meshes uploaded in world space) by gl_VertexIndex.
#extension GL_GOOGLE_include_directive : require
#include "shared/layouts.h"

layout(std140, set = 0, binding = 0) uniform Frame { FrameConstants frame; };
layout(std430, set = 0, binding = 1) readonly buffer Positions { vec4 positions[]; };
layout(std430, set = 0, binding = 2) readonly buffer Normals { vec4 normals[]; };
layout(push_constant) uniform Push { GbufferPush push; };

layout(location = 0) out vec3 world_position;
layout(location = 1) out vec3 world_normal;

void main() {
  vec3 position = positions[gl_VertexIndex].xyz;
  world_position = position;
  world_normal = normals[gl_VertexIndex].xyz;
  gl_Position = frame.view_projection * vec4(position, 1.0);
}
