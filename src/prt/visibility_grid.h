#pragma once
// Static geometry shadowing the characters (notes/prt-vsgl.md §2, the static-to-character
// transfer): a regular grid of points around the static meshes, each holding the SH projection
// of the static meshes' visibility V_s(x, ω) (1 where a ray from x toward ω leaves the static
// meshes unhit), computed with Embree next to the PRT transfer (prt/transfer.h) and cached with it
// (prt/transfer_cache.h). A character receiver at x with proxy visibility O_p then shades
// E = (O_p ∗ V_s(x)) · LH(N) (sh/product.h, the order-n truncated product the proxies use), V_s
// trilinear between the 8 grid points around x (prt/static_frame.h; exponentiate.comp's
// static-transfer variants).
//
// Conventions: world space (+Y up, meters), SH order n, n² coefficients per point (sh/basis.h);
// an unoccluded point holds exactly proj(1) = (√4π, 0, …): V_s = proj(1) − (4π/K) Σ_blocked y(s_k)
// over K uniform sphere directions (only the blocked part is estimated, as T_DS in transfer.h).
// Occluders are the static meshes only, not the ground (patch or outer): below the horizon the
// character's lighting already holds the lit ground (render::lighting_cube_set), which a static
// mesh standing on it then hides.
//
// Extent: the static meshes' bounds grown by margin_m in x, z and +y (the ground patch's margin,
// prt::StaticFieldOptions), y from the lower bound (or 0) up; points `spacing_m` apart. Outside
// it V_s = 1 (no shadowing; a point there still sees the meshes, so the value steps at the grid's
// edge by what the meshes hide from 2 m away: README). A point inside a mesh (more than a quarter
// of its rays hit back faces) is marked (DC = kInsidePoint, the rest 0) and left out of the
// trilinear sum, whose weights are renormalised over the valid corners, so a receiver in front
// of a wall does not take the wall's inside. A wall thinner than the spacing can still have valid
// points on both of its sides in one cell: within a spacing of such a wall the two sides mix.
//
// Determinism: point i uses a Hammersley set on the sphere Cranley–Patterson rotated by a hash of
// (seed, i); results do not depend on the thread count.
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "base/result.h"
#include "prt/surfaces.h"
#include "shaders/shared/layouts.h"

namespace proxygi::prt {

struct VisibilityGridSettings {
  float spacing_m = 0.2f;   // between grid points
  float margin_m = 2.0f;    // around the static meshes' bounds (x, z, +y)
  int directions = 1024;    // K per point, kMinDirections..kMaxDirections (transfer.h)
  std::uint32_t seed = 1;
  bool operator==(const VisibilityGridSettings&) const = default;
};
// A grid is refused when it would hold more points than this (raise spacing_m).
inline constexpr std::size_t kMaxVisibilityGridPoints = std::size_t(1) << 21;
inline constexpr float kInsidePoint = gpu_layout::kStaticVisibilityInside;  // the DC of a point inside a mesh
// Below this sum of valid corner weights a sample is treated as outside (all 8 corners inside).
inline constexpr float kMinVisibilityWeight = gpu_layout::kStaticVisibilityMinWeight;

struct VisibilityGrid {
  int order = 0;
  glm::vec3 origin{0.0f};   // world position of point (0, 0, 0), m
  float spacing = 0.0f;     // m
  glm::uvec3 size{0u};      // points per axis (0: no static meshes, empty grid)
  std::vector<float> values;  // point (x, y, z) at ((z·size.y + y)·size.x + x)·n², n² each
  std::uint64_t rays = 0;   // traced (0 when read from the cache)
  double seconds = 0.0;     // wall time of the compute
  std::size_t points() const { return std::size_t(size.x) * size.y * size.z; }
  std::size_t bytes() const { return values.size() * sizeof(float); }
};

// The occluders: every surface of `receivers` except the one named "ground" (and no outer
// ground). An empty grid when there are none. Fails on bad settings ("prt.grid.spacing 0: …").
Result<VisibilityGrid> compute_visibility_grid(const StaticReceivers& receivers, int order,
                                               const VisibilityGridSettings& settings, int threads = 0);

// V_s at p, trilinear between the valid ones of the 8 points around it, weights renormalised
// (n² values into out); false (out untouched) when p lies outside [origin, origin + (size −
// 1)·spacing], the grid is empty or the valid corners weigh ≤ kMinVisibilityWeight.
bool sample_visibility(const VisibilityGrid& grid, const glm::vec3& p, std::span<float> out);

}  // namespace proxygi::prt
