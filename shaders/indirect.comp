#version 460
// Indirect accumulation (frame step 6), order 3 (paper §5), compiled once per operator with
// -DINDIRECT_OPERATOR=0 (point, eq. 13), 1 (averaged, eq. 15, D by its polynomial fit) or 2
// (exact, eq. 17) as "indirect.comp:<operator>" (render::IndirectOperator), and with 3 as
// "indirect.comp:vsgl" (render.indirect_method vsgl: E_ind = Σ_k the closed form of
// sh::vsgl_irradiance over the lights vsgl_lights.comp fitted, no visibility, no ξ_p; a = 0):
//   point, averaged: E_ind = ξ_p Σ_i (albedo_i/π) max(κ_i, 0) max(V_i · H(N), 0), κ_i = rot(K, d_i) · L̃_N
//                    with K_l = D_l(s_i) or (−1)^l sqrt((2l+1)/4π) (then rot(K, d) = y(−d))
//   exact:           E_ind = ξ_p Σ_i (albedo_i/π) max(H(N) · R⁻¹ M(s_i) R L̃_N, 0), M from binding 7
// L̃_N: the receiver's sender light, the lighting above its tangent plane (sh/sender_light.h), read
// from the cubes at binding 9 by N (L̃ in every texel when render.mask_sender_light is off).
// ξ_p = clamp((V_p)_0 / (ω_p/√4π), 0, 1) with (V_p)_0 = √4π − (O_p)_0 from the exponentiation.
// Output per receiver: (E_r, E_g, E_b, ω_p), and the packed (E_direct + E_indirect, eye depth)
// upsampling reads. CPU twin: render::accumulate_indirect (exact: render/exact_indirect.h).
#extension GL_GOOGLE_include_directive : require
#define FRAME_TILE_CULLING
#include "frame_common.glsl"
#include "sh/sh_basis.glsl"

layout(local_size_x = kFrameLocalSize, local_size_y = kFrameLocalSize) in;
layout(std140, set = 0, binding = kIndirectBindFrame) uniform Frame { FrameConstants frame; };
layout(std430, set = 0, binding = kIndirectBindReceivers) readonly buffer Receivers { Receiver receivers[]; };
layout(std140, set = 0, binding = kIndirectBindProxies) uniform Proxies { ProxySphere proxies[kMaxProxies]; };
layout(std430, set = 0, binding = kIndirectBindVisibilityTable) readonly buffer VisibilityTable { float visibility_table[]; };
layout(std430, set = 0, binding = kIndirectBindDirect) readonly buffer Direct { vec4 direct[]; };
layout(std430, set = 0, binding = kIndirectBindIndirect) writeonly buffer Indirect { vec4 indirect[]; };
// What upsampling reads per tap, packed into one vec4: (E_direct + E_indirect, eye depth).
layout(std430, set = 0, binding = kIndirectBindShaded) writeonly buffer Shaded { vec4 shaded[]; };

#ifndef INDIRECT_OPERATOR
#error "compile with -DINDIRECT_OPERATOR=0 (point), 1 (averaged), 2 (exact) or 3 (vsgl)"
#endif
#if INDIRECT_OPERATOR == 2
#include "indirect_exact.glsl"
#endif
#if INDIRECT_OPERATOR != 3
#include "cube_taps.glsl"
// Per cube texel, coefficient i's (r, g, b, 0) at texel * 9 + i (gpu/frame_resources.cpp).
layout(set = 0, binding = kIndirectBindSenderLight) uniform samplerBuffer sender_light_texels;

// L̃_N of the three channels, bilinear in the cube face N hits (CPU twin render::sender_light).
// cube_map_taps with 9 values per texel gives texel × 9: the first of that cube texel's 9 texels here.
void sender_light(vec3 n, out vec3 light[9]) {
  const int count = int(kIndirectOrder * kIndirectOrder);
  CubeTaps taps = cube_map_taps(int(frame.lighting_cube_face_size), count, 0, n);
  for (int i = 0; i < count; ++i) {
    vec3 t00 = texelFetch(sender_light_texels, taps.t00 + i).rgb, t10 = texelFetch(sender_light_texels, taps.t10 + i).rgb;
    vec3 t01 = texelFetch(sender_light_texels, taps.t01 + i).rgb, t11 = texelFetch(sender_light_texels, taps.t11 + i).rgb;
    vec3 top = t00 + taps.fx * (t10 - t00);
    vec3 bottom = t01 + taps.fx * (t11 - t01);
    light[i] = top + taps.fy * (bottom - top);
  }
}
#endif
#if INDIRECT_OPERATOR == 3
layout(std430, set = 0, binding = kIndirectBindVsglLights) readonly buffer VsglLights {
  uvec4 vsgl_light_count;
  VsglLight vsgl_lights[];
};

// sh::vsgl_irradiance: eq. 6–7 (λ_σ = ‖μ − p‖²/σ², σ² floored), then the diffuse result with
// A(λ_d) exact; λ_in − λ_v − λ_σ in the form that does not cancel the large λ_σ.
vec3 vsgl_irradiance(VsglLight light, vec3 p, vec3 normal) {
  vec3 offset = light.mean_variance.xyz - p;
  float distance2 = dot(offset, offset);
  if (!(distance2 > 0.0)) return vec3(0.0);
  vec3 toward = offset * inversesqrt(distance2);
  float variance = max(light.mean_variance.w, kVsglMinRelativeVariance * distance2);
  float spread = distance2 / variance;
  vec3 axis = light.axis_sharpness.xyz;
  float sharpness_v = light.axis_sharpness.w;
  vec3 sum = spread * toward - sharpness_v * axis;
  float sharpness = length(sum);
  float exponent = -2.0 * spread * sharpness_v * (1.0 + dot(toward, axis)) / (sharpness + spread + sharpness_v);
  vec3 axis_in = sharpness > 0.0 ? sum / sharpness : toward;
  vec3 amplitude = light.amplitude.rgb * (exp(exponent) / (2.0 * kPi * variance));
  const float lambda_d = kVsglDiffuseSharpness;
  float cosine_amplitude = kPi * lambda_d / (2.0 * kPi * (1.0 - exp(-2.0 * lambda_d)));  // π / A(λ_d)
  float blurred = sharpness * lambda_d / (sharpness + lambda_d);
  return amplitude * (2.0 * kPi * cosine_amplitude * exp(blurred * (dot(axis_in, normal) - 1.0)) / (sharpness + lambda_d));
}

void main() {
  uvec2 receiver = gl_GlobalInvocationID.xy;
  uvec2 receiver_size = uvec2(frame.receiver_width, frame.receiver_height);
  if (!all(lessThan(receiver, receiver_size))) return;
  uint index = receiver.y * receiver_size.x + receiver.x;
  Receiver r = receivers[index];
  if (!(r.position_depth.w > 0.0) || frame.indirect_enabled == 0u) {
    indirect[index] = vec4(0.0);
    shaded[index] = r.position_depth.w > 0.0 ? vec4(direct[index].rgb, r.position_depth.w) : vec4(0.0);
    return;
  }
  vec3 irradiance = vec3(0.0);
  for (uint k = 0u; k < vsgl_light_count.x; ++k) irradiance += vsgl_irradiance(vsgl_lights[k], r.position_depth.xyz, r.normal.xyz);
  indirect[index] = vec4(irradiance, 0.0);
  shaded[index] = vec4(direct[index].rgb + irradiance, r.position_depth.w);
}
#else

float influence_fade(float s, float eta, int rows) {
  float width = 4.0 / float(rows - 1);
  float t = clamp((s - 1.0 / eta) / width, 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);
}

vec4 proxy_center_radius(uint i) { return proxies[i].center_radius; }

void main() {
  uvec2 receiver = gl_GlobalInvocationID.xy;
  uvec2 receiver_size = uvec2(frame.receiver_width, frame.receiver_height);
  bool inside = all(lessThan(receiver, receiver_size));
  uint index = receiver.y * receiver_size.x + receiver.x;
  Receiver r;
  r.position_depth = vec4(0.0);
  r.normal = vec4(0.0, 1.0, 0.0, 0.0);
  if (inside) r = receivers[index];
  bool valid = inside && r.position_depth.w > 0.0 && frame.indirect_enabled != 0u;
  vec3 p = r.position_depth.xyz;
  TILE_CULL(proxy_center_radius, frame.proxy_count, frame.indirect_eta, p, valid);
  if (!inside) return;
  if (!valid) {
    indirect[index] = vec4(0.0);
    shaded[index] = r.position_depth.w > 0.0 ? vec4(direct[index].rgb, r.position_depth.w) : vec4(0.0);
    return;
  }
  vec3 normal = r.normal.xyz;
  float normal_basis[9];
  sh_eval_basis_3(normal, normal_basis);
  const float cosine[3] = float[](0.886226925, 1.023326708, 0.495415912);
  float eta = frame.indirect_eta;
  float minimum_sine = 1.0 / eta;
  int rows = int(frame.visibility_table_rows);
  vec3 light[9];
  sender_light(normal, light);
  vec3 summed = vec3(0.0);
  float solid_angle_sum = 0.0;
  for (uint t = 0u; t < tile_proxy_count; ++t) {
    uint i = tile_proxies[t];
    vec4 sphere = proxies[i].center_radius;
    vec3 offset = sphere.xyz - p;
    float reach = eta * sphere.w;
    if (dot(offset, offset) >= reach * reach) continue;
    vec3 direction;
    float sine;
    if (!proxy_seen_from(p, normal, sphere.xyz, sphere.w, direction, sine) || sine <= minimum_sine) continue;
#if INDIRECT_OPERATOR == 2
    float weights[9];
    exact_indirect_weights(sine, direction, normal, weights);
    vec3 radiance = vec3(0.0);
    for (int c = 0; c < 9; ++c)
      radiance += weights[c] * light[c];
    summed += proxies[i].albedo.w * (proxies[i].albedo.rgb / kPi * max(radiance, vec3(0.0)));
#else
    float basis[9];
    sh_eval_basis_3(direction, basis);
#if INDIRECT_OPERATOR == 1
    vec3 averaged = vec3(0.28209, (0.08432 * sine - 0.25073) * sine - 0.32494,
                         ((-0.22230 * sine + 0.22502) * sine + 0.47398) * sine + 0.15950);
#endif
    float seen_cosine = 0.0;
    vec3 kappa = vec3(0.0);
    for (int l = 0; l < 3; ++l) {
      float visibility;
      ZONAL_LOOKUP(visibility_table, rows, 3, sine, l, visibility);
      float band_normal = 0.0;
      vec3 band_light = vec3(0.0);
      for (int m = -l; m <= l; ++m) {
        int c = l * (l + 1) + m;
        band_normal += basis[c] * normal_basis[c];
        band_light += basis[c] * light[c];
      }
      float scale = zonal_scale(l);
      seen_cosine += scale * visibility * scale * cosine[l] * band_normal;
#if INDIRECT_OPERATOR == 1
      kappa += scale * averaged[l] * band_light;
#else
      kappa += ((l & 1) == 0 ? 1.0 : -1.0) * band_light;  // sqrt(4π/(2l+1)) K_l = (−1)^l
#endif
    }
    summed += proxies[i].albedo.w * (proxies[i].albedo.rgb / kPi * max(kappa, vec3(0.0)) * max(seen_cosine, 0.0));
#endif
    float solid_angle = 2.0 * kPi * (1.0 - sqrt(max(1.0 - sine * sine, 0.0)));
    solid_angle_sum += solid_angle * influence_fade(sine, eta, rows) * proxies[i].albedo.w;  // w: the LOD fade's share
  }
  vec3 irradiance = vec3(0.0);
  if (solid_angle_sum > 0.0) {
    float covered_dc = max(kSqrtFourPi - direct[index].w, 0.0);
    irradiance = summed * clamp(covered_dc * kSqrtFourPi / solid_angle_sum, 0.0, 1.0);
  }
  indirect[index] = vec4(irradiance, solid_angle_sum);
  shaded[index] = vec4(direct[index].rgb + irradiance, r.position_depth.w);
}
#endif
