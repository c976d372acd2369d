#pragma once
// Virtual spherical Gaussian lights (VSGL; papers/vsgl-tokuyoshi.md §2–3, notes/prt-vsgl.md §3):
// a set of diffuse virtual point lights (VPLs) summarised by one SG of radiant intensity and one
// isotropic Gaussian of position, then evaluated at a receiver in closed form, without visibility.
//
//   VsglSums sums;                                   // positions relative to `origin`
//   for (const VirtualPointLight& v : vpls) add_light(sums, v, origin);
//   if (auto light = fit_vsgl(sums, origin)) E = vsgl_irradiance(*light, p, n);
//
// The four errata of the seed (notes §3) are corrected here, each with a test
// (tests/sh/vsgl_test.cpp): the sums are Σw, Σw ξ̄, Σw x, Σw‖x‖² (the seed lists Σw ξ̄ thrice);
// ξ_v = ξ̄_v/‖ξ̄_v‖ (the seed writes a hat); the Gaussian's sphere has radius ‖μ_v − x_p‖ (the
// seed writes μ_r); the weighted average of normalized SGs has no leading minus.
// RGB: the weights w are the luminance of each VPL's flux (the geometry is one for all channels);
// the amplitude c_v is kept per channel [DER].
// Units: meters, flux in W (any radiometric unit: irradiance comes out in it per m²).
#include <array>
#include <optional>
#include <span>

#include <glm/glm.hpp>

namespace proxygi::sh {

// One diffuse VPL: a patch of area A with normal n reflecting flux Φ R = albedo × E × A;
// its radiant intensity is I(ω) = Φ R max(ω·n, 0)/π.
struct VirtualPointLight {
  glm::dvec3 position{0.0};  // x_i, world meters
  glm::dvec3 normal{0.0, 0.0, 1.0};  // n_i, unit
  glm::dvec3 flux{0.0};      // Φ_i R_i per channel
};

// Rec. 709 luminance: the geometric weight w of a flux.
double luminance(const glm::dvec3& rgb);

// One triangle of a sender as vsgl_lights.comp forms its VPL: at the centroid, normal the
// normalized sum of the vertex normals (the face normal when they cancel, +Y when degenerate too),
// flux = albedo × max(E(n), 0) × area × exposure, E = Σ_i L̃_i y_i(n) (order 3, per channel, the
// irradiance SH the frame hands the senders), exposure the mean of the vertices' sender exposures
// (ref/sender_exposure.h; 1 when the draw has none).
VirtualPointLight triangle_light(const glm::dvec3 (&positions)[3], const glm::dvec3 (&normals)[3],
                                 const glm::dvec3& albedo, std::span<const std::array<float, 9>, 3> irradiance_order3,
                                 const glm::dvec3& exposures = glm::dvec3(1.0));

// The sums a VSGL is fitted from. Positions are relative to an origin the caller picks near the
// VPLs (their variance is a difference of sums: a near origin keeps it from cancelling).
struct VsglSums {
  double weight = 0.0;                 // Σ w_i
  glm::dvec3 weighted_axis{0.0};       // Σ w_i ξ̄_i, ξ̄_i = λ_d/(λ_d + 1) n_i (Toksvig)
  glm::dvec3 weighted_position{0.0};   // Σ w_i (x_i − origin)
  double weighted_square = 0.0;        // Σ w_i ‖x_i − origin‖²
  glm::dvec3 flux{0.0};                // Σ Φ_i R_i per channel
};
void add_light(VsglSums& sums, const VirtualPointLight& light, const glm::dvec3& origin);

// The smallest variance of a VSGL relative to the squared distance of its receiver
// (σ² ≥ 1e-6 ‖μ − x_p‖², so λ_σ ≤ 1e6): a single VPL has σ² = 0, which the closed form cannot
// take; this blurs a point light over 1e-3 rad. Shared with the GLSL twin.
inline constexpr double kVsglMinRelativeVariance = 1e-6;

struct Vsgl {
  glm::dvec3 axis{0.0, 0.0, 1.0};  // ξ_v: the intensity lobe's axis
  double sharpness = 0.0;          // λ_v = ‖ξ̄_v‖/(1 − ‖ξ̄_v‖)
  glm::dvec3 amplitude{0.0};       // c_v = Σ Φ R / A(λ_v) per channel (W/sr)
  glm::dvec3 mean{0.0};            // μ_v, world meters
  double variance = 0.0;           // σ_v², m² (≥ 0)
};
// The VSGL of the sums (origin as in add_light); nothing when Σ w ≤ 0.
std::optional<Vsgl> fit_vsgl(const VsglSums& sums, const glm::dvec3& origin);

// Incoming radiance lobe at x_p (eq. 7): L_in(ω) ≈ c_in G(ω; ξ_in, λ_in), per channel amplitude.
struct IncomingLobe {
  glm::dvec3 axis{0.0, 0.0, 1.0};
  double sharpness = 0.0;
  glm::dvec3 amplitude{0.0};  // c_in per channel (W/(m² sr))
};
// Nothing when x_p is at μ_v (the lobe is undefined there).
std::optional<IncomingLobe> vsgl_incoming(const Vsgl& light, const glm::dvec3& receiver);

// Irradiance at receiver (x_p, n_p) from one VSGL: the diffuse result of the seed (§3.2) with
// A(λ_d) kept exact, E = π/A(λ_d) · 2π c_in G(ξ_in·n; λ_in λ_d/(λ_in + λ_d)) / (λ_in + λ_d).
// No visibility. Zero at μ_v.
glm::dvec3 vsgl_irradiance(const Vsgl& light, const glm::dvec3& receiver, const glm::dvec3& normal);

// Brute-force unshadowed gathering: Σ_i I_i(−ω_i) max(n_p·ω_i, 0)/r_i², ω_i = (x_i − x_p)/r_i.
glm::dvec3 gather_vpl_irradiance(std::span<const VirtualPointLight> lights, const glm::dvec3& receiver,
                                 const glm::dvec3& normal);

}  // namespace proxygi::sh
