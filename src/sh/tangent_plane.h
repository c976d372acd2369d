#pragma once
// The tangent-plane rules for a sphere proxy that straddles the receiver's tangent plane or
// contains the receiver: the CPU twin of the GPU passes' proxy_seen_from. Both run the one
// definition in shaders/shared/tangent_plane.h (the rules, their units and why they are
// continuous are documented there).
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
                                                 const ProxySphere& sphere);

// φ of the rules (0 = skipped, 1 = the inscribed sphere unscaled) for a sphere of radius r whose
// centre is h above the receiver's plane, x from the receiver along the plane (-r < h < r).
float tangent_plane_fade(float h, float r, float x);

}  // namespace proxygi::sh
