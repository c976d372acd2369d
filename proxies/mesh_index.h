#pragma once
// Spatial queries on a triangle soup, used by fitting (signed distance grid) and by the quality
// measures (exact distances, inside tests). All coordinates are in one space (the bind space of
// proxies/bind_surface.h), meters.
//
// Inside test: winding number by signed ray crossings. From p a ray runs along +X, +Y and +Z;
// each triangle it crosses adds the sign of the triangle's normal component along the ray, so a
// point inside a closed, outward-oriented surface gets +1 per ray (+2 inside two overlapping
// closed parts, -1 for an inverted part) and a point outside gets 0. A point is inside when at
// least two of the three rays see a non-zero winding: this majority vote tolerates small holes
// (a ray through a hole miscounts, the other two usually do not). Ray origins are nudged by a
// fixed tiny offset so rays through shared edges and vertices do not count twice.
#include <algorithm>
#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

namespace proxygi::proxies {

struct TriangleSoup {
  std::vector<glm::vec3> positions;
  std::vector<glm::uvec3> triangles;  // indices into positions
};

// Closest point on triangle (a, b, c) to p (Voronoi-region method).
glm::vec3 closest_point_on_triangle(const glm::vec3& p, const glm::vec3& a, const glm::vec3& b,
                                    const glm::vec3& c);

// Axis-aligned box.
struct Box {
  glm::vec3 lo{0.0f};
  glm::vec3 hi{0.0f};
  float diagonal() const { return glm::length(hi - lo); }
};
Box bounds_of(std::span<const glm::vec3> points);

// Calls visit(linear_index) for every cell of a dims-sized grid (x fastest) at Chebyshev
// distance exactly `ring` from `center`: the shells of a nearest-neighbour search. Every cell of
// ring r is at least (r − 1) cells from any point of the center cell, the bound both grid
// searches stop on.
template <class Visit>
void for_each_cell_in_ring(const glm::ivec3& center, int ring, const glm::ivec3& dims, Visit&& visit) {
  const glm::ivec3 lo = glm::max(center - ring, glm::ivec3(0));
  const glm::ivec3 hi = glm::min(center + ring, dims - 1);
  for (int z = lo.z; z <= hi.z; ++z)
    for (int y = lo.y; y <= hi.y; ++y)
      for (int x = lo.x; x <= hi.x; ++x) {
        const glm::ivec3 offset = glm::abs(glm::ivec3(x, y, z) - center);
        if (std::max(offset.x, std::max(offset.y, offset.z)) != ring) continue;
        visit((std::size_t(z) * std::size_t(dims.y) + std::size_t(y)) * std::size_t(dims.x) + std::size_t(x));
      }
}

// Uniform grid of triangle buckets for nearest-surface distance queries.
class ClosestTriangleGrid {
 public:
  // `cell` > 0 meters. The soup must outlive the grid.
  void build(const TriangleSoup& soup, float cell);
  // Unsigned distance from p to the surface, searching no farther than max_distance; returns
  // max_distance when nothing is that close (so callers get a clamped distance cheaply).
  float distance(const glm::vec3& p, float max_distance) const;

 private:
  const TriangleSoup* soup_ = nullptr;
  glm::vec3 origin_{0.0f};
  float cell_ = 1.0f;
  glm::ivec3 dims_{0};
  std::vector<std::uint32_t> cell_start_;  // CSR layout: triangles of cell i are
  std::vector<std::uint32_t> cell_items_;  // cell_items_[cell_start_[i] .. cell_start_[i + 1])
};

// Signed ray-crossing winding numbers along the three axes (see the header comment).
class WindingIndex {
 public:
  // `bins` per side of each 2D bucket grid (perpendicular to each axis). The soup must outlive
  // the index.
  void build(const TriangleSoup& soup, int bins = 64);
  // Winding number of p along +axis (0 = X, 1 = Y, 2 = Z).
  int winding(const glm::vec3& p, int axis) const;
  // Majority vote of the three rays.
  bool inside(const glm::vec3& p) const;
  // Winding numbers along +axis of the points origin + i * step * e_axis, i < out.size(), from
  // one pass over the crossings of that line (what a grid needs: one line, many nodes).
  void winding_along_line(const glm::vec3& origin, int axis, float step, std::span<int> out) const;

 private:
  struct Plane {
    glm::vec2 origin{0.0f};
    glm::vec2 cell{1.0f};
    std::vector<std::uint32_t> start;
    std::vector<std::uint32_t> items;
  };
  const TriangleSoup* soup_ = nullptr;
  // The line through `point` along `axis`, nudged off shared edges: its (u, v) coordinates in q
  // and the plane bin it falls in; false when it misses the binned area.
  bool line_bin(const glm::vec3& point, int axis, glm::dvec2& q, std::size_t& cell) const;

  int bins_ = 0;
  float nudge_ = 0.0f;
  Plane planes_[3];
};

// Signed distance sampled on a regular grid: negative inside, positive outside, |value| clamped
// to `band` (fitting only needs distances near the surface). Trilinear between nodes, so a
// value is accurate to about half a cell.
struct DistanceGrid {
  glm::vec3 origin{0.0f};  // position of node (0, 0, 0)
  float cell = 1.0f;       // node spacing, meters
  glm::ivec3 dims{0};      // nodes per axis
  float band = 0.0f;
  std::vector<float> values;  // x fastest

  // Trilinear signed distance; points outside the grid read the clamped band value (outside).
  float sample(const glm::vec3& p) const;
};

// Builds the grid over `box` padded by `band`, node spacing `cell`. Distances: exact
// point–triangle distances for nodes within a cell of a triangle, then raster sweeps that pass
// each node's nearest triangle on to its neighbours (forward and backward, twice), which gives
// the exact distance except in rare configurations. Signs: winding numbers along grid lines.
DistanceGrid build_distance_grid(const TriangleSoup& soup, const WindingIndex& winding, const Box& box,
                                 float cell, float band);

}  // namespace proxygi::proxies
