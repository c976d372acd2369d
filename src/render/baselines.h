#pragma once
// CPU twins of the prior-work baselines of the speed–accuracy chart (settings::ShadingMethod):
//   vertex_receiver     ↔ vertex_receivers.comp   a mesh vertex as a receiver (vertex method)
//   ambient_occlusion   ↔ ambient_occlusion.comp  scalar AO from the proxy spheres (AO method)
// The vertex method shades its receivers with the image-space twins of shading.h
// (accumulate_log_occlusion, exponentiate_and_shade, accumulate_indirect) and interpolates the
// result linearly across each triangle (the rasterizer's perspective-correct interpolation is
// linear in world space: interpolate_triangle).
//
// Scalar AO at receiver p with unit normal N:
//   A = Π_i (1 − a_i),  a_i = w(s_i) · s_i² · max(N·d_i, 0),  E = A · E(N),  no bounce light,
// where (d_i, s_i) are the direction and sine of the half-angle of sphere i after the
// tangent-plane rules (sh/tangent_plane.h), so every kept sphere lies above the tangent plane and
// s² cos β = (1/π) ∫_cap N·ω dω is exactly the cosine-weighted fraction of the hemisphere it
// covers; w = sh::influence_fade_weight(s, η_shadow, log-table rows) is the shadow table's
// sphere-of-influence fade (0 for s ≤ 1/η_shadow); E(N) = √4π (LH(N))_0 per channel is the
// unshadowed irradiance from the environment's (windowed) SH, the image-space method's E with no
// proxy in reach. Spheres multiply in list order (the GPU keeps ascending order).
// Units: meters, world space; irradiance E = ∫ L cos (not divided by π).
#include <span>

#include <glm/glm.hpp>

#include "render/frame_tables.h"
#include "render/shading.h"

namespace proxygi::render {

// What vertex_receivers.comp writes for a vertex: (p, 1) and (N / |N|, 0); (0, 1, 0) for N = 0.
struct VertexReceiver {
  glm::vec4 position_depth{0.0f};
  glm::vec4 normal{0.0f, 1.0f, 0.0f, 0.0f};
};
VertexReceiver vertex_receiver(const glm::vec3& position, const glm::vec3& normal);

// Value at world point x of the linear interpolation of (value_a, value_b, value_c) over the
// triangle (a, b, c), by barycentric coordinates of x projected into the triangle's plane.
glm::vec3 interpolate_triangle(const glm::vec3& x, const glm::vec3& a, const glm::vec3& b, const glm::vec3& c,
                               const glm::vec3& value_a, const glm::vec3& value_b, const glm::vec3& value_c);

// E(N) = √4π (LH(N))_0 per channel, from the cube set of receiver point p (lighting_cube_set).
glm::vec3 unshadowed_irradiance(const FrameTables& tables, const glm::vec3& p, const glm::vec3& normal);

struct AmbientOcclusionResult {
  float unoccluded = 1.0f;     // A ∈ [0, 1]
  glm::vec3 irradiance{0.0f};  // E = A · E(N), rgb
};
AmbientOcclusionResult ambient_occlusion(const FrameTables& tables, const glm::vec3& p, const glm::vec3& normal,
                                         std::span<const Sphere> spheres);

}  // namespace proxygi::render
