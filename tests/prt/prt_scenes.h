#pragma once
// Small static scenes for the PRT tests: quads subdivided into receivers, and a wall corner.
#include <cmath>
#include <limits>
#include <vector>

#include "prt/surfaces.h"
#include "ref/embree_scene.h"
#include "sh/environment.h"
#include "sh/quadrature.h"

namespace proxygi::prt::test {

// The quad origin + a·u + b·v, a, b in [0, 1], facing normalize(cross(u, v)).
inline StaticSurface quad(const char* name, glm::vec3 origin, glm::vec3 u, glm::vec3 v, glm::vec3 albedo,
                          float spacing) {
  const glm::vec3 n = glm::normalize(glm::cross(u, v));
  StaticSurface s{name, {origin, origin + u, origin + u + v, origin + v}, {n, n, n, n}, {0, 1, 2, 0, 2, 3}, albedo};
  return subdivide(s, spacing);
}

// A floor (y = 0, x and z in [-1, 2]) and two walls 2 m high on its x = -1 and z = -1 edges,
// meeting in the corner (-1, y, -1).
inline StaticReceivers wall_corner(float spacing, glm::vec3 wall_albedo = glm::vec3(0.7f, 0.35f, 0.3f)) {
  StaticReceivers r;
  r.surfaces.push_back(quad("floor", {-1, 0, -1}, {0, 0, 3}, {3, 0, 0}, glm::vec3(0.6f), spacing));
  r.surfaces.push_back(quad("wall x", {-1, 0, -1}, {0, 2, 0}, {0, 0, 3}, wall_albedo, spacing));
  r.surfaces.push_back(quad("wall z", {-1, 0, -1}, {3, 0, 0}, {0, 2, 0}, wall_albedo, spacing));
  return r;
}

// Index of the vertex of `s` nearest to p.
inline std::size_t nearest_vertex(const StaticSurface& s, glm::vec3 p) {
  std::size_t best = 0;
  float best_d = std::numeric_limits<float>::max();
  for (std::size_t i = 0; i < s.positions.size(); ++i)
    if (const float d = glm::length(s.positions[i] - p); d < best_d) best_d = d, best = i;
  return best;
}

// The receivers as the path tracer's meshes (same triangles and albedo).
inline std::vector<ref::TriangleMesh> tracer_meshes(const StaticReceivers& r) {
  std::vector<ref::TriangleMesh> meshes;
  for (const StaticSurface& s : r.surfaces) {
    ref::TriangleMesh m;
    m.name = s.name;
    m.positions = s.positions;
    m.normals = s.normals;
    m.indices = s.indices;
    m.material.albedo = s.albedo;
    meshes.push_back(std::move(m));
  }
  return meshes;
}

// A positive band-limited sky: 0.4 + 2.5 max(s · sun, 0)^3 (bluish) projected to `order`.
inline sh::RgbSh test_lighting(int order, glm::dvec3 sun = glm::normalize(glm::dvec3(0.5, 0.8, 0.3))) {
  const sh::SphereQuadrature q = sh::make_sphere_quadrature(48, 96);
  sh::RgbSh out;
  out.order = order;
  const double tint[3] = {1.0, 0.9, 0.8};
  for (int c = 0; c < 3; ++c)
    out.channels[std::size_t(c)] = sh::project_function(order, q, [&](const glm::dvec3& s) {
      const double cosine = std::max(glm::dot(s, sun), 0.0);
      return tint[c] * (0.4 + 2.5 * cosine * cosine * cosine) + (c == 2 ? 0.2 * std::max(s.y, 0.0) : 0.0);
    });
  return out;
}

inline std::vector<float> to_float(const std::vector<double>& v) { return {v.begin(), v.end()}; }

}  // namespace proxygi::prt::test
