#pragma once
// Spherical Gaussians (SG), the lobes of the VSGL bounce method (papers/vsgl-tokuyoshi.md §1,
// notes/prt-vsgl.md §3):  G(ω; ξ, λ, a) = a e^{λ(ω·ξ − 1)},  ω and ξ unit vectors, λ ≥ 0
// (dimensionless sharpness), a the amplitude (the lobe's value on its axis, any unit).
//
//   SphericalGaussian light{axis, 8.0, 2.5};
//   double total = sg_integral(light);                       // a A(λ)
//   double e = sg_diffuse_irradiance(light, normal);          // ≈ ∫ G max(ω·n, 0) dω
//
// Every function is double precision and pure; the GLSL twins are in shaders/vsgl_lights.comp
// and shaders/indirect.comp (the vsgl variant).
#include <glm/glm.hpp>

namespace proxygi::sh {

struct SphericalGaussian {
  glm::dvec3 axis{0.0, 0.0, 1.0};  // ξ, unit
  double sharpness = 0.0;          // λ ≥ 0
  double amplitude = 1.0;          // a
};

// λ_d of the seed's eq. 1: max(ω·n, 0)/π ≈ G(ω; n, λ_d)/A(λ_d) (least squares, tested).
inline constexpr double kDiffuseLobeSharpness = 2.0;

// A(λ) = ∫ e^{λ(ω·ξ−1)} dω = (2π/λ)(1 − e^{−2λ}); 4π at λ = 0 (evaluated without cancellation).
double sg_area(double sharpness);
double sg_evaluate(const SphericalGaussian& g, const glm::dvec3& direction);
double sg_integral(const SphericalGaussian& g);  // a A(λ)

// The product of two SGs is an SG (exact): axis (λ1ξ1 + λ2ξ2)/λm, λm = ‖λ1ξ1 + λ2ξ2‖,
// amplitude a1 a2 e^{λm − λ1 − λ2}. When λm = 0 the axis is ξ1 (the product is a constant).
SphericalGaussian sg_product(const SphericalGaussian& a, const SphericalGaussian& b);
// ∫ G_a G_b dω exactly: a_a a_b A(λm) e^{λm − λa − λb}.
double sg_inner_product(const SphericalGaussian& a, const SphericalGaussian& b);
// Iwasaki et al.'s approximation the seed uses (§3.2): 2π a_a a_b G(ξa·ξb; λaλb/(λa+λb)) /
// (λa + λb). Exact as either λ → ∞ with the other fixed; λa + λb must be > 0.
double sg_inner_product_approx(const SphericalGaussian& a, const SphericalGaussian& b);

// The diffuse convolution of the seed: irradiance E = ∫ G max(ω·n, 0) dω with the clamped
// cosine replaced by π G(ω; n, λ_d)/A(λ_d) (eq. 1) and the product integral by Iwasaki's
// approximation. (The seed then also sets A(λ_d) ≈ π; this keeps A(λ_d) exact.)
double sg_diffuse_irradiance(const SphericalGaussian& g, const glm::dvec3& normal);

}  // namespace proxygi::sh
