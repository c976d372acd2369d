// Shared by the frame's compute passes: the frame constants, the tangent-plane rules and table
// lookups. CPU twins: sh::proxy_at_receiver (the same shared/tangent_plane.h) and src/render/shading.cpp
// (keep identical).
#ifndef PROXYGI_FRAME_COMMON_GLSL
#define PROXYGI_FRAME_COMMON_GLSL

#include "shared/layouts.h"
#include "shared/tangent_plane.h"

const float kPi = 3.14159265358979;
const float kSqrtFourPi = 3.5449077018110318;

float zonal_scale(int band) { return sqrt(4.0 * kPi / float(2 * band + 1)); }

// Tangent-plane rules (shared/tangent_plane.h, one definition with the CPU twin). Returns false
// when the sphere is skipped; else the unit direction to the adjusted center and s = min(r'/|c' − p|, 1).
bool proxy_seen_from(vec3 p, vec3 normal, vec3 center, float radius, out vec3 direction, out float sine) {
  SeenProxy seen = seen_proxy(p, normal, center, radius);
  direction = seen.direction;
  sine = seen.sine;
  return seen.sine > 0.0;
}

// Linear interpolation in a ZH table (sh/occlusion_tables.h ZonalTable layout): `rows` rows over
// s ∈ [0, 1], `order` floats a row. Declared by each shader as a macro over its buffer name.
#define ZONAL_LOOKUP(table, rows, order, s, band, out_value)                      \
  {                                                                             \
    float position_ = clamp(s, 0.0, 1.0) * float((rows) - 1);                   \
    int row_ = min(int(position_), (rows) - 2);                                 \
    float t_ = position_ - float(row_);                                         \
    float low_ = table[row_ * (order) + (band)];                                \
    float high_ = table[(row_ + 1) * (order) + (band)];                         \
    out_value = low_ + t_ * (high_ - low_);                                     \
  }

// Tiled culling (the "tiled compute culling" splat): the 8×8 receivers of a workgroup cull the
// proxy list once against the tile's bounding sphere, so each receiver only visits proxies whose
// sphere of influence η·r reaches its tile. Exact: a proxy that reaches a receiver of the tile
// reaches the tile's bounding sphere, so results equal the full loop. The list keeps ascending
// proxy order (per-lane chunks and a prefix sum, no atomics), so float sums are deterministic.
// Include with FRAME_TILE_CULLING defined and call from uniform control flow.
#ifdef FRAME_TILE_CULLING
shared vec3 tile_low[64];
shared vec3 tile_high[64];
shared uint tile_counts[64];
shared uint tile_proxies[kMaxProxies];
shared uint tile_proxy_count;

// Fills tile_proxies[0 .. tile_proxy_count) for `count` proxies read by proxy_sphere(i).
#define TILE_CULL(proxy_sphere, count, eta, p, valid)                                           \
  {                                                                                            \
    uint lane_ = gl_LocalInvocationIndex;                                                      \
    tile_low[lane_] = (valid) ? (p) : vec3(1e30);                                              \
    tile_high[lane_] = (valid) ? (p) : vec3(-1e30);                                            \
    barrier();                                                                                 \
    for (uint stride_ = 32u; stride_ > 0u; stride_ >>= 1) {                                    \
      if (lane_ < stride_) {                                                                   \
        tile_low[lane_] = min(tile_low[lane_], tile_low[lane_ + stride_]);                     \
        tile_high[lane_] = max(tile_high[lane_], tile_high[lane_ + stride_]);                  \
      }                                                                                        \
      barrier();                                                                               \
    }                                                                                          \
    vec3 tile_center_ = 0.5 * (tile_low[0] + tile_high[0]);                                    \
    float tile_radius_ = 0.5 * length(tile_high[0] - tile_low[0]);                             \
    bool tile_empty_ = tile_low[0].x > tile_high[0].x;                                         \
    uint chunk_ = ((count) + 63u) / 64u;                                                       \
    uint first_ = min(lane_ * chunk_, (count));                                                \
    uint last_ = min(first_ + chunk_, (count));                                                \
    uint matches_ = 0u;                                                                        \
    for (uint c_ = first_; c_ < last_ && !tile_empty_; ++c_) {                                 \
      vec4 s_ = proxy_sphere(c_);                                                              \
      float reach_ = (eta) * s_.w + tile_radius_;                                              \
      vec3 o_ = s_.xyz - tile_center_;                                                         \
      if (dot(o_, o_) < reach_ * reach_) ++matches_;                                           \
    }                                                                                          \
    tile_counts[lane_] = matches_;                                                             \
    barrier();                                                                                 \
    if (lane_ == 0u) {                                                                         \
      uint total_ = 0u;                                                                        \
      for (uint i_ = 0u; i_ < 64u; ++i_) {                                                     \
        uint n_ = tile_counts[i_];                                                             \
        tile_counts[i_] = total_;                                                              \
        total_ += n_;                                                                          \
      }                                                                                        \
      tile_proxy_count = total_;                                                               \
    }                                                                                          \
    barrier();                                                                                 \
    uint write_ = tile_counts[lane_];                                                          \
    for (uint c_ = first_; c_ < last_ && !tile_empty_; ++c_) {                                 \
      vec4 s_ = proxy_sphere(c_);                                                              \
      float reach_ = (eta) * s_.w + tile_radius_;                                              \
      vec3 o_ = s_.xyz - tile_center_;                                                         \
      if (dot(o_, o_) < reach_ * reach_) tile_proxies[write_++] = c_;                          \
    }                                                                                          \
    barrier();                                                                                 \
  }
#endif

#endif
