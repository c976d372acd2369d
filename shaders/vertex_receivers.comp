#version 460
// Vertex receivers (the vertex method's frame step 3): every vertex of one draw becomes a
// receiver, p = its world position, N = its normalized world normal, w = 1 (a valid receiver;
// the vertex method upsamples nothing, so no eye depth is needed). Receivers of padding and
// gaps stay zero (w = 0: no receiver) from the fill before the first dispatch.
// CPU twin: render::vertex_receiver (src/render/baselines.h).
#extension GL_GOOGLE_include_directive : require
#include "shared/layouts.h"

layout(local_size_x = 64) in;
layout(std430, set = 0, binding = kVertexReceiversBindPositions) readonly buffer Positions { vec4 positions[]; };
layout(std430, set = 0, binding = kVertexReceiversBindNormals) readonly buffer Normals { vec4 normals[]; };
layout(std430, set = 0, binding = kVertexReceiversBindReceivers) writeonly buffer Receivers { Receiver receivers[]; };
layout(push_constant) uniform Push { VertexReceiversPush push; };

void main() {
  uint vertex = gl_GlobalInvocationID.x;
  if (vertex >= push.vertex_count) return;
  vec3 normal = normals[vertex].xyz;
  float length_ = length(normal);
  Receiver result;
  result.position_depth = vec4(positions[vertex].xyz, 1.0);
  result.normal = vec4(length_ > 0.0 ? normal / length_ : vec3(0.0, 1.0, 0.0), 0.0);
  receivers[push.receiver_offset + vertex] = result;
}
