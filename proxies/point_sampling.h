#pragma once
// Point sets that stand for a character's surface and volume in the bind pose (bind space,
// meters; see proxies/bind_surface.h), and small helpers to sample them reproducibly.
#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "proxies/bind_surface.h"
#include "proxies/mesh_index.h"

namespace proxygi::proxies {

// SplitMix64: a tiny, fully specified generator so samples are the same on every platform.
class Random {
 public:
  explicit Random(std::uint64_t seed) : state_(seed) {}
  std::uint64_t next();
  float uniform();  // [0, 1)
 private:
  std::uint64_t state_;
};

// A point on the surface: triangle + barycentric coordinates, so it can be re-skinned at any
// pose by blending its triangle's skinned corners.
struct SurfaceSample {
  glm::vec3 position{0.0f};     // bind space
  std::uint32_t triangle = 0;
  glm::vec3 barycentric{1.0f / 3.0f};
  int bone = -1;                // dominant node of the interpolated influences
  glm::vec3 albedo{1.0f};       // linear base color at the sample
};

// `count` samples with density proportional to area (OpenMesh triangle areas).
std::vector<SurfaceSample> sample_surface(const anim::Character& character, const BindSurface& surface,
                                          int count, std::uint64_t seed);

// Interpolated influences of a sample (corner influences blended by barycentrics).
Influences sample_influences(const BindSurface& surface, const SurfaceSample& sample);

// Uniform grid over points for nearest-neighbour lookups.
class NearestPointGrid {
 public:
  void build(std::span<const glm::vec3> points, float cell);
  // Index of the nearest point, or -1 when the grid is empty.
  int nearest(const glm::vec3& p) const;

 private:
  std::span<const glm::vec3> points_;
  glm::vec3 origin_{0.0f};
  float cell_ = 1.0f;
  glm::ivec3 dims_{0};
  std::vector<std::uint32_t> start_;
  std::vector<std::uint32_t> items_;
};

// Points strictly inside the surface: one jittered point per inside node of the distance grid
// (kept when the grid still reads it as inside), thinned to at most max_count.
std::vector<glm::vec3> sample_interior(const DistanceGrid& grid, int max_count, std::uint64_t seed);

// n nearly uniform unit directions (Fibonacci sphere).
std::vector<glm::vec3> fibonacci_directions(int n);
// n points filling the unit ball evenly (radius^(1/3) stratified, Fibonacci directions).
std::vector<glm::vec3> unit_ball_points(int n);

}  // namespace proxygi::proxies
