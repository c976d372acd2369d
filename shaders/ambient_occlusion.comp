#version 460
// Scalar ambient occlusion from the proxy spheres (the AO baseline; replaces frame steps 4–6 at
// the same 1/k receivers, then the same upsampling and composite):
//   A = Π_i (1 − a_i),   a_i = w(s_i) · s_i² · max(N·d_i, 0),   E = A · E(N),   no bounce light.
// a_i is the cosine-weighted fraction of the hemisphere sphere i covers, (1/π) ∫_cap N·ω dω,
// which equals s² cos β for a cap of sin half-angle s whose axis d makes angle β with N, as long
// as the cap lies above the tangent plane. The tangent-plane rules (proxy_seen_from, notes
// sh-math §5) replace a straddling sphere by one resting on the plane, so every kept cap does
// and the formula is exact for the adjusted sphere. w is the sphere-of-influence fade of the
// shadow table (0 at s = 1/η_shadow, smoothstep over 4 rows), so AO and SHEXP cover the same
// receivers. E(N) = √4π (LH(N))_0 per channel: the unshadowed irradiance of the environment's
// SH, the same cube maps exponentiate.comp reads (the ground-lit set above the ground). The
// product over overlapping spheres is the usual AO independence assumption (it over-darkens
// where spheres overlap; SHEXP does not).
// Output per receiver: direct (E, A), indirect 0, shaded (E, eye depth).
// CPU twin: render::ambient_occlusion (src/render/baselines.h).
#extension GL_GOOGLE_include_directive : require
#define FRAME_TILE_CULLING
#include "frame_common.glsl"

#define SH_COUNT (SH_ORDER * SH_ORDER)

layout(local_size_x = kFrameLocalSize, local_size_y = kFrameLocalSize) in;
layout(std140, set = 0, binding = kAoBindFrame) uniform Frame { FrameConstants frame; };
layout(std430, set = 0, binding = kAoBindReceivers) readonly buffer Receivers { Receiver receivers[]; };
layout(std140, set = 0, binding = kAoBindProxies) uniform Proxies { ProxySphere proxies[kMaxProxies]; };
layout(std430, set = 0, binding = kAoBindLightingCube) readonly buffer LightingCube { float lighting_cube[]; };  // r, g, b cubes, twice
layout(std430, set = 0, binding = kAoBindDirect) writeonly buffer Direct { vec4 direct[]; };
layout(std430, set = 0, binding = kAoBindIndirect) writeonly buffer Indirect { vec4 indirect[]; };
layout(std430, set = 0, binding = kAoBindShaded) writeonly buffer Shaded { vec4 shaded[]; };
layout(std430, set = 0, binding = kAoBindTileCounts) writeonly buffer TileCounts { uint tile_list_lengths[]; };  // the heat map

#include "lighting_cube.glsl"

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
  bool valid = inside && r.position_depth.w > 0.0;
  vec3 p = r.position_depth.xyz;
  TILE_CULL(proxy_center_radius, frame.proxy_count, frame.shadow_eta, p, valid);
  if (gl_LocalInvocationIndex == 0u) tile_list_lengths[gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x] = tile_proxy_count;
  if (!inside) return;
  indirect[index] = vec4(0.0);
  if (!valid) {
    direct[index] = vec4(0.0, 0.0, 0.0, 1.0);
    shaded[index] = vec4(0.0);
    return;
  }
  vec3 normal = r.normal.xyz;
  float eta = frame.shadow_eta;
  float minimum_sine = 1.0 / eta;
  int rows = int(frame.log_table_rows);
  float unoccluded = 1.0;
  for (uint t = 0u; t < tile_proxy_count; ++t) {
    vec4 sphere = proxies[tile_proxies[t]].center_radius;
    float weight = proxies[tile_proxies[t]].albedo.w;  // the LOD cross-fade's share (1: whole)
    vec3 offset = sphere.xyz - p;
    float reach = eta * sphere.w;
    if (dot(offset, offset) >= reach * reach) continue;
    vec3 direction;
    float sine;
    if (!proxy_seen_from(p, normal, sphere.xyz, sphere.w, direction, sine) || sine <= minimum_sine) continue;
    float covered = influence_fade(sine, eta, rows) * sine * sine * max(dot(normal, direction), 0.0);
    float kept = 1.0 - clamp(covered, 0.0, 1.0);
    unoccluded *= weight == 1.0 ? kept : pow(kept, weight);  // a fade: Π (1 − a_i)^w_i
  }
  int set = lighting_cube_set(p);
  vec3 unshadowed = kSqrtFourPi * vec3(lighting_lookup_dc(set, normal), lighting_lookup_dc(set + 1, normal),
                                       lighting_lookup_dc(set + 2, normal));
  vec3 irradiance = max(unoccluded * unshadowed, vec3(0.0));
  direct[index] = vec4(irradiance, unoccluded);
  shaded[index] = vec4(irradiance, r.position_depth.w);
}
