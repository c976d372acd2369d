#include "sh/vsgl.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "image/image.h"
#include "sh/spherical_gaussian.h"

namespace proxygi::sh {
namespace {
constexpr double kPi = std::numbers::pi;
}

double luminance(const glm::dvec3& rgb) { return image::rec709_luminance(rgb); }

void add_light(VsglSums& sums, const VirtualPointLight& light, const glm::dvec3& origin) {
  const double w = luminance(light.flux);
  const glm::dvec3 x = light.position - origin;
  constexpr double kShrink = kDiffuseLobeSharpness / (kDiffuseLobeSharpness + 1.0);
  sums.weight += w;
  sums.weighted_axis += w * kShrink * light.normal;
  sums.weighted_position += w * x;
  sums.weighted_square += w * glm::dot(x, x);
  sums.flux += light.flux;
}

std::optional<Vsgl> fit_vsgl(const VsglSums& sums, const glm::dvec3& origin) {
  if (!(sums.weight > 0.0)) return std::nullopt;
  Vsgl out;
  const glm::dvec3 mean_axis = sums.weighted_axis / sums.weight;  // ξ̄_v
  // ‖ξ̄_v‖ ≤ λ_d/(λ_d + 1) < 1 for unit normals; clamped against rounding.
  const double length = std::min(glm::length(mean_axis), 1.0 - 1e-9);
  out.axis = length > 0.0 ? mean_axis / length : glm::dvec3(0.0, 0.0, 1.0);
  out.sharpness = length / (1.0 - length);
  out.amplitude = sums.flux / sg_area(out.sharpness);
  const glm::dvec3 mean = sums.weighted_position / sums.weight;
  out.mean = origin + mean;
  out.variance = std::max(sums.weighted_square / sums.weight - glm::dot(mean, mean), 0.0);
  return out;
}

std::optional<IncomingLobe> vsgl_incoming(const Vsgl& light, const glm::dvec3& receiver) {
  const glm::dvec3 offset = light.mean - receiver;
  const double distance2 = glm::dot(offset, offset);
  if (!(distance2 > 0.0)) return std::nullopt;
  const glm::dvec3 toward = offset / std::sqrt(distance2);  // ξ_μ
  const double variance = std::max(light.variance, kVsglMinRelativeVariance * distance2);
  const double spread = distance2 / variance;                // λ_σ (eq. 6, radius ‖μ_v − x_p‖)
  // Eq. 7: the product of G(ω; −ξ_v, λ_v) and G(ω; ξ_μ, λ_σ).
  const glm::dvec3 sum = spread * toward - light.sharpness * light.axis;
  const double sharpness = glm::length(sum);
  // λ_in − λ_v − λ_σ without cancelling the large λ_σ: (λ_in² − (λ_σ + λ_v)²)/(λ_in + λ_σ + λ_v).
  const double exponent =
      -2.0 * spread * light.sharpness * (1.0 + glm::dot(toward, light.axis)) / (sharpness + spread + light.sharpness);
  IncomingLobe out;
  out.axis = sharpness > 0.0 ? sum / sharpness : toward;
  out.sharpness = sharpness;
  out.amplitude = light.amplitude * (std::exp(exponent) / (2.0 * kPi * variance));
  return out;
}

glm::dvec3 vsgl_irradiance(const Vsgl& light, const glm::dvec3& receiver, const glm::dvec3& normal) {
  const auto lobe = vsgl_incoming(light, receiver);
  if (!lobe) return glm::dvec3(0.0);
  const SphericalGaussian unit{lobe->axis, lobe->sharpness, 1.0};
  return lobe->amplitude * sg_diffuse_irradiance(unit, normal);
}

glm::dvec3 gather_vpl_irradiance(std::span<const VirtualPointLight> lights, const glm::dvec3& receiver,
                                 const glm::dvec3& normal) {
  glm::dvec3 sum(0.0);
  for (const VirtualPointLight& light : lights) {
    const glm::dvec3 offset = light.position - receiver;
    const double distance2 = glm::dot(offset, offset);
    if (!(distance2 > 0.0)) continue;
    const glm::dvec3 direction = offset / std::sqrt(distance2);
    const double emitted = std::max(-glm::dot(direction, light.normal), 0.0) / kPi;
    sum += light.flux * (emitted * std::max(glm::dot(direction, normal), 0.0) / distance2);
  }
  return sum;
}

}  // namespace proxygi::sh
