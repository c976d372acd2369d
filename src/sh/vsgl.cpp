#include "sh/vsgl.h"

#include <algorithm>
#include <cmath>

#include "image/image.h"
#include "sh/basis.h"
#include "sh/spherical_gaussian.h"

namespace proxygi::sh {

double luminance(const glm::dvec3& rgb) { return image::rec709_luminance(rgb); }

VirtualPointLight triangle_light(const glm::dvec3 (&positions)[3], const glm::dvec3 (&normals)[3],
                                 const glm::dvec3& albedo, std::span<const std::array<float, 9>, 3> irradiance_order3,
                                 const glm::dvec3& exposures) {
  const glm::dvec3 face = glm::cross(positions[1] - positions[0], positions[2] - positions[0]);
  const double area = 0.5 * glm::length(face);
  const glm::dvec3 summed = normals[0] + normals[1] + normals[2];
  VirtualPointLight vpl;
  vpl.position = (positions[0] + positions[1] + positions[2]) / 3.0;
  vpl.normal = glm::length(summed) > 0.0 ? glm::normalize(summed) : area > 0.0 ? face / (2.0 * area) : glm::dvec3(0, 1, 0);
  double basis[9];
  evaluate_basis<3>(vpl.normal, basis);
  const double exposure = (exposures.x + exposures.y + exposures.z) / 3.0;
  for (int c = 0; c < 3; ++c) {
    double irradiance = 0.0;
    for (int i = 0; i < 9; ++i) irradiance += basis[i] * double(irradiance_order3[std::size_t(c)][std::size_t(i)]);
    vpl.flux[c] = albedo[c] * std::max(irradiance, 0.0) * area * exposure;
  }
  return vpl;
}

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
