#version 460
// Sun map of the VSGL sun variant (render.vsgl_sun), vertex stage: pulls the senders' world
// positions and normals by gl_VertexIndex and projects them orthographically from the sun
// (frame.rsm_view_projection, sh::RsmView). CPU twin: sh::rsm_texel_light (sh/vsgl_sun.h).
#extension GL_GOOGLE_include_directive : require
#include "shared/layouts.h"

layout(std140, set = 0, binding = kRsmBindFrame) uniform Frame { FrameConstants frame; };
layout(std430, set = 0, binding = kRsmBindPositions) readonly buffer Positions { vec4 positions[]; };
layout(std430, set = 0, binding = kRsmBindNormals) readonly buffer Normals { vec4 normals[]; };

layout(location = 0) out vec3 world_position;
layout(location = 1) out vec3 world_normal;

void main() {
  world_position = positions[gl_VertexIndex].xyz;
  world_normal = normals[gl_VertexIndex].xyz;
  gl_Position = frame.rsm_view_projection * vec4(world_position, 1.0);
}
