#include "ref/path_tracer_lighting.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "render/environment_lighting.h"
#include "scene/environment.h"
#include "sh/basis.h"
#include "sh/convolution.h"

namespace proxygi::ref {
namespace {

float channel_mean(const glm::vec3& rgb) { return (rgb.r + rgb.g + rgb.b) / 3.0f; }

}  // namespace

EnvironmentLight EnvironmentLight::constant(const glm::vec3& radiance) {
  EnvironmentLight light;
  light.kind_ = Kind::constant;
  light.constant_ = radiance;
  return light;
}

EnvironmentLight EnvironmentLight::analytic_sky(const scene::Environment& environment) {
  const scene::AnalyticSky sky(environment);
  EnvironmentLight light;
  light.kind_ = Kind::sky;
  light.sky_ = sky;
  light.sun_direction_ = sky.sun_direction();
  light.sun_cos_radius_ = sky.sun_cos_radius();
  light.sun_radiance_ = sky.sun_radiance();
  light.has_sun_ = glm::dot(light.sun_radiance_, glm::vec3(1.0f)) > 0.0f;
  return light;
}

EnvironmentLight EnvironmentLight::map(image::ImageF image, float intensity, const glm::mat3& world_to_environment) {
  EnvironmentLight light;
  light.kind_ = Kind::map;
  light.map_ = std::move(image);
  light.map_intensity_ = intensity;
  light.world_to_environment_ = world_to_environment;
  std::vector<float> weights(light.map_.pixels.size());
  for (std::size_t i = 0; i < weights.size(); ++i) weights[i] = channel_mean(glm::vec3(light.map_.pixels[i]));
  light.sampler_ = EquirectSampler(light.map_.width, light.map_.height, weights, glm::transpose(world_to_environment));
  return light;
}

EnvironmentLight EnvironmentLight::spherical_harmonics(const sh::RgbSh& lighting) {
  EnvironmentLight light;
  light.kind_ = Kind::sh;
  light.sh_order_ = lighting.order;
  for (int c = 0; c < 3; ++c)
    light.sh_coefficients_[std::size_t(c)].assign(lighting.channels[std::size_t(c)].begin(),
                                                  lighting.channels[std::size_t(c)].end());
  // Tabulate the (smooth) band-limited radiance at texel centers for importance sampling.
  constexpr int kWidth = 128, kHeight = 64;
  std::vector<float> weights(std::size_t(kWidth) * kHeight);
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      const glm::vec3 d = scene::equirect_direction({(x + 0.5f) / float(kWidth), (y + 0.5f) / float(kHeight)});
      weights[std::size_t(y) * kWidth + std::size_t(x)] = std::abs(channel_mean(light.radiance_without_sun(d)));
    }
  light.sampler_ = EquirectSampler(kWidth, kHeight, weights);
  return light;
}

Result<EnvironmentLight> EnvironmentLight::from_scene(const scene::Scene& scene, LightingKind kind,
                                                     int lighting_order) {
  if (kind == LightingKind::sh) {
    const int order = lighting_order;
    if (order < sh::kMinOrder || order > sh::kMaxOrder)
      return make_error("lighting order " + std::to_string(order) + " out of range (" + std::to_string(sh::kMinOrder) +
                        ".." + std::to_string(sh::kMaxOrder) + ")");
    auto environment = render::make_environment_lighting(scene, order);
    if (!environment) return environment.error();
    sh::RgbSh lighting = std::move(environment->lighting);
    for (auto& channel : lighting.channels) sh::apply_ringing_window(order, channel);  // as make_frame_tables
    return spherical_harmonics(lighting);
  }
  if (scene.environment.type == scene::Environment::Type::sky) return analytic_sky(scene.environment);
  const scene::EnvironmentMapInfo info = scene::environment_map_info(scene);
  auto image = image::read_image(info.file);
  if (!image) return image.error();
  return map(std::move(*image), info.intensity, scene::world_to_environment(scene.environment));
}

glm::vec3 EnvironmentLight::radiance_without_sun(const glm::vec3& direction) const {
  switch (kind_) {
    case Kind::constant: return constant_;
    case Kind::sky: return sky_->sky_radiance(direction);
    case Kind::map: {
      const glm::vec2 uv = scene::equirect_uv(world_to_environment_ * direction);
      const int x = std::clamp(int(uv.x * float(map_.width)), 0, map_.width - 1);
      const int y = std::clamp(int(uv.y * float(map_.height)), 0, map_.height - 1);
      return glm::vec3(map_.at(x, y)) * map_intensity_;
    }
    case Kind::sh: {
      float basis[sh::kMaxOrder * sh::kMaxOrder];
      const int count = sh_order_ * sh_order_;
      sh::evaluate_basis(sh_order_, direction, std::span<float>(basis, std::size_t(count)));
      glm::vec3 out(0.0f);
      for (int c = 0; c < 3; ++c) {
        const std::vector<float>& coefficients = sh_coefficients_[std::size_t(c)];
        float sum = 0.0f;
        for (int i = 0; i < count; ++i) sum += coefficients[std::size_t(i)] * basis[i];
        out[c] = sum;  // signed, as the proxy method sees it (header)
      }
      return out;
    }
  }
  return glm::vec3(0.0f);
}

glm::vec3 EnvironmentLight::radiance(const glm::vec3& direction) const {
  glm::vec3 out = radiance_without_sun(direction);
  if (in_sun(direction)) out += sun_radiance_;
  return out;
}

}  // namespace proxygi::ref
