#pragma once
// Ambient occlusion (the AO baseline's shadow step, ambient_occlusion.comp, compiled per SH order):
// E = Π_i (1 − a_i) · E(N) from the same spheres at the image-space receivers, no bounce light;
// fills direct, indirect (zero) and shaded like the proxy method. CPU twin: render::ambient_occlusion.
#include "base/result.h"
#include "gpu/frame_passes.h"
#include "gpu/pass_barriers.h"
#include "gpu/resources.h"

namespace proxygi::gpu {

class AmbientOcclusionPass {
 public:
  struct Inputs {
    const Buffer* constants = nullptr;
    const Buffer* receivers = nullptr;
    const Buffer* proxies = nullptr;        // uniform
    const Buffer* lighting_cube = nullptr;  // E(N) from the LH cubes
    std::uint32_t receiver_width = 0, receiver_height = 0;
  };
  struct Outputs {
    const Buffer* direct = nullptr;
    const Buffer* indirect = nullptr;
    const Buffer* shaded = nullptr;
    const Buffer* tile_counts = nullptr;  // uint per 8×8-receiver tile: proxies its culling kept (heat map)
  };
  static constexpr FramePass kPass = FramePass::shadow;

  static Result<AmbientOcclusionPass> create(const Context& context, int order);
  std::vector<ResourceAccess> accesses(const Inputs& in, const Outputs& out) const;
  void record(const Context& context, VkCommandBuffer commands, const Inputs& in, const Outputs& out) const;

 private:
  Pipeline pipeline_;
};

}  // namespace proxygi::gpu
