#pragma once
// The raster shadow splat (frame step 4, paper §4 and §4.1): each proxy's sphere of influence
// (radius η·r) is drawn as a coarse bounding mesh, one instance per proxy; the depth test against
// the receivers' depth is the coverage oracle, and the fragment stage adds the proxy's rotated
// log-occlusion vector to RGBA32F colour targets by additive blending. The alternative to
// shadow_gather.comp (tiled compute culling); both give the same f = Σ_i rot(O_log(s_i), d_i) per
// receiver, CPU twin render::accumulate_log_occlusion.
//
// Recorded in three steps, all at receiver resolution (1/k of the display):
//   depth    receiver_depth.frag: depth buffer ← each receiver's projected depth (1 where none)
//   splat    shadow_splat.vert/.frag: back faces, depth test GREATER (the receiver lies in front
//            of the back surface), no depth writes; blended into the targets, cleared to 0;
//            order 6 needs two draws over 5 targets each (shaders/shared/splat_layouts.h)
//   resolve  splat_resolve.comp: targets → the log-occlusion buffer in the gather's layout
//            (receiver index × n² + i), which exponentiate.comp reads.
// Assumes the frame's standard depth range (near 0, far 1) and that the sphere of influence's
// back surface lies before the far plane (no depth clamp): receivers it misses there lose that
// proxy's shadow.
#include <cstdint>
#include <memory>
#include <vector>

#include <glm/glm.hpp>
#include <vulkan/vulkan.h>

#include "base/result.h"
#include "gpu/pass_barriers.h"
#include "gpu/pipeline.h"
#include "gpu/resources.h"

namespace proxygi::gpu {

class Context;

// The buffers one shadow pass reads and writes (owned by the frame).
struct ShadowSplatInputs {
  const Buffer* constants = nullptr;      // FrameConstants (uniform)
  const Buffer* receivers = nullptr;      // Receiver per receiver pixel
  const Buffer* proxies = nullptr;        // ProxySphere[kMaxProxies] (uniform)
  std::uint32_t proxy_count = 0;          // instances drawn
  const Buffer* log_table = nullptr;      // faded ZH log-occlusion table
  const Buffer* log_occlusion = nullptr;  // output: receivers × n² floats
};

class ShadowSplatPass {
 public:
  // receiver_scale k places receiver pixel centers on the display texels receivers.comp picks.
  static Result<std::unique_ptr<ShadowSplatPass>> create(Context& context, int order, std::uint32_t display_width,
                                                         std::uint32_t display_height, std::uint32_t receiver_scale);

  // What record() reads and writes (PassBarriers orders it against the other passes).
  std::vector<ResourceAccess> accesses(const ShadowSplatInputs& inputs) const;
  // depth + splat + resolve; the steps are ordered by full barriers among themselves.
  void record(VkCommandBuffer commands, const ShadowSplatInputs& inputs) const;
  void record_depth(VkCommandBuffer commands, const ShadowSplatInputs& inputs) const;
  void record_splat(VkCommandBuffer commands, const ShadowSplatInputs& inputs) const;
  void record_resolve(VkCommandBuffer commands, const ShadowSplatInputs& inputs) const;

  std::uint32_t target_count() const { return std::uint32_t(targets_.size()); }
  std::uint32_t bounding_mesh_vertices() const { return mesh_vertices_; }

 private:
  explicit ShadowSplatPass(Context& context) : context_(context) {}
  void set_viewport(VkCommandBuffer commands) const;

  Context& context_;
  int order_ = 4;
  std::uint32_t receiver_width_ = 0, receiver_height_ = 0;
  float viewport_x_ = 0.0f, viewport_y_ = 0.0f, viewport_width_ = 0.0f, viewport_height_ = 0.0f;
  std::uint32_t passes_ = 1, targets_per_pass_ = 1;
  Pipeline depth_pipeline_, splat_pipeline_, resolve_pipeline_;
  std::vector<Image> targets_;  // RGBA32F, passes × targets per pass
  Image depth_;                 // D32, receiver size
  Buffer bounding_mesh_;        // vec4 triangle list on the unit sphere's outside
  std::uint32_t mesh_vertices_ = 0;
};

// A convex polyhedron whose faces all lie at distance ≥ 1 from the origin (an icosahedron
// subdivided `subdivisions` times, 20 · 4^subdivisions triangles, scaled by 1 / its inradius), as
// a counter-clockwise (seen from outside) triangle list. The splat uses one subdivision (80
// triangles, 1.07× the sphere's radius at the vertices); 0 was not measurably faster on lavapipe.
std::vector<glm::vec4> unit_sphere_bounding_mesh(int subdivisions = 1);

}  // namespace proxygi::gpu
