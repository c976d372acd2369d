#pragma once
// Tracking: world-space spheres of a frame from the rig and the frame's node world matrices.
//
//   Result<TrackingRig> rig = compile_tracking(proxy_rig, character, proxy_rig.binding);
//   std::vector<WorldSphere> spheres(rig->spheres.size());
//   TrackProxiesJob job{&*rig, pose.world, spheres};   // pose.world: anim::PoseBuffers::world
//   job.run();
//
// Per sphere with influences {n_k, w_k, c_k, r_k} (c_k, r_k: the sphere's center and radius in
// node n_k's bone space):
//   center_world = sum_k w_k * node_world[n_k] * c_k
//   radius_world = sum_k w_k * r_k * scale(node_world[n_k])
// where scale(M) is the largest column length of M's upper 3x3 (a conservative uniform scale:
// the sphere still covers what it covered under non-uniform scale). Rigid binding has one
// influence, the sphere's bone. Blended binding carries the sphere's bind-space center with its
// mean skin weights (linear blend skinning of the center).
#include <array>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "anim/character.h"
#include "base/result.h"
#include "proxies/proxy_rig.h"

namespace proxygi::proxies {

// One sphere as the GPU reads it (std430: two vec4).
struct WorldSphere {
  glm::vec3 center{0.0f};  // world space, meters
  float radius = 0.0f;     // meters
  glm::vec3 albedo{1.0f};  // linear RGB
  float reserved = 0.0f;
};
static_assert(sizeof(WorldSphere) == 32);

struct TrackedSphere {
  int count = 0;                                   // influences used (1..kSphereWeights)
  std::array<int, kSphereWeights> nodes{};         // node indices
  std::array<float, kSphereWeights> weights{};     // sum to 1
  std::array<glm::vec4, kSphereWeights> centers{}; // xyz: center in node's bone space, w: radius there
  glm::vec3 albedo{1.0f};
};

struct TrackingRig {
  Binding binding = Binding::rigid;
  int node_count = 0;  // node_world must hold this many matrices
  std::vector<TrackedSphere> spheres;
};

// Resolves the rig against the character for one binding. Errors name the sphere and bone
// ("sphere 3: weight node 40 out of range").
Result<TrackingRig> compile_tracking(const ProxyRig& rig, const anim::Character& character, Binding binding);

struct TrackProxiesJob {
  // Inputs.
  const TrackingRig* rig = nullptr;
  std::span<const glm::mat4> node_world;  // one per node, world space (anim::PoseBuffers::world)
  // Output (caller-owned): one per rig sphere.
  std::span<WorldSphere> spheres;

  Status validate() const;  // pointers and sizes
  Status run() const;       // validate(), then track; no allocation
};

}  // namespace proxygi::proxies
