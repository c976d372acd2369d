#include "sh/spherical_gaussian.h"

#include <cmath>
#include <numbers>

namespace proxygi::sh {

double sg_area(double sharpness) {
  constexpr double kTwoPi = 2.0 * std::numbers::pi;
  if (sharpness < 1e-8) return 2.0 * kTwoPi * (1.0 - sharpness);  // series: 4π(1 − λ + ...)
  return kTwoPi * -std::expm1(-2.0 * sharpness) / sharpness;
}

double sg_evaluate(const SphericalGaussian& g, const glm::dvec3& direction) {
  return g.amplitude * std::exp(g.sharpness * (glm::dot(direction, g.axis) - 1.0));
}

double sg_integral(const SphericalGaussian& g) { return g.amplitude * sg_area(g.sharpness); }

SphericalGaussian sg_product(const SphericalGaussian& a, const SphericalGaussian& b) {
  const glm::dvec3 sum = a.sharpness * a.axis + b.sharpness * b.axis;
  const double sharpness = glm::length(sum);
  SphericalGaussian out;
  out.axis = sharpness > 0.0 ? sum / sharpness : a.axis;
  out.sharpness = sharpness;
  out.amplitude = a.amplitude * b.amplitude * std::exp(sharpness - a.sharpness - b.sharpness);
  return out;
}

double sg_inner_product(const SphericalGaussian& a, const SphericalGaussian& b) { return sg_integral(sg_product(a, b)); }

double sg_inner_product_approx(const SphericalGaussian& a, const SphericalGaussian& b) {
  const double sum = a.sharpness + b.sharpness;
  const double sharpness = a.sharpness * b.sharpness / sum;
  return 2.0 * std::numbers::pi * a.amplitude * b.amplitude *
         std::exp(sharpness * (glm::dot(a.axis, b.axis) - 1.0)) / sum;
}

double sg_diffuse_irradiance(const SphericalGaussian& g, const glm::dvec3& normal) {
  const SphericalGaussian cosine{normal, kDiffuseLobeSharpness, std::numbers::pi / sg_area(kDiffuseLobeSharpness)};
  return sg_inner_product_approx(g, cosine);
}

}  // namespace proxygi::sh
