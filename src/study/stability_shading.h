#pragma once
// What the stability sweeps evaluate at one receiver: the frame's shading through its CPU twins
// (render/shading.h), and the exact answer for the same spheres and the same band-limited lighting.
// Scalars are Rec. 709 luminance of irradiance E = ∫ L max(N·ω, 0) dω (not / π).
#include <span>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

#include "render/frame_tables.h"
#include "render/shading.h"
#include "sh/environment.h"
#include "sh/quadrature.h"

namespace proxygi::study {

enum class SweepLight { sky, delta };  // the default scene's sky and sun; a delta light at the sun's direction
// Projected at the highest order (6), unwindowed.
sh::RgbSh sweep_lighting(SweepLight light);
// The frame's tables for `lighting` at `order`, windowed with h = window (≤ 0: no window), no ground.
render::FrameTables sweep_tables(const sh::RgbSh& lighting, int order, double window, float shadow_eta = 15.0f);

inline constexpr float kOptimalLinearOnly = 1e30f;  // τ that makes HYB take no squaring (OL alone)

struct MethodShade {
  double value = 0.0;       // the frame's output (clamped to [0, unshadowed], exponentiate.comp)
  double unclamped = 0.0;   // O_p · LH(N) before the F4 clamp
  double unshadowed = 0.0;  // √4π LH_0(N)
  std::vector<float> visibility;  // O_p
  int squarings = 0;
};
// HYB with τ (kOptimalLinearOnly: OL) on the log sum of the spheres (accumulate_log_occlusion).
MethodShade shade_method(const render::FrameTables& tables, float tau, const glm::vec3& p, const glm::vec3& normal,
                         std::span<const render::Sphere> spheres);
// The prior-work baselines of the chart on the same receivers (render/baselines.h):
// scalar AO from the spheres (the AO method: E = A · E(N), clamped as the frame writes it), and
// the vertex method on the ground: HYB at the three vertices of the ground grid's triangle around
// ground point p (spacing 1/render::kGroundVerticesPerMetre, triangulated as make_ground_grid;
// the grid's lines are offset by kVertexGridOffset of a cell so p lies inside a triangle rather
// than on a vertex), interpolated linearly (render::interpolate_triangle). `visibility` is empty.
inline constexpr glm::vec2 kVertexGridOffset{0.37f, 0.61f};
MethodShade shade_ambient_occlusion(const render::FrameTables& tables, const glm::vec3& p, const glm::vec3& normal,
                                    std::span<const render::Sphere> spheres);
MethodShade shade_vertex_ground(const render::FrameTables& tables, float tau, const glm::vec3& p, std::span<const render::Sphere> spheres);
// A ground receiver p (normal +Y) by the method of that name: "hyb" (τ = tau), "ol", "ao" or "vertex"
// (HYB at τ = tau on the grid's vertices); any other name is a contract violation.
MethodShade shade_ground_method(std::string_view method, const render::FrameTables& tables, float tau, const glm::vec3& p,
                                std::span<const render::Sphere> spheres);
// The same with an explicit log sum f (n² values).
MethodShade shade_log_sum(const render::FrameTables& tables, float tau, std::span<const float> f, const glm::vec3& p,
                          const glm::vec3& normal);
// Shading of a given visibility vector O (product space, exact exp): clamped and unclamped.
MethodShade shade_visibility(const render::FrameTables& tables, std::span<const float> visibility, const glm::vec3& p,
                             const glm::vec3& normal);
// Product space: Π_i O_i of the projected per-sphere occlusions (tangent-plane rules and the
// influence cut applied as in the frame).
std::vector<float> product_space_visibility(const render::FrameTables& tables, const glm::vec3& p, const glm::vec3& normal,
                                            std::span<const render::Sphere> spheres);

// The exact answer for the tables' (windowed) lighting.
class TruthIntegrator {
 public:
  // Full-sphere product quadrature z_nodes × 2 z_nodes (several spheres, SH projections).
  TruthIntegrator(const render::FrameTables& tables, int z_nodes);
  // ∫ L max(N·ω, 0): the unshadowed shade.
  double unshadowed(const glm::dvec3& normal) const;
  // ∫ L V max(N·ω, 0), V = 0 where the ray from p hits a sphere; p inside a sphere sees nothing.
  double shadowed(const glm::dvec3& p, const glm::dvec3& normal, std::span<const render::Sphere> spheres) const;
  // One sphere, by a cap quadrature about its direction (precise for small caps).
  double shadowed_one(const glm::dvec3& p, const glm::dvec3& normal, const render::Sphere& sphere) const;
  // SH projection (the tables' order) of the true visibility from p over the whole sphere.
  std::vector<double> visibility_sh(const glm::dvec3& p, std::span<const render::Sphere> spheres) const;

 private:
  double light(const glm::dvec3& direction) const;
  int order_;
  std::vector<double> luminance_sh_;  // order² coefficients of the luminance of the lighting
  sh::SphereQuadrature quadrature_;
  std::vector<double> light_at_;      // luminance at each quadrature direction
  std::vector<double> basis_at_;      // order² basis values per direction
};

double luminance(const glm::vec3& rgb);
// Relative L2 distance ||a − b|| / ||b||.
double relative_l2(std::span<const double> a, std::span<const double> b);

}  // namespace proxygi::study
