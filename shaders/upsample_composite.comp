#version 460
// Upsampling and composite (frame steps 7 and 8, one pass: both run per display pixel and the
// pass already has its G-buffer texel, so fusing them saves a full-resolution round trip).
// Step 7: display-resolution irradiance E = E_direct + E_indirect from the 2×2 surrounding
// receivers with the joint-bilateral weights of eq. 11 (bilinear × depth × normal^32), or plain
// bilinear; where every weight vanishes, the valid tap nearest in depth (written as an AOV).
// Step 8: radiance = albedo/π · E on covered pixels, the environment along the view ray
// elsewhere; HDR linear out and tonemapped sRGB 8-bit out (packed RGBA8).
// Vertex method (frame.composite_mode == kCompositeDisplayIrradiance): step 7 is the rasterizer's
// interpolation of the vertex irradiance, which the G-buffer's second target already holds.
// CPU twins: render::upsample, render::tonemap and image::linear_to_srgb.
#extension GL_GOOGLE_include_directive : require
#include "frame_common.glsl"

layout(local_size_x = kFrameLocalSize, local_size_y = kFrameLocalSize) in;
layout(std140, set = 0, binding = kCompositeBindFrame) uniform Frame { FrameConstants frame; };
layout(set = 0, binding = kCompositeBindPositionDepth, rgba32f) uniform readonly image2D position_depth_image;
layout(set = 0, binding = kCompositeBindNormal, rgba32f) uniform readonly image2D normal_image;
layout(std430, set = 0, binding = kCompositeBindReceivers) readonly buffer Receivers { Receiver receivers[]; };
layout(std430, set = 0, binding = kCompositeBindShaded) readonly buffer Shaded { vec4 shaded[]; };  // (E, eye depth)
layout(std430, set = 0, binding = kCompositeBindIrradiance) writeonly buffer Irradiance { vec4 irradiance[]; };
layout(set = 0, binding = kCompositeBindAlbedo, rgba32f) uniform readonly image2D albedo_image;
layout(std430, set = 0, binding = kCompositeBindEnvironment) readonly buffer Environment { vec4 environment[]; };
layout(std430, set = 0, binding = kCompositeBindHdr) writeonly buffer Hdr { vec4 hdr[]; };
layout(std430, set = 0, binding = kCompositeBindLdr) writeonly buffer Ldr { uint ldr[]; };
layout(push_constant) uniform Push { CompositePush push; };

vec3 environment_radiance(vec3 direction) {
  // Inverse of sh/environment.h: direction = (sin θ sin φ, cos θ, −sin θ cos φ).
  float theta = acos(clamp(direction.y, -1.0, 1.0));
  float phi = atan(direction.x, -direction.z);
  float u = (phi + kPi) / (2.0 * kPi);
  float v = theta / kPi;
  int x = clamp(int(u * float(push.environment_width)), 0, int(push.environment_width) - 1);
  int y = clamp(int(v * float(push.environment_height)), 0, int(push.environment_height) - 1);
  return environment[y * int(push.environment_width) + x].rgb;
}

vec3 tonemap(vec3 radiance) {
  vec3 x = max(radiance * frame.exposure, vec3(0.0));
  uint curve = frame.tonemap;
  if (curve == kTonemapAces) return clamp((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
  if (curve == kTonemapReinhard) return x / (1.0 + x);
  return clamp(x, 0.0, 1.0);
}

float linear_to_srgb(float value) {
  return value <= 0.0031308 ? 12.92 * value : 1.055 * pow(value, 1.0 / 2.4) - 0.055;
}

// Step 7 for a covered pixel.
vec3 upsampled_irradiance(uvec2 pixel, float depth) {
  vec3 normal = imageLoad(normal_image, ivec2(pixel)).xyz;
  ivec2 receiver_size = ivec2(uvec2(frame.receiver_width, frame.receiver_height));
  float k = float(frame.receiver_scale);
  // Receiver (i, j) sits at display position (i k + k/2) (its block center).
  vec2 coordinate = (vec2(pixel) + 0.5) / k - 0.5;
  ivec2 base = ivec2(floor(coordinate));
  vec2 fraction = coordinate - vec2(base);
  bool bilateral = frame.composite_mode == kCompositeBilateral;
  float epsilon = frame.bilateral_depth_epsilon;
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
      // facing^32 by five squarings: pow() is exp2(32 log2 x), several times dearer on lavapipe.
      facing *= facing;
      facing *= facing;
      facing *= facing;
      facing *= facing;
      facing *= facing;
      weight *= facing / (epsilon + abs(depth - tap_depth));
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
  return weight_sum > 1e-6 * max(bilinear_sum, 1e-30) ? total / weight_sum : nearest_value;
}

// The shading of the receiver whose block holds this pixel (the 1/k grid as it is).
vec3 nearest_receiver(uvec2 pixel) {
  ivec2 receiver_size = ivec2(frame.receiver_width, frame.receiver_height);
  ivec2 source = clamp(ivec2(pixel) / int(frame.receiver_scale), ivec2(0), receiver_size - 1);
  return shaded[uint(source.y * receiver_size.x + source.x)].rgb;
}

void main() {
  uvec2 pixel = gl_GlobalInvocationID.xy;
  uvec2 display_size = uvec2(frame.display_width, frame.display_height);
  if (any(greaterThanEqual(pixel, display_size))) return;
  uint index = pixel.y * display_size.x + pixel.x;
  vec4 position_depth = imageLoad(position_depth_image, ivec2(pixel));
  vec3 radiance;
  vec3 e = vec3(0.0);
  if (position_depth.w > 0.0) {
    e = frame.composite_mode == kCompositeDisplayIrradiance ? imageLoad(normal_image, ivec2(pixel)).rgb
                                                           : upsampled_irradiance(pixel, position_depth.w);
    irradiance[index] = vec4(e, 1.0);
    radiance = imageLoad(albedo_image, ivec2(pixel)).rgb / kPi * e;
  } else {
    irradiance[index] = vec4(0.0);
    vec2 ndc = (vec2(pixel) + 0.5) / vec2(display_size) * 2.0 - 1.0;
    vec4 far_point = frame.inverse_view_projection * vec4(ndc, 1.0, 1.0);
    vec3 direction = normalize(far_point.xyz / far_point.w - frame.eye_position.xyz);
    radiance = environment_radiance(direction);
  }
  vec3 display;
  if (frame.debug_view != kDebugViewFinal && position_depth.w > 0.0) {  // the viewer's views
    uint view = frame.debug_view;
    if (view == kDebugViewAlbedo) display = imageLoad(albedo_image, ivec2(pixel)).rgb;
    else if (view == kDebugViewNormals) display = 0.5 + 0.5 * imageLoad(normal_image, ivec2(pixel)).xyz;
    else if (view == kDebugViewIrradiance) display = tonemap(e / kPi);
    else display = tonemap(nearest_receiver(pixel) / kPi);
    radiance = display;
  } else {
    display = tonemap(radiance);
  }
  hdr[index] = vec4(radiance, 1.0);
  uvec3 encoded = uvec3(clamp(vec3(linear_to_srgb(display.r), linear_to_srgb(display.g), linear_to_srgb(display.b)), 0.0, 1.0) * 255.0 + 0.5);
  ldr[index] = encoded.r | (encoded.g << 8) | (encoded.b << 16) | (255u << 24);
}
