#include "render/baselines.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "sh/occlusion_tables.h"
#include "sh/tangent_plane.h"

namespace proxygi::render {
namespace {

constexpr float kSqrtFourPi = 3.5449077018110318f;

}  // namespace

VertexReceiver vertex_receiver(const glm::vec3& position, const glm::vec3& normal) {
  const float length = glm::length(normal);
  return {glm::vec4(position, 1.0f), glm::vec4(length > 0.0f ? normal / length : glm::vec3(0.0f, 1.0f, 0.0f), 0.0f)};
}

glm::vec3 interpolate_triangle(const glm::vec3& x, const glm::vec3& a, const glm::vec3& b, const glm::vec3& c,
                               const glm::vec3& value_a, const glm::vec3& value_b, const glm::vec3& value_c) {
  const glm::vec3 n = glm::cross(b - a, c - a);
  const float area = glm::dot(n, n);
  if (area <= 0.0f) return (value_a + value_b + value_c) / 3.0f;
  const float u = glm::dot(glm::cross(c - b, x - b), n) / area;  // weight of a
  const float v = glm::dot(glm::cross(a - c, x - c), n) / area;  // weight of b
  return u * value_a + v * value_b + (1.0f - u - v) * value_c;
}

glm::vec3 unshadowed_irradiance(const FrameTables& tables, const glm::vec3& p, const glm::vec3& normal) {
  const int order = tables.settings.sh_order;
  std::vector<float> lh(std::size_t(order * order));
  glm::vec3 irradiance(0.0f);
  const int set = lighting_cube_set(p);
  for (int channel = 0; channel < 3; ++channel) {
    lookup_lighting_cube(tables.lighting_cube[std::size_t(set + channel)], normal, lh);
    irradiance[channel] = kSqrtFourPi * lh[0];
  }
  return irradiance;
}

AmbientOcclusionResult ambient_occlusion(const FrameTables& tables, const glm::vec3& p, const glm::vec3& normal,
                                         std::span<const Sphere> spheres) {
  const float eta = tables.shadow_eta;
  const float minimum_sine = 1.0f / eta;
  AmbientOcclusionResult result;
  for (const Sphere& sphere : spheres) {
    const glm::vec3 offset = sphere.center - p;
    const float reach = eta * sphere.radius;
    if (glm::dot(offset, offset) >= reach * reach) continue;  // outside the sphere of influence
    const auto seen = sh::proxy_at_receiver(p, normal, {sphere.center, sphere.radius});
    if (!seen || seen->sine <= minimum_sine) continue;
    const float covered = sh::influence_fade_weight(seen->sine, eta, tables.log_occlusion.rows) * seen->sine *
                          seen->sine * std::max(glm::dot(normal, seen->direction), 0.0f);
    const float kept = 1.0f - std::clamp(covered, 0.0f, 1.0f);
    result.unoccluded *= sphere.weight == 1.0f ? kept : std::pow(kept, sphere.weight);  // a fade: Π (1 − a_i)^w_i
  }
  result.irradiance = glm::max(result.unoccluded * unshadowed_irradiance(tables, p, normal), glm::vec3(0.0f));
  return result;
}

}  // namespace proxygi::render
