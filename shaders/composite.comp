#version 460
// Composite (frame step 8): radiance = albedo/π · E on covered pixels, the environment seen
// along the view ray elsewhere; HDR linear out, and tonemapped sRGB 8-bit out (packed RGBA8).
// CPU twin: render::tonemap (and the sRGB encoding of image::linear_to_srgb).
#extension GL_GOOGLE_include_directive : require
#include "frame_common.glsl"

layout(local_size_x = kFrameLocalSize, local_size_y = kFrameLocalSize) in;
layout(std140, set = 0, binding = 0) uniform Frame { FrameConstants frame; };
layout(set = 0, binding = 1, rgba32f) uniform readonly image2D position_depth_image;
layout(set = 0, binding = 2, rgba32f) uniform readonly image2D albedo_image;
layout(std430, set = 0, binding = 3) readonly buffer Irradiance { vec4 irradiance[]; };
layout(std430, set = 0, binding = 4) readonly buffer Environment { vec4 environment[]; };
layout(std430, set = 0, binding = 5) writeonly buffer Hdr { vec4 hdr[]; };
layout(std430, set = 0, binding = 6) writeonly buffer Ldr { uint ldr[]; };
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
  vec3 x = max(radiance * frame.output_params.x, vec3(0.0));
  uint curve = uint(frame.output_params.y);
  if (curve == 0u) return clamp((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
  if (curve == 1u) return x / (1.0 + x);
  return clamp(x, 0.0, 1.0);
}

float linear_to_srgb(float value) {
  return value <= 0.0031308 ? 12.92 * value : 1.055 * pow(value, 1.0 / 2.4) - 0.055;
}

void main() {
  uvec2 pixel = gl_GlobalInvocationID.xy;
  uvec2 display_size = frame.sizes.xy;
  if (any(greaterThanEqual(pixel, display_size))) return;
  uint index = pixel.y * display_size.x + pixel.x;
  vec4 position_depth = imageLoad(position_depth_image, ivec2(pixel));
  vec3 radiance;
  if (position_depth.w > 0.0) {
    vec3 albedo = imageLoad(albedo_image, ivec2(pixel)).rgb;
    radiance = albedo / kPi * irradiance[index].rgb;
  } else {
    vec2 ndc = (vec2(pixel) + 0.5) / vec2(display_size) * 2.0 - 1.0;
    vec4 far_point = frame.inverse_view_projection * vec4(ndc, 1.0, 1.0);
    vec3 direction = normalize(far_point.xyz / far_point.w - frame.eye_position.xyz);
    radiance = environment_radiance(direction);
  }
  hdr[index] = vec4(radiance, 1.0);
  vec3 display = tonemap(radiance);
  uvec3 encoded = uvec3(clamp(vec3(linear_to_srgb(display.r), linear_to_srgb(display.g), linear_to_srgb(display.b)), 0.0, 1.0) * 255.0 + 0.5);
  ldr[index] = encoded.r | (encoded.g << 8) | (encoded.b << 16) | (255u << 24);
}
