#version 460
// Upsampling (frame step 7): display-resolution irradiance E = E_direct + E_indirect from the
// 2×2 surrounding receivers with the joint-bilateral weights of eq. 11 (bilinear × depth ×
// normal^32), or plain bilinear; where every weight vanishes, the valid tap nearest in depth.
// CPU twin: render::upsample.
#extension GL_GOOGLE_include_directive : require
#include "frame_common.glsl"

layout(local_size_x = kFrameLocalSize, local_size_y = kFrameLocalSize) in;
layout(std140, set = 0, binding = 0) uniform Frame { FrameConstants frame; };
layout(set = 0, binding = 1, rgba32f) uniform readonly image2D position_depth_image;
layout(set = 0, binding = 2, rgba32f) uniform readonly image2D normal_image;
layout(std430, set = 0, binding = 3) readonly buffer Receivers { Receiver receivers[]; };
layout(std430, set = 0, binding = 4) readonly buffer Shaded { vec4 shaded[]; };  // (E, eye depth)
layout(std430, set = 0, binding = 5) writeonly buffer Irradiance { vec4 irradiance[]; };

void main() {
  uvec2 pixel = gl_GlobalInvocationID.xy;
  uvec2 display_size = frame.sizes.xy;
  if (any(greaterThanEqual(pixel, display_size))) return;
  uint out_index = pixel.y * display_size.x + pixel.x;
  vec4 position_depth = imageLoad(position_depth_image, ivec2(pixel));
  if (position_depth.w <= 0.0) {
    irradiance[out_index] = vec4(0.0);
    return;
  }
  vec3 normal = imageLoad(normal_image, ivec2(pixel)).xyz;
  float depth = position_depth.w;
  ivec2 receiver_size = ivec2(frame.sizes.zw);
  float k = float(frame.counts.y);
  // Receiver (i, j) sits at display position (i k + k/2) (its block center).
  vec2 coordinate = (vec2(pixel) + 0.5) / k - 0.5;
  ivec2 base = ivec2(floor(coordinate));
  vec2 fraction = coordinate - vec2(base);
  bool bilateral = frame.counts.w == 0u;
  float epsilon = frame.output_params.z;
  vec3 total = vec3(0.0);
  float weight_sum = 0.0, bilinear_sum = 0.0;
  float nearest_gap = 1e30;
  vec3 nearest_value = vec3(0.0);
  for (int tap = 0; tap < 4; ++tap) {
    ivec2 offset = ivec2(tap & 1, tap >> 1);
    ivec2 source = clamp(base + offset, ivec2(0), receiver_size - 1);
    uint index = uint(source.y * receiver_size.x + source.x);
    vec4 tap_shaded = shaded[index];  // one read for value and depth; the normal only when needed
    float tap_depth = tap_shaded.w;
    if (tap_depth <= 0.0) continue;
    vec3 value = tap_shaded.rgb;
    float weight = (offset.x == 1 ? fraction.x : 1.0 - fraction.x) * (offset.y == 1 ? fraction.y : 1.0 - fraction.y);
    bilinear_sum += weight;
    if (bilateral) {
      float facing = max(dot(normal, receivers[index].normal.xyz), 0.0);
      weight *= pow(facing, 32.0) / (epsilon + abs(depth - tap_depth));
      weight *= epsilon;
    }
    total += weight * value;
    weight_sum += weight;
    float gap = abs(tap_depth - depth);
    if (gap < nearest_gap) {
      nearest_gap = gap;
      nearest_value = value;
    }
  }
  vec3 result = weight_sum > 1e-6 * max(bilinear_sum, 1e-30) ? total / weight_sum : nearest_value;
  irradiance[out_index] = vec4(result, 1.0);
}
