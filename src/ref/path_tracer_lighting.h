#pragma once
// The environment as the reference path tracer sees it: radiance(direction) for rays that escape,
// with the sun disc kept apart so the integrator can sample it explicitly and weight both
// strategies with MIS.
//
// Kinds (all radiances linear RGB, directions unit world vectors pointing toward the sky):
//  - constant(L): L in every direction (analytic tests, furnace tests).
//  - sky (full): scene::AnalyticSky: the gradient is radiance_without_sun(), the disc is the
//    "sun" (uniform radiance sun_radiance inside the cone dot(d, sun_direction) >= sun_cos_radius).
//  - map (full): the equirectangular image × intensity, looked up at the nearest texel of
//    equirect_uv(world_to_environment · d) (the lookup of the rasterizer's background).
//  - sh (band-limited, the proxy method's lighting): radiance(d) = sum_lm L_lm y_lm(d) per
//    channel, signed: the band-limited lighting rings below zero and the proxy method integrates
//    it unclamped; clamping here made the default scene's open ground 5–21% brighter (blue to
//    red) at order 6 than the proxy method shows, an error of the comparison, not of visibility.
//    L is the scene's environment projected to order `lighting_order` (the reference's own band
//    limit, sh::kMinOrder..sh::kMaxOrder; `proxygi reference` defaults it to the scene's
//    render.sh_order) by render::make_environment_lighting and windowed with
//    sh::apply_ringing_window(order) exactly as render::make_frame_tables does. No sun term: the
//    disc is inside the projection.
// sh and map carry an EquirectSampler (a 128 x 64 table of |SH radiance|, or the map itself)
// for next-event estimation, MIS-combined with BSDF sampling like the sun.
#include <array>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "base/result.h"
#include "image/image.h"
#include "ref/sampling_environment.h"
#include "scene/environment.h"
#include "scene/scene.h"
#include "sh/environment.h"

namespace proxygi::ref {

enum class LightingKind { sh, full };

class EnvironmentLight {
 public:
  static EnvironmentLight constant(const glm::vec3& radiance);
  static EnvironmentLight analytic_sky(const scene::Environment& environment);  // type == sky
  static EnvironmentLight map(image::ImageF image, float intensity, const glm::mat3& world_to_environment);
  // `lighting` is used as given (window it first when that is wanted).
  static EnvironmentLight spherical_harmonics(const sh::RgbSh& lighting);

  // The scene's environment: full (sky or map) or its windowed SH projection of order
  // `lighting_order` (used by the sh kind only). Fails when a map cannot be read or the order is
  // out of range.
  static Result<EnvironmentLight> from_scene(const scene::Scene& scene, LightingKind kind, int lighting_order);

  // Total radiance arriving from `direction` (sun included).
  glm::vec3 radiance(const glm::vec3& direction) const;
  // Radiance without the sun disc (what only BSDF sampling can find).
  glm::vec3 radiance_without_sun(const glm::vec3& direction) const;

  // Importance sampler of radiance_without_sun (sh and map kinds; null for constant and sky,
  // whose smooth gradients cosine sampling handles well).
  const EquirectSampler* importance() const { return sampler_.empty() ? nullptr : &sampler_; }

  bool has_sun() const { return has_sun_; }
  glm::vec3 sun_direction() const { return sun_direction_; }
  float sun_cos_radius() const { return sun_cos_radius_; }
  glm::vec3 sun_radiance() const { return sun_radiance_; }
  bool in_sun(const glm::vec3& direction) const {
    return has_sun_ && glm::dot(direction, sun_direction_) >= sun_cos_radius_;
  }

 private:
  enum class Kind { constant, sky, map, sh };
  EnvironmentLight() = default;

  Kind kind_ = Kind::constant;
  glm::vec3 constant_{0.0f};
  std::optional<scene::AnalyticSky> sky_;
  // map
  image::ImageF map_;
  float map_intensity_ = 1.0f;
  glm::mat3 world_to_environment_{1.0f};
  // sh
  int sh_order_ = 0;
  std::array<std::vector<float>, 3> sh_coefficients_;
  EquirectSampler sampler_;
  // sun (sky only)
  bool has_sun_ = false;
  glm::vec3 sun_direction_{0.0f, 1.0f, 0.0f};
  float sun_cos_radius_ = 1.0f;
  glm::vec3 sun_radiance_{0.0f};
};

}  // namespace proxygi::ref
