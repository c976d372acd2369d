#pragma once
// Shadow gather (frame step 4, shadow_gather.comp, compiled per SH order): per receiver the sum of
// the rotated log-occlusion vectors of the proxies whose sphere of influence η·r reaches it, with
// tiled culling (frame_common.glsl). CPU twin: render::accumulate_log_occlusion.
#include "base/result.h"
#include "gpu/frame_passes.h"
#include "gpu/pass_barriers.h"
#include "gpu/resources.h"

namespace proxygi::gpu {

class ShadowGatherPass {
 public:
  struct Inputs {
    const Buffer* constants = nullptr;  // FrameConstants (η, proxy count, sizes)
    const Buffer* receivers = nullptr;
    const Buffer* proxies = nullptr;    // ProxySphere[kMaxProxies], uniform
    const Buffer* log_table = nullptr;  // faded ZH log-occlusion table
    std::uint32_t receiver_width = 0, receiver_height = 0;
  };
  struct Outputs {
    const Buffer* log_occlusion = nullptr;  // receivers × n² floats
    const Buffer* tile_counts = nullptr;    // uint per 8×8-receiver tile: proxies its culling kept (heat map)
  };
  static constexpr FramePass kPass = FramePass::shadow;

  static Result<ShadowGatherPass> create(const Context& context, int order);
  std::vector<ResourceAccess> accesses(const Inputs& in, const Outputs& out) const;
  void record(const Context& context, VkCommandBuffer commands, const Inputs& in, const Outputs& out) const;

 private:
  Pipeline pipeline_;
};

}  // namespace proxygi::gpu
