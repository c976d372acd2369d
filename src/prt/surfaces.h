#pragma once
// Static receivers for precomputed radiance transfer (PRT): the static meshes and the ground of a
// scene as world-space triangle meshes whose vertices carry the transfer vectors (prt/transfer.h).
//
// Spacing: triangles are split uniformly until no edge is longer than `spacing_m`. Transfer is
// stored per vertex and interpolated linearly, so a contact shadow narrower than about one spacing
// is smeared. 0.1 m is the default: a stair tread (0.3 m) gets 3+ vertices across and a
// character's foot (0.25 m) shadow 2–3; the project's wall corner with stairs and its ground patch
// (assets/scenes/wall_corner.json) come to 21,772 vertices, 5.3 MiB and ~18 s on 2 cores at order
// 4 (README). Halving the spacing quadruples all three.
// The ground is only meshed over a patch around the static meshes (their xz bounds grown by
// `ground_margin_m`); beyond it the ground is treated as unoccluded (T = H(+Y)), because nothing
// static stands there. Conventions: world space (glTF: +Y up, meters), unit vertex normals.
#include <cstdint>
#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "base/result.h"
#include "world/world.h"

namespace proxygi::prt {

struct StaticSurface {
  std::string name;                    // "static_meshes[i]:<primitive>" or "ground"
  std::vector<glm::vec3> positions;    // world space, m
  std::vector<glm::vec3> normals;      // unit, one per position
  std::vector<std::uint32_t> indices;  // 3 per triangle
  glm::vec3 albedo{0.8f};              // linear rgb in [0, 1] (one per surface: the material's factor)
};

// The ground outside the meshed patch: y = 0, |x|, |z| <= half_size, minus the patch rectangle.
struct OuterGround {
  bool enabled = false;
  float half_size = 0.0f;                      // m
  glm::vec2 patch_min{0.0f}, patch_max{0.0f};  // xz of the meshed patch (excluded)
  glm::vec3 albedo{0.8f};
};

struct StaticReceivers {
  std::vector<StaticSurface> surfaces;
  OuterGround outer_ground;
};

// Splits every triangle into m² congruent triangles, m = ceil(longest edge / spacing_m), and
// welds vertices closer than 1e-5 m with the same normal (shared edges of equal m weld exactly).
StaticSurface subdivide(const StaticSurface& surface, float spacing_m);

// A ground patch [min, max] in xz at y = 0 as a grid of cells at most `spacing_m` a side, two
// triangles each (normal +Y).
StaticSurface ground_patch(glm::vec2 patch_min, glm::vec2 patch_max, float spacing_m, const glm::vec3& albedo);

// The world's static meshes (albedo override, else each primitive's material base color) and the
// ground patch around them, subdivided. Primitives without normals are skipped with a warning
// (as the renderers skip them). Fails when spacing_m is not positive.
Result<StaticReceivers> static_receivers(const world::World& world, float spacing_m, float ground_margin_m);

}  // namespace proxygi::prt
