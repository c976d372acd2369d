#include "render/proxy_rules.h"

#include <algorithm>
#include <cmath>

namespace proxygi::render {

std::optional<SeenSphere> proxy_seen_from(const glm::vec3& p, const glm::vec3& normal, const glm::vec3& center,
                                          float radius) {
  const glm::vec3 to_center = center - p;
  const float height = glm::dot(to_center, normal);
  if (height <= -radius) return std::nullopt;                                    // rule 1
  if (glm::dot(to_center, to_center) < radius * radius && height <= 0.0f) return std::nullopt;  // rule 2
  glm::vec3 seen_center = center;
  float seen_radius = radius;
  if (height < radius) {                                                         // rule 3
    seen_center = center + normal * (0.5f * (radius - height));
    seen_radius = 0.5f * (radius + height);
    if (height <= 0.0f) {                                                        // rule 4
      const float circle = std::sqrt(std::max(radius * radius - height * height, 0.0f));
      const glm::vec3 foot = center - height * normal;
      const float factor = circle > 0.0f ? std::min(1.0f, (glm::length(p - foot) - circle) / circle) : 1.0f;
      if (factor <= 0.0f) return std::nullopt;
      seen_radius *= factor;
    }
  }
  const glm::vec3 offset = seen_center - p;
  const float distance = glm::length(offset);
  if (distance <= 0.0f || seen_radius <= 0.0f) return std::nullopt;
  SeenSphere seen;
  seen.direction = offset / distance;
  seen.distance = distance;
  seen.radius = seen_radius;
  seen.sine = std::min(seen_radius / distance, 1.0f);
  return seen;
}

}  // namespace proxygi::render
