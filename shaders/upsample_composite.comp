#version 460
// Upsampling and composite (frame steps 7 and 8, one pass: both run per display pixel and the
// pass already has its G-buffer texel, so fusing them saves a full-resolution round trip).
// Step 7: display-resolution irradiance E = E_direct + E_indirect from the 2×2 surrounding
// receivers with the joint-bilateral weights of eq. 11 (bilinear × depth × normal^32), or plain
// bilinear. The depth term is the tap's distance to the pixel's tangent plane over eye depth (F8:
// scale-invariant). Where every weight vanishes, bilinear × that term alone (interpolating), and
// only where that is 0 too the valid tap nearest in depth.
// Step 8: radiance = albedo/π · E on covered pixels, the environment along the view ray
// elsewhere; HDR linear out and tonemapped sRGB 8-bit out (packed RGBA8).
// Vertex method (frame.composite_mode == kCompositeDisplayIrradiance): step 7 is the rasterizer's
// interpolation of the vertex irradiance, which the G-buffer's second target already holds.
// The viewer's views (frame.debug_view, layouts.h kDebugView*) show an input instead: the
// direct and indirect buffers upsampled with the same taps (so they sum to the final frame), the
// visibility DC, or the shadow pass's per-tile list lengths as a heat map. They are compiled only
// into the DEBUG_VIEWS variant ("upsample_composite.comp:views"): lavapipe runs both sides of
// every branch under a lane mask, so the final frame's pipeline leaves the views' reads out.
// Outputs: the sRGB frame always; NO_IRRADIANCE_AOV leaves out the irradiance AOV and NO_HDR the
// linear radiance (":no_aov", ":ldr_only", for frames whose caller reads neither, FrameOutput::
// float_targets): on lavapipe each vec4 store is a loop over the lanes per component, and the two
// vec4 stores took about 40 % of this pass.
// CPU twins: render::upsample, render::tonemap and image::linear_to_srgb.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_control_flow_attributes : require
#include "frame_common.glsl"

layout(local_size_x = kFrameLocalSize, local_size_y = kFrameLocalSize) in;
layout(std140, set = 0, binding = kCompositeBindFrame) uniform Frame { FrameConstants frame; };
layout(set = 0, binding = kCompositeBindPositionDepth, rgba32f) uniform readonly image2D position_depth_image;
layout(set = 0, binding = kCompositeBindNormal, rgba32f) uniform readonly image2D normal_image;
// The receivers, their shading and the environment are read as texels: lavapipe gathers texels
// in SIMD vectors, where a storage-buffer read is a loop over the lanes (most of this pass's time).
layout(set = 0, binding = kCompositeBindReceivers) uniform samplerBuffer receiver_texels;  // layouts.h kReceiverTexels
layout(set = 0, binding = kCompositeBindShaded) uniform samplerBuffer shaded_texels;  // (E, eye depth)
layout(std430, set = 0, binding = kCompositeBindIrradiance) writeonly buffer Irradiance { vec4 irradiance[]; };
layout(set = 0, binding = kCompositeBindAlbedo, rgba32f) uniform readonly image2D albedo_image;
layout(set = 0, binding = kCompositeBindEnvironment) uniform samplerBuffer environment_texels;
layout(std430, set = 0, binding = kCompositeBindHdr) writeonly buffer Hdr { vec4 hdr[]; };
layout(std430, set = 0, binding = kCompositeBindLdr) writeonly buffer Ldr { uint ldr[]; };
layout(std430, set = 0, binding = kCompositeBindDirect) readonly buffer Direct { vec4 direct_light[]; };      // (E_direct, w)
layout(std430, set = 0, binding = kCompositeBindIndirect) readonly buffer Indirect { vec4 indirect_light[]; };  // (E_indirect, ω)
layout(std430, set = 0, binding = kCompositeBindTileCounts) readonly buffer TileCounts { uint tile_list_lengths[]; };
layout(push_constant) uniform Push { CompositePush push; };

vec3 environment_radiance(vec3 direction) {
  // Inverse of sh/environment.h: direction = (sin θ sin φ, cos θ, −sin θ cos φ).
  float theta = acos(clamp(direction.y, -1.0, 1.0));
  float phi = atan(direction.x, -direction.z);
  float u = (phi + kPi) / (2.0 * kPi);
  float v = theta / kPi;
  int x = clamp(int(u * float(push.environment_width)), 0, int(push.environment_width) - 1);
  int y = clamp(int(v * float(push.environment_height)), 0, int(push.environment_height) - 1);
  return texelFetch(environment_texels, y * int(push.environment_width) + x).rgb;
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

// Step 7's taps for a covered pixel: the valid receivers of the 2×2 around it with their weights
// (eq. 11 or bilinear) and shaded values; when every weight vanishes, the same taps weighted by
// bilinear × tangent-plane term, and when that is 0 the tap nearest in depth alone (weight 1). Any receiver quantity upsamples as Σ w_i v_i / weight_sum with these taps, so
// the direct and indirect views sum to the final frame's irradiance.
// Slot t holds tap t (offset (t & 1, t >> 1)) and every loop over slots runs 0..3 unrolled, so
// each array is indexed by constants: llvmpipe spills dynamically indexed arrays to memory.
// Sums skip unused slots and run in slot order, the order of the taps.
struct UpsampleTaps {
  uint index[4];
  float weight[4];
  vec3 shaded[4];
  bool used[4];
  float weight_sum;
};

UpsampleTaps upsample_taps(uvec2 pixel, vec3 position, float depth) {
  vec3 normal = imageLoad(normal_image, ivec2(pixel)).xyz;
  ivec2 receiver_size = ivec2(uvec2(frame.receiver_width, frame.receiver_height));
  float k = float(frame.receiver_scale);
  // Receiver (i, j) sits at display position (i k + k/2) (its block center).
  vec2 coordinate = (vec2(pixel) + 0.5) / k - 0.5;
  ivec2 base = ivec2(floor(coordinate));
  vec2 fraction = coordinate - vec2(base);
  bool bilateral = frame.composite_mode == kCompositeBilateral;
  float epsilon = frame.bilateral_depth_epsilon;
  UpsampleTaps taps;
  float weight_sum = 0.0, bilinear_sum = 0.0, fallback_sum = 0.0;
  float fallback[4];
  float nearest_gap = 1e30;
  uint nearest_index = 0u;
  vec3 nearest_value = vec3(0.0);
  [[unroll]] for (int tap = 0; tap < 4; ++tap) {
    ivec2 offset = ivec2(tap & 1, tap >> 1);
    ivec2 source = clamp(base + offset, ivec2(0), receiver_size - 1);
    uint index = uint(source.y * receiver_size.x + source.x);
    vec4 tap_shaded = texelFetch(shaded_texels, int(index));  // one read for value and depth; the normal only when needed
    float tap_depth = tap_shaded.w;
    taps.used[tap] = tap_depth > 0.0;
    taps.index[tap] = index;
    taps.weight[tap] = 0.0;
    taps.shaded[tap] = vec3(0.0);
    fallback[tap] = 0.0;
    if (!taps.used[tap]) continue;
    vec3 value = tap_shaded.rgb;
    float weight = (offset.x == 1 ? fraction.x : 1.0 - fraction.x) * (offset.y == 1 ? fraction.y : 1.0 - fraction.y);
    bilinear_sum += weight;
    if (bilateral) {
      vec3 tap_position = texelFetch(receiver_texels, int(kReceiverTexels * index)).xyz;
      vec3 tap_normal = texelFetch(receiver_texels, int(kReceiverTexels * index + 1u)).xyz;
      float facing = max(dot(normal, tap_normal), 0.0);
      // facing^32 by five squarings: pow() is exp2(32 log2 x), several times dearer on lavapipe.
      facing *= facing;
      facing *= facing;
      facing *= facing;
      facing *= facing;
      facing *= facing;
      float plane_gap = abs(dot(normal, tap_position - position)) / depth;
      float near_plane = epsilon / (epsilon + plane_gap);
      fallback[tap] = weight * near_plane;
      fallback_sum += weight * near_plane;
      weight *= facing * near_plane;
    } else {
      fallback[tap] = weight;
      fallback_sum += weight;
    }
    taps.weight[tap] = weight;
    taps.shaded[tap] = value;
    weight_sum += weight;
    float gap = abs(tap_depth - depth);
    if (gap < nearest_gap) {
      nearest_gap = gap;
      nearest_index = index;
      nearest_value = value;
    }
  }
  taps.weight_sum = weight_sum;
  if (!(weight_sum > 1e-6 * max(bilinear_sum, 1e-30)) && fallback_sum > 0.0) {
    [[unroll]] for (int t = 0; t < 4; ++t) taps.weight[t] = fallback[t];
    taps.weight_sum = fallback_sum;
  } else if (!(weight_sum > 1e-6 * max(bilinear_sum, 1e-30))) {
    [[unroll]] for (int t = 1; t < 4; ++t) taps.used[t] = false;
    taps.used[0] = true;
    taps.index[0] = nearest_index;
    taps.weight[0] = 1.0;
    taps.shaded[0] = nearest_value;
    taps.weight_sum = 1.0;
  }
  return taps;
}

vec3 upsample_shaded(UpsampleTaps taps) {
  vec3 total = vec3(0.0);
  [[unroll]] for (int t = 0; t < 4; ++t)
    if (taps.used[t]) total += taps.weight[t] * taps.shaded[t];
  return total / taps.weight_sum;
}

#ifdef DEBUG_VIEWS
// A receiver quantity (kDebugViewDirect: E_direct and its w, kDebugViewIndirect: E_indirect) with the same taps.
vec4 upsample_buffer(UpsampleTaps taps, uint view) {
  vec4 total = vec4(0.0);
  [[unroll]] for (int t = 0; t < 4; ++t)
    if (taps.used[t]) total += taps.weight[t] * (view == kDebugViewIndirect ? indirect_light[taps.index[t]] : direct_light[taps.index[t]]);
  return total / taps.weight_sum;
}

// The heat map's ramp over t = count / proxies in [0, 1] (blue, cyan, green, yellow, red); the
// UI's legend draws the same (viewer_ui.cpp heat_color).
vec3 heat_color(float t) {
  t = clamp(t, 0.0, 1.0);
  return clamp(vec3(1.5 - abs(4.0 * t - 3.0), 1.5 - abs(4.0 * t - 2.0), 1.5 - abs(4.0 * t - 1.0)), 0.0, 1.0);
}

// The shading of the receiver whose block holds this pixel (the 1/k grid as it is).
vec3 nearest_receiver(uvec2 pixel) {
  ivec2 receiver_size = ivec2(frame.receiver_width, frame.receiver_height);
  ivec2 source = clamp(ivec2(pixel) / int(frame.receiver_scale), ivec2(0), receiver_size - 1);
  return texelFetch(shaded_texels, source.y * receiver_size.x + source.x).rgb;
}

#endif

void main() {
  uvec2 pixel = gl_GlobalInvocationID.xy;
  uvec2 display_size = uvec2(frame.display_width, frame.display_height);
  if (any(greaterThanEqual(pixel, display_size))) return;
  uint index = pixel.y * display_size.x + pixel.x;
  vec4 position_depth = imageLoad(position_depth_image, ivec2(pixel));
#ifdef DEBUG_VIEWS
  uint view = frame.debug_view;
  bool receiver_views = frame.composite_mode != kCompositeDisplayIrradiance;  // the vertex method has none at display res
#endif
  vec3 radiance;
  vec3 e = vec3(0.0);
  vec3 albedo = vec3(0.0);
  vec4 aov = vec4(0.0);  // the irradiance AOV, stored once below (each store is a loop over the lanes)
  UpsampleTaps taps;
  [[unroll]] for (int t = 0; t < 4; ++t) taps.used[t] = false;
  taps.weight_sum = 1.0;
  if (position_depth.w > 0.0) {
    albedo = imageLoad(albedo_image, ivec2(pixel)).rgb;
    if (frame.composite_mode == kCompositeDisplayIrradiance) {
      e = imageLoad(normal_image, ivec2(pixel)).rgb;
    } else {
      taps = upsample_taps(pixel, position_depth.xyz, position_depth.w);
      e = upsample_shaded(taps);
    }
    aov = vec4(e, 1.0);
    radiance = albedo / kPi * e;
  } else {
    vec2 ndc = (vec2(pixel) + 0.5) / vec2(display_size) * 2.0 - 1.0;
    vec4 far_point = frame.inverse_view_projection * vec4(ndc, 1.0, 1.0);
    vec3 direction = normalize(far_point.xyz / far_point.w - frame.eye_position.xyz);
    radiance = environment_radiance(direction);
  }
#ifndef NO_IRRADIANCE_AOV
  irradiance[index] = aov;
#endif
  vec3 display = tonemap(radiance);
#ifdef DEBUG_VIEWS
  if (view != kDebugViewFinal && position_depth.w > 0.0 && view <= kDebugViewReceivers) {  // the frame's inputs
    if (view == kDebugViewAlbedo) display = albedo;
    else if (view == kDebugViewNormals) display = 0.5 + 0.5 * imageLoad(normal_image, ivec2(pixel)).xyz;
    else if (view == kDebugViewIrradiance) display = tonemap(e / kPi);
    else display = tonemap(nearest_receiver(pixel) / kPi);
    radiance = display;
  } else if ((view == kDebugViewDirect || view == kDebugViewIndirect) && position_depth.w > 0.0 && receiver_views) {
    radiance = albedo / kPi * upsample_buffer(taps, view).rgb;
    display = tonemap(radiance);
  } else if (view == kDebugViewOcclusion && position_depth.w > 0.0 && receiver_views) {
    float visible = clamp(upsample_buffer(taps, kDebugViewDirect).w * frame.occlusion_scale, 0.0, 1.0);
    radiance = vec3(visible);
    display = radiance;
  } else if (view == kDebugViewHeatMap && frame.tile_counts_valid != 0u) {
    uvec2 tile = pixel / (frame.receiver_scale * kFrameLocalSize);
    uint tiles_x = (frame.receiver_width + kFrameLocalSize - 1u) / kFrameLocalSize;
    uint count = tile_list_lengths[tile.y * tiles_x + tile.x];
    if (count > 0u) display = mix(display, heat_color(float(count) / float(max(frame.proxy_count, 1u))), 0.65);
    radiance = vec3(float(count));
  }
#endif
#ifndef NO_HDR
  hdr[index] = vec4(radiance, 1.0);
#endif
  uvec3 encoded = uvec3(clamp(vec3(linear_to_srgb(display.r), linear_to_srgb(display.g), linear_to_srgb(display.b)), 0.0, 1.0) * 255.0 + 0.5);
  // In the caller's channel order (an image output of B8G8R8A8: one raw copy lands it).
  if (push.ldr_swap_red_blue != 0u) encoded = encoded.bgr;
  ldr[index] = encoded.r | (encoded.g << 8) | (encoded.b << 16) | (255u << 24);
}
