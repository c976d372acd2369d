#version 460
// Foundation test: writes element i = i * multiplier + offset into a storage buffer.
#extension GL_GOOGLE_include_directive : require
#include "shared/layouts.h"

layout(local_size_x = kTestPatternLocalSize) in;
layout(push_constant) uniform Push { TestPatternPush push; };
layout(std430, set = 0, binding = 0) writeonly buffer Output { uint values[]; };

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i < push.element_count) values[i] = i * push.multiplier + push.offset;
}
