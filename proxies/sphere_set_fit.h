#pragma once
// The per-bone core of the variational sphere-set fit (after VSSA, Wang et al. 2006; see
// notes/sh-math.md §6). Everything is in bind space, meters.
//
// A bone owns a point set (surface samples, mesh vertices and interior points whose dominant
// bone it is). Its k spheres partition those points into clusters; each sphere comes within
// `slack` of every point of its cluster (radius = max over members of distance − slack, at least
// half the farthest distance), so the union covers every point to within the slack, and its center
// minimizes the sphere's outside volume (the part not inside the mesh). Steps:
//  - cluster: Lloyd iterations (each point joins the nearest cluster centroid, centroids move
//    to their members' mean), so a limb splits into even segments;
//  - fit: per cluster, a compass search over the center minimizing outside volume, estimated
//    with a fixed set of points filling the ball and a soft inside/outside step of the signed
//    distance grid (width one grid cell, so the estimate is smooth in the center);
//  - assign (VSSA's assignment on the combined objective): each point joins the sphere whose
//    boundary it is deepest inside (least |p − c| − r), the clusters are refitted, and the
//    result is kept while the bone's outside volume falls and no sphere protrudes past
//    max(tolerance, the worst protrusion before);
//  - split: the worst sphere is cut in two at its cluster's extreme points along the principal
//    axis, then the bone is re-clustered; remove: a sphere is dropped and the bone re-clustered
//    (the two halves of VSSA's teleport, driven over the character by proxies/fit.cpp).
// The error of a sphere is its protrusion: the largest signed distance to the mesh surface
// over points on its boundary sphere (0 when it lies entirely inside).
#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "proxies/mesh_index.h"

namespace proxygi::proxies {

// What a sphere costs, measured against the signed distance grid.
struct SphereObjective {
  const DistanceGrid* grid = nullptr;
  std::span<const glm::vec3> ball;        // points filling the unit ball (unit_ball_points)
  std::span<const glm::vec3> directions;  // unit directions (fibonacci_directions)
  float slack = 0.0f;      // meters a member may lie outside its sphere (>= 0)
  float tolerance = 0.0f;  // meters of protrusion the assignment step may reach

  // Estimated volume of the sphere outside the mesh, m³.
  float outside_volume(const glm::vec3& center, float radius) const;
  // Largest distance outside the mesh of a point of the sphere's boundary, meters (>= 0).
  float protrusion(const glm::vec3& center, float radius) const;
};

struct ClusterSphere {
  glm::vec3 center{0.0f};
  float radius = 0.0f;
  glm::vec3 centroid{0.0f};             // Lloyd anchor: mean of the members
  std::vector<std::uint32_t> members;   // indices into the point array
  float protrusion = 0.0f;              // error, meters
  float outside = 0.0f;                 // estimated volume outside the mesh, m³
};

// The smallest-outside-volume sphere that comes within objective.slack of every member
// (non-empty).
ClusterSphere fit_cluster(std::span<const glm::vec3> points, std::vector<std::uint32_t> members,
                          const SphereObjective& objective);

// The spheres of one bone.
class BoneSphereSet {
 public:
  // `points` must outlive the set; `members` are the bone's points (non-empty).
  BoneSphereSet(std::span<const glm::vec3> points, std::vector<std::uint32_t> members,
                const SphereObjective& objective);

  const std::vector<ClusterSphere>& spheres() const { return spheres_; }
  // Index of the sphere with the largest protrusion among those that can still split.
  int worst() const;
  float worst_error() const;
  // Index of the splittable sphere with the largest outside volume, -1 when none.
  int most_outside() const;
  // Summed volume of its spheres, m³ (overlaps counted twice).
  float volume() const;
  // Largest protrusion and summed outside volume (m³) over all its spheres.
  float worst_protrusion() const;
  float outside_volume() const;
  // Splits sphere `index` in two and runs `lloyd_iterations` of re-clustering over the bone.
  // Returns false when the sphere has fewer than two distinct members (nothing changes) or when
  // re-clustering emptied a cluster so the count did not grow.
  bool split(int index, int lloyd_iterations);
  // Drops sphere `index` (the set must hold two or more) and re-clusters the bone.
  void remove(int index, int lloyd_iterations);

 private:
  void relax(int iterations);
  void assign(int iterations);
  void refit(std::vector<std::vector<std::uint32_t>> clusters);
  std::span<const glm::vec3> points_;
  std::vector<std::uint32_t> members_;
  const SphereObjective* objective_;
  std::vector<ClusterSphere> spheres_;
  std::vector<bool> splittable_;
};

}  // namespace proxygi::proxies
