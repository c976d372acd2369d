#pragma once
// Exponentiate (frame step 5, exponentiate.comp, compiled per SH order): O_p = exp*(f) by HYB (or
// OL alone when τ is the float maximum) and direct E = O_p · LH(N) from the lighting cubes.
// CPU twin: render::shade_direct.
#include "base/result.h"
#include "gpu/frame_passes.h"
#include "gpu/pass_barriers.h"
#include "gpu/resources.h"

namespace proxygi::gpu {

class ExponentiatePass {
 public:
  struct Inputs {
    const Buffer* constants = nullptr;       // FrameConstants (τ, OL table size, cube size)
    const Buffer* receivers = nullptr;
    const Buffer* log_occlusion = nullptr;   // receivers × n²
    const Buffer* optimal_linear = nullptr;  // OL (a, b) rows
    const Buffer* lighting_cube = nullptr;   // LH(N) cubes r, g, b
    std::uint32_t receiver_width = 0, receiver_height = 0;
  };
  struct Outputs {
    const Buffer* direct = nullptr;  // vec4 per receiver: rgb E_direct, a (O_p)_0
  };
  static constexpr FramePass kPass = FramePass::exponentiate;

  static Result<ExponentiatePass> create(const Context& context, int order);
  std::vector<ResourceAccess> accesses(const Inputs& in, const Outputs& out) const;
  void record(const Context& context, VkCommandBuffer commands, const Inputs& in, const Outputs& out) const;

 private:
  Pipeline pipeline_;
};

}  // namespace proxygi::gpu
