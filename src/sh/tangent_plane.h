#pragma once
// Replacement rules for a sphere proxy that straddles the receiver's tangent plane or contains
// the receiver (notes sh-math.md section 5; the GPU splat shader mirrors this function).
// Receiver p with unit normal N, sphere (c, r); h = (c - p) . N, D = |c - p|.
//   1. h <= -r (fully below the plane)                  -> skip
//   2. D < r and h <= 0 (receiver inside, centre below)  -> skip
//   3. -r < h < r: the sphere inscribed in the part above the plane along N,
//        c' = c + N (r - h) / 2,  r' = (r + h) / 2  (keeps the top point c + rN; touches the
//        plane at q1 = c - hN); continuous with rule 1 (r' -> 0) and with no change (h -> r).
//   4. (continuity fix) if h <= 0: rho = sqrt(r^2 - h^2), r' *= min(1, (|p - q1| - rho) / rho),
//        skip when that factor <= 0, so the proxy fades out as p approaches the cut circle
//        instead of popping when p enters the sphere.
//   5. s = sin(alpha) = min(r' / |c' - p|, 1), direction (c' - p) / |c' - p|.
// Known remaining discontinuity: rule 4 applies for h <= 0 only, so at h = 0 the factor jumps
// for receivers within 2 rho of q1 (tested and measured in tests/sh/tangent_plane_test.cpp).
#include <optional>

#include <glm/glm.hpp>

namespace proxygi::sh {

struct ProxySphere {
  glm::vec3 center{0.0f};
  float radius = 0.0f;
};

// What the receiver accumulates for one proxy: the adjusted sphere, its direction and s.
struct ProxyAtReceiver {
  ProxySphere sphere;   // after the rules
  glm::vec3 direction;  // unit, from p to the adjusted centre
  float sine = 0.0f;    // s = sin(alpha) = min(r' / d', 1), the table coordinate
};

// std::nullopt = skip the proxy at this receiver. normal must be unit.
std::optional<ProxyAtReceiver> proxy_at_receiver(const glm::vec3& receiver, const glm::vec3& normal,
                                                 const ProxySphere& sphere, bool continuity_fix = true);

}  // namespace proxygi::sh
