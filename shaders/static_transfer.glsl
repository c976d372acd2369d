// Static receivers' PRT in the frame (render.static_transfer ratio = 1, l1 = 2): the lookup of
// the PRT triangle under a receiver and the ratio / l1 sums of prt/static_field.h, which holds
// the CPU twin of every line here (find_static_hit, interpolate_record, shade_static_direct);
// for every other receiver the static meshes' visibility grid (prt/visibility_grid.h:
// sample_visibility; prt::character_receiver_direct).
// Include in exponentiate.comp after the `static_*` buffers, `lighting_cube`, SH_COUNT and
// SH_EXPAND_JOIN, with STATIC_TRANSFER defined 1 or 2.
#ifndef PROXYGI_STATIC_TRANSFER_GLSL
#define PROXYGI_STATIC_TRANSFER_GLSL

#define STATIC_RECORD_FLOATS (4 * SH_COUNT + 6)
#define sh_product SH_EXPAND_JOIN(sh_product_, SH_ORDER)

struct StaticHit {
  uint triangle;
  vec3 weights;  // barycentric weights of the triangle's vertices 0, 1, 2
};

// The PRT triangle under receiver (p, N): nearest plane within kStaticHitDistance among the
// triangles listed in p's grid cell, first in cell order on ties (prt::find_static_hit).
bool find_static_hit(vec3 p, vec3 normal, out StaticHit hit) {
  hit.triangle = 0u;
  hit.weights = vec3(0.0);
  uvec3 size = uvec3(static_grid[4], static_grid[5], static_grid[6]);
  if (size.x == 0u) return false;
  vec3 origin = vec3(uintBitsToFloat(static_grid[0]), uintBitsToFloat(static_grid[1]), uintBitsToFloat(static_grid[2]));
  float cell_edge = uintBitsToFloat(static_grid[3]);
  vec3 cell_f = floor((p - origin) / cell_edge);
  if (any(lessThan(cell_f, vec3(0.0))) || any(greaterThanEqual(cell_f, vec3(size)))) return false;
  uvec3 cell = uvec3(cell_f);
  uint index = (cell.z * size.y + cell.y) * size.x + cell.x;
  uint cells = size.x * size.y * size.z;
  uint lists = kStaticGridHeader + cells + 1u;
  bool found = false;
  float best_distance = kStaticHitDistance;
  uint first = static_grid[kStaticGridHeader + index], last = static_grid[kStaticGridHeader + index + 1u];
  for (uint k = first; k < last; ++k) {
    uint t = static_grid[lists + k];
    StaticTriangle triangle = static_triangles[t];
    vec3 n_t = triangle.normal.xyz;
    if (!(dot(normal, n_t) > kStaticHitCosine)) continue;
    vec3 a = static_positions[triangle.vertices.x].xyz;
    float d = dot(p - a, n_t);
    if (!(abs(d) <= best_distance)) continue;
    if (found && !(abs(d) < best_distance)) continue;
    vec3 v0 = static_positions[triangle.vertices.y].xyz - a, v1 = static_positions[triangle.vertices.z].xyz - a;
    vec3 v2 = (p - d * n_t) - a;
    float d00 = dot(v0, v0), d01 = dot(v0, v1), d11 = dot(v1, v1);
    float d20 = dot(v2, v0), d21 = dot(v2, v1);
    float denominator = d00 * d11 - d01 * d01;
    if (!(denominator > 0.0)) continue;
    float wb = (d11 * d20 - d01 * d21) / denominator, wc = (d00 * d21 - d01 * d20) / denominator;
    float wa = 1.0 - wb - wc;
    if (wa < -kStaticHitBarycentricSlack || wb < -kStaticHitBarycentricSlack || wc < -kStaticHitBarycentricSlack) continue;
    hit.triangle = t;
    hit.weights = vec3(wa, wb, wc);
    best_distance = abs(d);
    found = true;
  }
  return found;
}

// Value i of the hit's record interpolated barycentrically (prt::interpolate_record).
float static_record(StaticHit hit, uvec3 vertices, int i) {
  return hit.weights.x * static_records[vertices.x * STATIC_RECORD_FLOATS + i] +
         hit.weights.y * static_records[vertices.y * STATIC_RECORD_FLOATS + i] +
         hit.weights.z * static_records[vertices.z * STATIC_RECORD_FLOATS + i];
}

// Direct E of a static receiver with visibility O_p = g (prt::shade_static_direct): ratio scales
// the proxy-shadowed light from the environment's own cubes (set 0: the transfer already holds
// the ground) by the static factor; l1 sums O_p · u and κ (B · L). Clamped at 0 per channel.
vec3 shade_static_direct(StaticHit hit, vec3 normal, float g[SH_COUNT]) {
  uvec3 vertices = static_triangles[hit.triangle].vertices.xyz;
  vec3 e = vec3(0.0);
#if STATIC_TRANSFER == 1
  for (int channel = 0; channel < 3; ++channel) {
    float lh[SH_COUNT];
    lighting_lookup(channel, normal, lh);
    float unshadowed = max(kSqrtFourPi * lh[0], 0.0);
    float sum = 0.0;
    for (int i = 0; i < SH_COUNT; ++i) sum += g[i] * lh[i];
    float shadowed = clamp(sum, 0.0, unshadowed);
    float t_di_l = static_record(hit, vertices, 4 * SH_COUNT + 3 + channel);
    e[channel] = unshadowed > 0.0 ? max(shadowed * t_di_l / unshadowed, 0.0) : 0.0;
  }
#else
  // κ = clamp((D · O_p) / (√4π D_0), 0, 1), 1 where static geometry blocks (almost) nothing.
  float blocked_dot = 0.0;
  for (int i = 0; i < SH_COUNT; ++i) blocked_dot += static_record(hit, vertices, 3 * SH_COUNT + i) * g[i];
  float blocked_total = kSqrtFourPi * static_record(hit, vertices, 3 * SH_COUNT);
  float kappa = blocked_total > 1e-6 ? clamp(blocked_dot / blocked_total, 0.0, 1.0) : 1.0;
  for (int channel = 0; channel < 3; ++channel) {
    float sum = 0.0;
    for (int i = 0; i < SH_COUNT; ++i) sum += g[i] * static_record(hit, vertices, channel * SH_COUNT + i);
    e[channel] = max(sum + kappa * static_record(hit, vertices, 4 * SH_COUNT + channel), 0.0);
  }
#endif
  return e;
}

// V_s at p, trilinear between the valid ones of the 8 grid points around it, renormalised
// (prt::sample_visibility); false outside the grid (the receiver keeps l0).
bool sample_static_visibility(vec3 p, out float v[SH_COUNT]) {
  for (int i = 0; i < SH_COUNT; ++i) v[i] = 0.0;
  uvec3 size = uvec3(floatBitsToUint(static_visibility[4]), floatBitsToUint(static_visibility[5]),
                     floatBitsToUint(static_visibility[6]));
  if (size.x == 0u) return false;
  vec3 origin = vec3(static_visibility[0], static_visibility[1], static_visibility[2]);
  vec3 u = (p - origin) / static_visibility[3];
  if (any(lessThan(u, vec3(0.0))) || any(greaterThan(u, vec3(size - 1u)))) return false;
  uvec3 base = min(uvec3(floor(u)), max(size, uvec3(2u)) - 2u);
  vec3 f = u - vec3(base);
  float total = 0.0;
  for (uint corner = 0u; corner < 8u; ++corner) {
    uvec3 o = uvec3(corner & 1u, (corner >> 1u) & 1u, (corner >> 2u) & 1u);
    uvec3 q = min(base + o, size - 1u);
    float w = (o.x == 1u ? f.x : 1.0 - f.x) * (o.y == 1u ? f.y : 1.0 - f.y) * (o.z == 1u ? f.z : 1.0 - f.z);
    uint offset = kStaticVisibilityHeader + ((q.z * size.y + q.y) * size.x + q.x) * uint(SH_COUNT);
    if (static_visibility[offset] < 0.0) continue;  // inside a mesh (kStaticVisibilityInside)
    total += w;
    for (int i = 0; i < SH_COUNT; ++i) v[i] += w * static_visibility[offset + uint(i)];
  }
  if (!(total > kStaticVisibilityMinWeight)) return false;
  for (int i = 0; i < SH_COUNT; ++i) v[i] /= total;
  return true;
}

// Direct E of a receiver in the grid with proxy visibility g: (g ∗ V_s) · LH(N) from p's cube
// set, clamped to [0, unshadowed] per channel as l0 (prt::character_receiver_direct).
vec3 shade_character_direct(vec3 p, vec3 normal, float g[SH_COUNT], float v_static[SH_COUNT]) {
  float visibility[SH_COUNT];
  sh_product(g, v_static, visibility);
  int set = lighting_cube_set(p);
  vec3 e;
  for (int channel = 0; channel < 3; ++channel) {
    float lh[SH_COUNT];
    lighting_lookup(set + channel, normal, lh);
    float sum = 0.0;
    for (int i = 0; i < SH_COUNT; ++i) sum += visibility[i] * lh[i];
    e[channel] = clamp(sum, 0.0, max(kSqrtFourPi * lh[0], 0.0));
  }
  return e;
}

#endif
