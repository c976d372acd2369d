// The tangent-plane rules (notes/sh-math.md §5, made continuous for issue 16 / stability F2): the
// sphere a receiver accumulates in place of a proxy that straddles its tangent plane or contains
// it. One definition, compiled as GLSL (frame_common.glsl's proxy_seen_from, every splat, gather,
// AO and indirect pass) and as C++ with GLM (sh::proxy_at_receiver, the CPU twins).
// Receiver p with unit normal N, sphere (c, r), metres, any one space; h = (c − p)·N.
//   1. h ≥ r: the sphere unchanged.
//   2. h ≤ −r: skipped (fully below the plane).
//   3. −r < h < r: the sphere inscribed in the part above the plane along N,
//        c′ = c + N (r − h)/2, r′ = (r + h)/2 (keeps the top point; touches the plane at q = c − hN),
//      with r′ scaled by √φ (the blocked light of a small cap goes with r′², so with φ):
//        x = |p − q|, ρ = √(r² − h²) (the circle where the sphere cuts the plane), t = max(h, 0)/r,
//        φ = min(1, t + (1 − t)·max(0, x/ρ − 1)),    skipped when φ ≤ 0.
//      h ≤ 0: φ = x/ρ − 1 fades the proxy out as p reaches the cut circle, where p enters the
//      sphere (the old rule "p inside, centre below: skip" is φ ≤ 0). h > 0: p inside the sphere
//      keeps φ ≥ t, so a sphere sinking through the receiver fades from full (h = r) to nothing
//      (h = 0) instead of switching off at h = 0. φ is continuous in p, c and r everywhere.
//   4. s = sin α = min(r″/|c″ − p|, 1), the table coordinate, and the unit direction to c″.
#ifndef PROXYGI_SHADERS_SHARED_TANGENT_PLANE_H
#define PROXYGI_SHADERS_SHARED_TANGENT_PLANE_H

#ifdef __cplusplus
#include <glm/glm.hpp>
namespace proxygi::tangent_plane_rules {
using glm::vec3;
using glm::vec4;
using glm::dot;
using glm::length;
using glm::max;
using glm::min;
using glm::sqrt;
#define PROXYGI_TANGENT_PLANE_FN inline
#else
#define PROXYGI_TANGENT_PLANE_FN
#endif

// What a receiver sees of one proxy: `sphere` is c″ (xyz) and r″ (w); sine 0 = skipped.
struct SeenProxy {
  vec4 sphere;
  vec3 direction;  // unit, from p to c″ (+N when skipped)
  float sine;      // s = min(r″/|c″ − p|, 1)
};

// φ of rule 3 for a receiver at distance x from the foot point q (h, r, x in metres, −r < h < r).
PROXYGI_TANGENT_PLANE_FN float tangent_plane_fade(float h, float r, float x) {
  float rho = sqrt(max(r * r - h * h, 0.0f));
  float t = max(h, 0.0f) / r;
  if (!(rho > 0.0f)) return 1.0f;  // h = ±r to float precision: rule 1 or 2 takes over
  return min(1.0f, t + (1.0f - t) * max(0.0f, x / rho - 1.0f));
}

PROXYGI_TANGENT_PLANE_FN SeenProxy seen_proxy(vec3 p, vec3 normal, vec3 center, float radius) {
  SeenProxy seen;
  seen.sphere = vec4(center, radius);
  seen.direction = normal;
  seen.sine = 0.0f;
  vec3 to_center = center - p;
  float h = dot(to_center, normal);
  if (h <= -radius) return seen;
  vec3 seen_center = center;
  float seen_radius = radius;
  if (h < radius) {
    vec3 foot = center - h * normal;
    float fade = tangent_plane_fade(h, radius, length(p - foot));
    if (!(fade > 0.0f)) return seen;
    seen_center = center + normal * (0.5f * (radius - h));
    seen_radius = 0.5f * (radius + h) * sqrt(fade);
  }
  vec3 offset = seen_center - p;
  float distance_to_center = length(offset);
  if (!(distance_to_center > 0.0f) || !(seen_radius > 0.0f)) return seen;
  seen.sphere = vec4(seen_center, seen_radius);
  seen.direction = offset / distance_to_center;
  seen.sine = min(seen_radius / distance_to_center, 1.0f);
  return seen;
}

#undef PROXYGI_TANGENT_PLANE_FN
#ifdef __cplusplus
}  // namespace proxygi::tangent_plane_rules
#endif

#endif
