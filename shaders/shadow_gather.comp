#version 460
// Shadow accumulation (frame step 4), the compute-gather variant with tiled culling: every
// receiver loops over the proxies its 8×8 tile kept (per-proxy data in a uniform buffer, as rendering-notes §6 recommends on lavapipe) and
// sums f = Σ_i rot(O_log(s_i), d_i); each tile's list length goes to TileCounts (the heat map). The coverage oracle is the faded table: s ≤ 1/η gives 0
// and is skipped before any SH work. CPU twin: render::accumulate_log_occlusion.
#extension GL_GOOGLE_include_directive : require
#define FRAME_TILE_CULLING
#include "frame_common.glsl"
#include "sh/sh_basis.glsl"

#define SH_COUNT (SH_ORDER * SH_ORDER)
#define SH_JOIN(a, b) a##b
#define SH_EXPAND_JOIN(a, b) SH_JOIN(a, b)
#define sh_eval_basis SH_EXPAND_JOIN(sh_eval_basis_, SH_ORDER)

layout(local_size_x = kFrameLocalSize, local_size_y = kFrameLocalSize) in;
layout(std140, set = 0, binding = kShadowBindFrame) uniform Frame { FrameConstants frame; };
layout(std430, set = 0, binding = kShadowBindReceivers) readonly buffer Receivers { Receiver receivers[]; };
layout(std140, set = 0, binding = kShadowBindProxies) uniform Proxies { ProxySphere proxies[kMaxProxies]; };
layout(std430, set = 0, binding = kShadowBindLogTable) readonly buffer LogTable { float log_table[]; };
layout(std430, set = 0, binding = kShadowBindLogOcclusion) writeonly buffer LogOcclusion { float log_occlusion[]; };
layout(std430, set = 0, binding = kShadowBindTileCounts) writeonly buffer TileCounts { uint tile_list_lengths[]; };

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

  float f[SH_COUNT];
  for (int i = 0; i < SH_COUNT; ++i) f[i] = 0.0;
  if (valid) {
    vec3 normal = r.normal.xyz;
    float minimum_sine = 1.0 / frame.shadow_eta;
    int rows = int(frame.log_table_rows);
    for (uint t = 0u; t < tile_proxy_count; ++t) {
      vec4 sphere = proxies[tile_proxies[t]].center_radius;
      float weight = proxies[tile_proxies[t]].albedo.w;  // the LOD cross-fade's share (1: whole)
      // Cheap reject before the rules: outside the sphere of influence η·r.
      vec3 offset = sphere.xyz - p;
      float reach = frame.shadow_eta * sphere.w;
      if (dot(offset, offset) >= reach * reach) continue;
      vec3 direction;
      float sine;
      if (!proxy_seen_from(p, normal, sphere.xyz, sphere.w, direction, sine) || sine <= minimum_sine) continue;
      float basis[SH_COUNT];
      sh_eval_basis(direction, basis);
      for (int l = 0; l < SH_ORDER; ++l) {
        float zonal;
        ZONAL_LOOKUP(log_table, rows, SH_ORDER, sine, l, zonal);
        float scaled = zonal_scale(l) * zonal * weight;
        for (int m = -l; m <= l; ++m) f[l * (l + 1) + m] += scaled * basis[l * (l + 1) + m];
      }
    }
  }
  for (int i = 0; i < SH_COUNT; ++i) log_occlusion[index * SH_COUNT + i] = f[i];
}
