#include "render/environment_lighting.h"

#include <algorithm>
#include <cmath>

#include "scene/environment.h"

namespace proxygi::render {

sh::AnalyticSky to_sh_sky(const scene::Environment& environment) {
  const scene::AnalyticSky sky(environment);
  const double scale = double(environment.sky.radiance) * double(environment.intensity);
  sh::AnalyticSky out;
  out.zenith = glm::dvec3(environment.sky.zenith_color) * scale;
  out.horizon = glm::dvec3(environment.sky.horizon_color) * scale;
  out.ground = glm::dvec3(environment.sky.below_horizon_color) * scale;
  out.sun_direction = glm::dvec3(sky.sun_direction());
  out.sun_radius_radians = std::acos(std::clamp(double(sky.sun_cos_radius()), -1.0, 1.0));
  out.sun_radiance = glm::dvec3(sky.sun_radiance());
  return out;
}

SunInput scene_sun(const scene::Scene& scene, int order) {
  SunInput sun;
  if (scene.environment.type != scene::Environment::Type::sky) return sun;
  const sh::AnalyticSky sky = to_sh_sky(scene.environment);
  sun.present = true;
  sun.lighting = sh::project_sun_disc(order, sky);
  sun.direction = glm::vec3(sky.sun_direction);
  sun.irradiance = scene::AnalyticSky(scene.environment).sun_irradiance();
  return sun;
}

Result<EnvironmentLighting> make_environment_lighting(const scene::Scene& scene, int order, int panorama_width) {
  EnvironmentLighting out;
  const int width = std::max(panorama_width, 8), height = width / 2;
  out.background = image::ImageF(width, height);
  if (scene.environment.type == scene::Environment::Type::sky) {
    const scene::AnalyticSky sky(scene.environment);
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x) {
        const glm::vec3 direction = scene::equirect_direction({(x + 0.5f) / float(width), (y + 0.5f) / float(height)});
        out.background.at(x, y) = glm::vec4(sky.radiance(direction), 1.0f);
      }
    out.lighting = sh::project_sky(order, to_sh_sky(scene.environment));
    return out;
  }
  const scene::EnvironmentMapInfo info = scene::environment_map_info(scene);
  auto map = image::read_image(info.file);
  if (!map) return map.error();
  // World-frame panorama: each texel looks up the map in the environment's own frame.
  const glm::mat3 to_environment = scene::world_to_environment(scene.environment);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const glm::vec3 world = scene::equirect_direction({(x + 0.5f) / float(width), (y + 0.5f) / float(height)});
      const glm::vec2 uv = scene::equirect_uv(to_environment * world);
      const int u = std::clamp(int(uv.x * float(map->width)), 0, map->width - 1);
      const int v = std::clamp(int(uv.y * float(map->height)), 0, map->height - 1);
      out.background.at(x, y) = glm::vec4(glm::vec3(map->at(u, v)) * info.intensity, 1.0f);
    }
  out.lighting = sh::project_equirect(order, out.background);
  return out;
}

}  // namespace proxygi::render
