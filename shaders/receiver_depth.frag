#version 460
// Raster shadow splat, depth set-up: writes each receiver's depth (its world point p projected
// with the frame's view-projection, framebuffer depth 0 near .. 1 far) into the receiver-size
// depth buffer the splat tests against. Pixels without a receiver get 1 (far): no back face is
// farther, so nothing is splatted there.
#extension GL_GOOGLE_include_directive : require
#include "shared/layouts.h"

layout(std140, set = 0, binding = kSplatBindFrame) uniform Frame { FrameConstants frame; };
layout(std430, set = 0, binding = kSplatBindReceivers) readonly buffer Receivers { Receiver receivers[]; };

void main() {
  uvec2 pixel = uvec2(gl_FragCoord.xy);
  Receiver r = receivers[pixel.y * frame.receiver_width + pixel.x];
  float depth = 1.0;
  if (r.position_depth.w > 0.0) {
    vec4 clip = frame.view_projection * vec4(r.position_depth.xyz, 1.0);
    depth = clamp(clip.z / clip.w, 0.0, 1.0);
  }
  gl_FragDepth = depth;
}
