#pragma once
// Environment lighting as radiance(direction): the analytic sky with a sun disc, and the
// description of an equirectangular HDR/EXR map (the image itself is loaded by src/image).
// Radiance is linear RGB. Directions are unit vectors in world space (glTF: +Y up), pointing
// from the scene toward the sky.
//
// Analytic sky (Environment::type == sky), for a direction d in the environment's own frame
// (world rotated by -rotation_degrees about +Y) with s = sun direction, r = sun angular radius:
//   sky(d) = sky.radiance * mix(horizon_color, zenith_color, sqrt(d.y))   for d.y >= 0
//          = sky.radiance * below_horizon_color                           for d.y <  0
//   sun(d) = sun.color * sun.irradiance / (pi * sin^2 r)   if dot(d, s) >= cos r, else 0
//   radiance(d) = intensity * (sky(d) + sun(d))
// The sun is a uniform disc added on top of the sky, with its radiance set so that a surface
// facing it receives exactly sun.irradiance * sun.color from the disc (integral of L cos over
// the disc = L * pi * sin^2 r). The gradient rises quickly away from the horizon (sqrt); the
// lower hemisphere is uniform, so radiance steps at the horizon and at the disc edge.
// s = (cos e sin a, sin e, cos e cos a) for elevation e and azimuth a, i.e. azimuth 0 is +Z
// and 90 is +X; the environment rotation adds to the azimuth (the gradient does not depend on
// azimuth, so rotation only moves the sun).
//
// This is the model of sh::AnalyticSky (sh/environment.h), whose project_sky projects it to SH:
// fill it with zenith/horizon/ground = zenith_color/horizon_color/below_horizon_color times
// sky.radiance * intensity, sun_direction = sun_direction(env), sun_radius_radians = r and
// sun_radiance = AnalyticSky(env).sun_radiance().
//
// The path tracer samples the sun by picking directions uniformly in the cone
// {d : dot(d, sun_direction()) >= sun_cos_radius()} (solid angle 2 pi (1 - cos r)).
#include <filesystem>

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace proxygi::scene {

// The analytic sky of an Environment with type == sky, with the trigonometry done once so
// radiance() costs a few multiplies (it is called per path-tracer miss and per SH sample).
class AnalyticSky {
 public:
  explicit AnalyticSky(const Environment& environment);  // environment.type must be sky

  // Total radiance arriving from world direction `direction` (unit length).
  glm::vec3 radiance(const glm::vec3& direction) const;
  // The sky gradient alone, without the sun disc.
  glm::vec3 sky_radiance(const glm::vec3& direction) const;

  glm::vec3 sun_direction() const { return sun_direction_; }  // world, unit, toward the sun
  float sun_cos_radius() const { return sun_cos_radius_; }
  glm::vec3 sun_radiance() const { return sun_radiance_; }    // inside the disc, intensity included
  glm::vec3 sun_irradiance() const;  // onto a surface facing the sun, intensity included

 private:
  glm::mat3 world_to_environment_;
  glm::vec3 zenith_, horizon_, below_horizon_;  // colors times sky radiance times intensity
  glm::vec3 sun_direction_;
  float sun_cos_radius_;
  float sun_sin2_radius_;
  glm::vec3 sun_radiance_;
};

// Plain-function form of AnalyticSky(environment).radiance(direction), for one-off callers
// such as SH projection (construct AnalyticSky once in loops).
glm::vec3 sky_radiance(const Environment& environment, const glm::vec3& direction);

// Toward the sun in world space (environment rotation applied).
glm::vec3 sun_direction(const Environment& environment);

// Rotation about +Y by -rotation_degrees: world direction -> environment (map/sky) direction.
glm::mat3 world_to_environment(const Environment& environment);

// Equirectangular mapping of an environment-frame direction (the convention of
// sh/environment.h), u, v in [0, 1]:
//   phi = 2 pi u - pi, theta = pi v, direction = (sin theta sin phi, cos theta, -sin theta cos phi)
// so the center column (u = 0.5) looks along -Z, u = 0.75 along +X (the panorama reads
// unmirrored from inside), and v = 0 is the top row (+Y). Texel (i, j) of a W x H image covers
// u in [i/W, (i+1)/W], v in [j/H, (j+1)/H]; its center is ((i + 0.5) / W, (j + 0.5) / H).
glm::vec2 equirect_uv(const glm::vec3& direction);
glm::vec3 equirect_direction(const glm::vec2& uv);  // inverse; returns a unit vector

// What the renderer needs to light a scene from an HDR/EXR map (Environment::type == map):
// radiance(d) = intensity * image(equirect_uv(world_to_environment * d)).
struct EnvironmentMapInfo {
  std::filesystem::path file;  // resolved against the scene folder
  float intensity = 1.0f;
  float rotation_degrees = 0.0f;
};
EnvironmentMapInfo environment_map_info(const Scene& scene);  // scene.environment.type must be map

}  // namespace proxygi::scene
