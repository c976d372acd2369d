#pragma once
// The tessellated ground of the vertex method (settings::ShadingMethod::vertex). The image-space
// method draws the ground as one quad; vertex receivers need vertices where shadows and bounce
// light vary, so the ground becomes a tensor-product grid: lines every 1/vertices_per_metre over
// the fine region and the ground's edges beyond it (no T-junctions, so no cracks). Outside the
// fine region nothing varies on the plane but the far field, so the two coarse border cells
// lose nothing there.
//
// Choice for scenes (ground_fine_region): the fine region is the box of every character's root
// position over the scene's frames, grown by kGroundMargin, clipped to the ground; density
// kGroundVerticesPerMetre = 16 (6.25 cm spacing). In the default scene (camera 7.2 m away, 50°
// field of view, 512² at 1/4) a receiver covers about 5 cm of ground near the character, so the
// vertex method gets about the image-space method's receiver density where the shadows are
// (153 × 83 = 12,699 ground vertices for the default walk; the paper's Figure 6 compares 60,767
// vertices with a 256² receiver buffer in the same spirit).
// Units: meters; the ground lies in y = 0 with normal +Y, centered at the origin.
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace proxygi::render {

inline constexpr float kGroundVerticesPerMetre = 16.0f;
inline constexpr float kGroundMargin = 2.5f;      // m around the characters' roots: body and shadow reach
inline constexpr int kGroundMaxFineLines = 1024;  // per axis; the density drops to fit

struct GroundGrid {
  std::vector<glm::vec3> positions;    // y = 0
  std::vector<glm::vec3> normals;      // +Y
  std::vector<std::uint32_t> indices;  // triangles, counter-clockwise seen from +Y
  int lines_x = 0, lines_z = 0;        // grid lines per axis (vertices = lines_x · lines_z)
};

// A square ground of side `size` (m) with fine lines over [fine_min, fine_max] (x, z; clipped to
// the square). Vertices are ordered in 8×8 blocks of the grid so each group of 64 vertex
// receivers is one compact patch (tiled culling bounds it tightly).
GroundGrid make_ground_grid(float size, glm::vec2 fine_min, glm::vec2 fine_max, float vertices_per_metre);

struct GroundRegion {
  glm::vec2 min{0.0f}, max{0.0f};  // x, z (m)
  float vertices_per_metre = kGroundVerticesPerMetre;
};
// The fine region for a scene (see above); the density is lowered when the region would need
// more than kGroundMaxFineLines lines along an axis.
GroundRegion ground_fine_region(const scene::Scene& scene);

}  // namespace proxygi::render
