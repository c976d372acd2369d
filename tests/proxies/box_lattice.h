#pragma once
// Exact box geometry shared by the proxy-fitting tests (fit_test.cpp, sphere_set_test.cpp,
// teleport_test.cpp): signed distances, fitting points on a lattice, triangle soups, and the
// volume a sphere union puts outside the boxes, measured on a fine lattice.
// Units: meters (volumes m³). Boxes are axis-aligned, [lo, hi] per axis.
#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "anim/character.h"
#include "proxies/mesh_index.h"
#include "proxies/sphere_set_fit.h"

namespace proxygi::proxies::testing {

struct AxisBox {
  glm::vec3 lo{0.0f}, hi{0.0f};
};

// Signed distance from p to the box (negative inside).
float box_sdf(const glm::vec3& p, const glm::vec3& lo, const glm::vec3& hi);

// The box's points on a lattice of `spacing` from lo (its faces and inside, up to hi + 1e-4 m),
// appended to `points`; returns their indices there.
std::vector<std::uint32_t> add_box_lattice(std::vector<glm::vec3>& points, const AxisBox& box, float spacing = 0.02f);

// The primitive's positions and triangles appended to `soup` (indices offset past its positions).
void add_to_soup(TriangleSoup& soup, const anim::Primitive& primitive);

// The volume of the union of `spheres` outside every box of `boxes`: the cell centres of a lattice
// of `spacing` over the union's bounding box that lie in a sphere (distance <= radius) and outside
// each box (box_sdf > 0), times the cell volume.
float union_outside_volume(std::span<const ClusterSphere> spheres, std::span<const AxisBox> boxes,
                           float spacing = 0.005f);

}  // namespace proxygi::proxies::testing
