#version 460
// Receivers pass (frame step 3): one receiver per k×k block of display pixels, the block's
// center texel, or the first covered texel of the block when the center is background.
// CPU twin: render::select_receiver (src/render/shading.h).
#extension GL_GOOGLE_include_directive : require
#include "frame_common.glsl"

layout(local_size_x = kFrameLocalSize, local_size_y = kFrameLocalSize) in;
layout(std140, set = 0, binding = kReceiversBindFrame) uniform Frame { FrameConstants frame; };
layout(set = 0, binding = kReceiversBindPositionDepth, rgba32f) uniform readonly image2D position_depth_image;
layout(set = 0, binding = kReceiversBindNormal, rgba32f) uniform readonly image2D normal_image;
layout(std430, set = 0, binding = kReceiversBindReceivers) writeonly buffer Receivers { Receiver receivers[]; };

void main() {
  uvec2 receiver = gl_GlobalInvocationID.xy;
  uvec2 receiver_size = uvec2(frame.receiver_width, frame.receiver_height);
  if (any(greaterThanEqual(receiver, receiver_size))) return;
  uint k = frame.receiver_scale;
  ivec2 display_size = ivec2(uvec2(frame.display_width, frame.display_height));
  ivec2 origin = ivec2(receiver * k);
  ivec2 center = min(origin + ivec2(k / 2u), display_size - 1);
  ivec2 chosen = center;
  vec4 position_depth = imageLoad(position_depth_image, center);
  if (position_depth.w <= 0.0) {
    for (uint y = 0u; y < k && position_depth.w <= 0.0; ++y)
      for (uint x = 0u; x < k && position_depth.w <= 0.0; ++x) {
        ivec2 texel = origin + ivec2(x, y);
        if (any(greaterThanEqual(texel, display_size))) continue;
        vec4 candidate = imageLoad(position_depth_image, texel);
        if (candidate.w > 0.0) {
          position_depth = candidate;
          chosen = texel;
        }
      }
  }
  Receiver result;
  result.position_depth = position_depth.w > 0.0 ? position_depth : vec4(0.0);
  result.normal = position_depth.w > 0.0 ? vec4(imageLoad(normal_image, chosen).xyz, 0.0) : vec4(0.0, 1.0, 0.0, 0.0);
  receivers[receiver.y * receiver_size.x + receiver.x] = result;
}
