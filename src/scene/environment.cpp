#include "scene/environment.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/constants.hpp>

#include "base/check.h"

namespace proxygi::scene {
namespace {

glm::mat3 rotation_y(float degrees) {
  const float a = glm::radians(degrees);
  const float c = std::cos(a);
  const float s = std::sin(a);
  // Columns: images of +X, +Y, +Z. Positive angles turn +Z toward +X.
  return glm::mat3(glm::vec3(c, 0.0f, -s), glm::vec3(0.0f, 1.0f, 0.0f), glm::vec3(s, 0.0f, c));
}

glm::vec3 unrotated_sun_direction(const Sun& sun) {
  const float e = glm::radians(sun.elevation_degrees);
  const float a = glm::radians(sun.azimuth_degrees);
  return glm::vec3(std::cos(e) * std::sin(a), std::sin(e), std::cos(e) * std::cos(a));
}

}  // namespace

glm::mat3 world_to_environment(const Environment& environment) {
  return rotation_y(-environment.rotation_degrees);
}

glm::vec3 sun_direction(const Environment& environment) {
  return glm::normalize(rotation_y(environment.rotation_degrees) * unrotated_sun_direction(environment.sun));
}

AnalyticSky::AnalyticSky(const Environment& environment)
    : world_to_environment_(world_to_environment(environment)),
      zenith_(environment.sky.zenith_color * (environment.sky.radiance * environment.intensity)),
      horizon_(environment.sky.horizon_color * (environment.sky.radiance * environment.intensity)),
      below_horizon_(environment.sky.below_horizon_color * (environment.sky.radiance * environment.intensity)),
      sun_direction_(scene::sun_direction(environment)) {
  PROXYGI_CHECK(environment.type == Environment::Type::sky, "AnalyticSky needs a sky environment");
  const float r = glm::radians(environment.sun.angular_radius_degrees);
  PROXYGI_CHECK(r > 0.0f, "sun angular radius must be positive (validate the scene first)");
  sun_cos_radius_ = std::cos(r);
  sun_sin2_radius_ = std::sin(r) * std::sin(r);
  sun_radiance_ = environment.sun.color *
                  (environment.sun.irradiance * environment.intensity / (glm::pi<float>() * sun_sin2_radius_));
}

glm::vec3 AnalyticSky::sky_radiance(const glm::vec3& direction) const {
  const float y = std::clamp((world_to_environment_ * direction).y, -1.0f, 1.0f);
  if (y >= 0.0f) return glm::mix(horizon_, zenith_, std::sqrt(y));
  return below_horizon_;
}

glm::vec3 AnalyticSky::radiance(const glm::vec3& direction) const {
  glm::vec3 result = sky_radiance(direction);
  if (glm::dot(direction, sun_direction_) >= sun_cos_radius_) result += sun_radiance_;
  return result;
}

glm::vec3 AnalyticSky::sun_irradiance() const {
  return sun_radiance_ * (glm::pi<float>() * sun_sin2_radius_);
}

glm::vec3 sky_radiance(const Environment& environment, const glm::vec3& direction) {
  return AnalyticSky(environment).radiance(direction);
}

glm::vec2 equirect_uv(const glm::vec3& direction) {
  const glm::vec3 d = glm::normalize(direction);
  // Inverse of equirect_direction: sin phi ~ d.x, cos phi ~ -d.z.
  float u = (std::atan2(d.x, -d.z) + glm::pi<float>()) / glm::two_pi<float>();
  u -= std::floor(u);  // phi = pi and -pi are the same seam column; keep u in [0, 1)
  const float v = std::acos(std::clamp(d.y, -1.0f, 1.0f)) / glm::pi<float>();
  return glm::vec2(u, v);
}

glm::vec3 equirect_direction(const glm::vec2& uv) {
  const float phi = glm::two_pi<float>() * uv.x - glm::pi<float>();
  const float theta = glm::pi<float>() * uv.y;
  const float s = std::sin(theta);
  return glm::normalize(glm::vec3(s * std::sin(phi), std::cos(theta), -s * std::cos(phi)));
}

EnvironmentMapInfo environment_map_info(const Scene& scene) {
  PROXYGI_CHECK(scene.environment.type == Environment::Type::map, "environment is not a map");
  return EnvironmentMapInfo{resolve_scene_path(scene, scene.environment.map_path),
                            scene.environment.intensity, scene.environment.rotation_degrees};
}

}  // namespace proxygi::scene
