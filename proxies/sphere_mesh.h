#pragma once
// Spheres as triangle geometry, for `proxygi pose --proxies` (OBJ/PLY export) and debugging.
//
//   SphereGeometry geometry;
//   append_sphere_geometry(spheres, 16, geometry);   // spheres: world space (tracking.h)
//   // geometry.positions / normals / indices: append to a mesh writer, or:
//   write_spheres_obj("proxies.obj", spheres);
#include <cstdint>
#include <filesystem>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "base/result.h"
#include "proxies/tracking.h"

namespace proxygi::proxies {

struct SphereGeometry {
  std::vector<glm::vec3> positions;  // world space, meters
  std::vector<glm::vec3> normals;    // unit, outward
  std::vector<glm::vec3> colors;     // per vertex: the sphere's albedo (linear)
  std::vector<std::uint32_t> indices;  // triangles, counter-clockwise seen from outside
};

// Appends one UV sphere per input (`segments` >= 3 around, segments / 2 rings), indices offset
// by what `out` already holds.
void append_sphere_geometry(std::span<const WorldSphere> spheres, int segments, SphereGeometry& out);

// Writes the spheres as a Wavefront OBJ (one group per sphere), atomically.
Status write_spheres_obj(const std::filesystem::path& path, std::span<const WorldSphere> spheres, int segments = 16);

}  // namespace proxygi::proxies
