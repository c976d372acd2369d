#pragma once
// Receivers pass (frame step 3, receivers.comp): one receiver per k×k block of display pixels,
// the block's center texel, or the first covered texel when the center is background.
// CPU twin: render::select_receiver.
#include "base/result.h"
#include "gpu/frame_passes.h"
#include "gpu/pass_barriers.h"
#include "gpu/resources.h"

namespace proxygi::gpu {

class ReceiversPass {
 public:
  struct Inputs {
    const Buffer* constants = nullptr;     // FrameConstants (sizes, k)
    const Image* position_depth = nullptr; // G-buffer, GENERAL layout
    const Image* normal = nullptr;
    std::uint32_t receiver_width = 0, receiver_height = 0;
  };
  struct Outputs {
    const Buffer* receivers = nullptr;  // Receiver per receiver pixel
  };
  static constexpr FramePass kPass = FramePass::receivers;

  static Result<ReceiversPass> create(const Context& context);
  std::vector<ResourceAccess> accesses(const Inputs& in, const Outputs& out) const;
  void record(const Context& context, VkCommandBuffer commands, const Inputs& in, const Outputs& out) const;

 private:
  Pipeline pipeline_;
};

}  // namespace proxygi::gpu
