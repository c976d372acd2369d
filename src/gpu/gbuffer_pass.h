#pragma once
// G-buffer pass (frame step 2, gbuffer.vert/.frag): every draw rasterized at display resolution
// into world position + eye depth, normal (or, for the vertex method, the interpolated vertex
// irradiance) and albedo; the targets end in GENERAL layout for the compute passes.
// Draws come in an untextured and a textured pipeline: only draws with a base color texture use
// the textured one, since on lavapipe (Mesa 22.3) a layout holding a sampled image makes every
// per-draw descriptor push re-bind it (the 20-mannequin crowd's G-buffer took ~200 ms instead of
// 30 ms). Untextured draws are recorded first, then the textured ones.
#include <span>

#include "base/result.h"
#include "gpu/draw_item.h"
#include "gpu/frame_passes.h"
#include "gpu/pass_barriers.h"

namespace proxygi::gpu {

class GbufferPass {
 public:
  struct Inputs {
    const Buffer* constants = nullptr;  // FrameConstants (view-projection, eye)
    std::span<const DrawItem> draws;
    const Buffer* shaded = nullptr;     // vertex method: receivers' E (else null)
    std::uint32_t receiver_capacity = 0;  // vertex method: draws beyond it are skipped
    std::uint32_t width = 0, height = 0;
  };
  struct Outputs {
    const Image* position_depth = nullptr;  // kGbufferFormat: xyz world position, a eye depth (0: background)
    const Image* normal = nullptr;          // xyz normal (vertex method: rgb irradiance)
    const Image* albedo = nullptr;          // rgb linear albedo
    const Image* depth = nullptr;           // kDepthFormat
  };
  static constexpr FramePass kPass = FramePass::gbuffer;

  // vertex_irradiance: the vertex method's variant.
  static Result<GbufferPass> create(const Context& context, bool vertex_irradiance);
  std::vector<ResourceAccess> accesses(const Inputs& in, const Outputs& out) const;
  void record(const Context& context, VkCommandBuffer commands, const Inputs& in, const Outputs& out) const;

 private:
  bool vertex_irradiance_ = false;
  Pipeline untextured_, textured_;
};

}  // namespace proxygi::gpu
