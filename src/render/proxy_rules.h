#pragma once
// Which part of a proxy sphere a receiver sees: the tangent-plane replacement rules
// (notes/sh-math.md §5, shared by both published implementations). Only the hemisphere above
// the receiver's tangent plane matters (the clamped cosine is zero below it), and a sphere that
// crosses the plane would put large blocking mass below the horizon and ring.
//
// With h = (c − p)·N and D = |c − p|:
//   1. h ≤ −r (fully below the plane)                   → skip
//   2. D < r and h ≤ 0 (p inside, center not above)     → skip
//   3. −r < h < r (straddling; includes p inside with the center above):
//      c' = c + N (r − h)/2, r' = (r + h)/2  (the sphere inscribed in the part above the plane;
//      keeps the top point c + rN, touches the plane at q1 = c − hN)
//   4. if h ≤ 0 after 3: ρ = √(r² − h²), r' *= min(1, (|p − q1| − ρ)/ρ), skip if that factor ≤ 0
//      (removes the pop when p crosses into the sphere).
// The GLSL twin is shaders/frame_common.glsl proxy_seen_from(); keep them identical.
#include <optional>

#include <glm/glm.hpp>

namespace proxygi::render {

struct SeenSphere {
  glm::vec3 direction;  // unit, from p toward the (adjusted) center
  float distance = 0;   // |c' − p| (m)
  float radius = 0;     // r' (m)
  float sine = 0;       // s = min(r'/distance, 1): sine of the cap half-angle
};

std::optional<SeenSphere> proxy_seen_from(const glm::vec3& p, const glm::vec3& normal, const glm::vec3& center,
                                          float radius);

}  // namespace proxygi::render
