#pragma once
// Per-frame culling and level of detail of world-space proxies (proxies/tracking.h).
//
// Culling: a proxy shadows or lights receivers only within its sphere of influence (radius
// eta × r, eta ≈ 15 for shadows; DESIGN.md), and the receivers that matter are visible, so a
// proxy whose influence sphere lies entirely outside one frustum plane is skipped.
// Planes are extracted from a view-projection matrix (Gribb–Hartmann) with the OpenGL depth
// range z in [-w, w]; for a Vulkan [0, w] projection this near plane lies slightly closer to the
// eye, which only keeps more proxies (conservative).
//
// Level of detail: spheres are grouped by bone chain (chain_groups). When a group's bounding
// sphere projects to fewer than `pixel_threshold` pixels of radius, its spheres are replaced by
// that bounding sphere (albedo: volume-weighted mean); when the whole character's bounding
// sphere is that small, the character becomes one sphere.
#include <array>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "anim/character.h"
#include "base/result.h"
#include "proxies/proxy_rig.h"
#include "proxies/tracking.h"

namespace proxygi::proxies {

struct Frustum {
  std::array<glm::vec4, 6> planes{};  // (n, d): a point p is inside a plane when dot(n, p) + d >= 0; |n| = 1
  static Frustum from_view_projection(const glm::mat4& view_projection);
  // True when a sphere (world space) is not entirely outside any plane.
  bool touches(const glm::vec3& center, float radius) const;
};

struct CullProxiesJob {
  // Inputs.
  std::span<const WorldSphere> spheres;
  Frustum frustum;
  float eta = 15.0f;  // influence radius / sphere radius (> 0)
  // Outputs (caller-owned): indices of kept spheres in the first *kept_count entries.
  std::span<std::uint32_t> kept;  // at least spheres.size()
  int* kept_count = nullptr;

  Status validate() const;
  Status run() const;
};

// Chain id per rig sphere: the sphere's bone climbs to the first ancestor-or-self whose parent
// branches (two or more children) or is a root; spheres with the same such node share a group
// (an arm from shoulder to hand, a leg, the spine segment between branches).
std::vector<int> chain_groups(const ProxyRig& rig, const anim::Character& character);

struct MergeSmallProxiesJob {
  // Inputs.
  std::span<const WorldSphere> spheres;
  std::span<const int> groups;   // one per sphere (chain_groups)
  glm::vec3 eye{0.0f};           // camera position, world space
  float focal_pixels = 1000.0f;  // viewport height / (2 tan(fov_y / 2))
  float pixel_threshold = 2.0f;  // merge below this projected radius, pixels
  // Outputs (caller-owned): merged spheres in the first *out_count entries.
  std::span<WorldSphere> out;    // at least spheres.size()
  int* out_count = nullptr;

  Status validate() const;
  Status run() const;
};

// Bounding sphere of spheres (center: volume-weighted centroid; radius: reaches every sphere),
// albedo volume-weighted.
WorldSphere bounding_sphere(std::span<const WorldSphere> spheres);

}  // namespace proxygi::proxies
