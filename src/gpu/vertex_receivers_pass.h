#pragma once
// Vertex receivers (the vertex baseline's receiver step, vertex_receivers.comp): every vertex of
// every draw becomes a receiver, each draw starting a group of kVertexReceiverGroup (frame_config.h),
// so tiled culling bounds one mesh patch. Padding reads as "no receiver" (eye depth 0).
#include <span>

#include "base/result.h"
#include "gpu/draw_item.h"
#include "gpu/frame_passes.h"
#include "gpu/pass_barriers.h"

namespace proxygi::gpu {

class VertexReceiversPass {
 public:
  struct Inputs {
    std::span<const DrawItem> draws;       // world-space positions and normals
    std::uint32_t receiver_capacity = 0;   // FrameConfig::vertex_receivers; draws beyond it are skipped
  };
  struct Outputs {
    const Buffer* receivers = nullptr;
  };
  static constexpr FramePass kPass = FramePass::receivers;

  static Result<VertexReceiversPass> create(const Context& context);
  std::vector<ResourceAccess> accesses(const Inputs& in, const Outputs& out) const;
  void record(const Context& context, VkCommandBuffer commands, const Inputs& in, const Outputs& out) const;

 private:
  Pipeline pipeline_;
};

}  // namespace proxygi::gpu
