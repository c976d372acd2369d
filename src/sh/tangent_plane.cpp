#include "sh/tangent_plane.h"

#include <algorithm>
#include <cmath>

namespace proxygi::sh {

std::optional<ProxyAtReceiver> proxy_at_receiver(const glm::vec3& receiver, const glm::vec3& normal,
                                                 const ProxySphere& sphere, bool continuity_fix) {
  const float r = sphere.radius;
  const glm::vec3 to_center = sphere.center - receiver;
  const float h = glm::dot(to_center, normal);
  if (h <= -r) return std::nullopt;                                 // rule 1
  if (glm::dot(to_center, to_center) < r * r && h <= 0.0f) return std::nullopt;  // rule 2
  ProxySphere adjusted = sphere;
  if (h < r) {  // rule 3
    adjusted.center = sphere.center + normal * (0.5f * (r - h));
    adjusted.radius = 0.5f * (r + h);
    if (continuity_fix && h <= 0.0f) {  // rule 4
      const float rho = std::sqrt(std::max(r * r - h * h, 0.0f));
      const glm::vec3 foot = sphere.center - h * normal;
      const float factor = std::min(1.0f, (glm::length(receiver - foot) - rho) / rho);
      if (!(factor > 0.0f)) return std::nullopt;
      adjusted.radius *= factor;
    }
  }
  const glm::vec3 offset = adjusted.center - receiver;
  const float distance = glm::length(offset);
  if (!(distance > 0.0f) || !(adjusted.radius > 0.0f)) return std::nullopt;
  return ProxyAtReceiver{adjusted, offset / distance, std::min(adjusted.radius / distance, 1.0f)};
}

}  // namespace proxygi::sh
