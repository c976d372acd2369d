#include "sh/tangent_plane.h"

#include "shaders/shared/tangent_plane.h"

namespace proxygi::sh {

std::optional<ProxyAtReceiver> proxy_at_receiver(const glm::vec3& receiver, const glm::vec3& normal,
                                                 const ProxySphere& sphere) {
  const tangent_plane_rules::SeenProxy seen = tangent_plane_rules::seen_proxy(receiver, normal, sphere.center, sphere.radius);
  if (!(seen.sine > 0.0f)) return std::nullopt;
  return ProxyAtReceiver{{glm::vec3(seen.sphere), seen.sphere.w}, seen.direction, seen.sine};
}

float tangent_plane_fade(float h, float r, float x) { return tangent_plane_rules::tangent_plane_fade(h, r, x); }

}  // namespace proxygi::sh
