#pragma once
// Indirect (frame step 6, indirect.comp, one variant per operator): bounce light from the proxies,
// Σ_i κ_i (V_i · H(N)) normalized by ξ_p (eq. 12), κ_i from the receiver's sender light L̃_N, and the packed shaded buffer (E_direct +
// E_indirect, eye depth) the upsampler reads. CPU twin: render::accumulate_indirect.
// indirect_method vsgl: the variant "indirect.comp:vsgl" sums the closed form of the VSGL lights
// (vsgl_lights_pass.h) instead; CPU twin sh::vsgl_irradiance.
#include "base/result.h"
#include "gpu/frame_passes.h"
#include "gpu/pass_barriers.h"
#include "gpu/resources.h"

namespace proxygi::gpu {

class IndirectPass {
 public:
  struct Inputs {
    const Buffer* constants = nullptr;         // FrameConstants (η, L̃, indirect on/off)
    const Buffer* receivers = nullptr;
    const Buffer* proxies = nullptr;           // uniform
    const Buffer* visibility_table = nullptr;  // faded order-3 ZH visibility
    const Buffer* direct = nullptr;            // exponentiate's output
    const Buffer* exact_table = nullptr;       // M(s) rows (read by the exact variant only)
    const Buffer* vsgl_lights = nullptr;       // VsglLightsPass's lights (read by the vsgl variant only)
    const Buffer* sender_light = nullptr;      // L̃_N cube texels, (r, g, b, 0) per coefficient (FrameTables::sender_light_cube; not vsgl)
    std::uint32_t receiver_width = 0, receiver_height = 0;
  };
  struct Outputs {
    const Buffer* indirect = nullptr;  // vec4 per receiver: rgb E_indirect, a ω_p
    const Buffer* shaded = nullptr;    // vec4 per receiver: rgb E_direct + E_indirect, a eye depth
  };
  static constexpr FramePass kPass = FramePass::indirect;

  // The variant of render.indirect_method (vsgl) or else of render.indirect_operator.
  static Result<IndirectPass> create(const Context& context, const settings::RenderSettings& render);
  std::vector<ResourceAccess> accesses(const Inputs& in, const Outputs& out) const;
  void record(const Context& context, VkCommandBuffer commands, const Inputs& in, const Outputs& out) const;

 private:
  Pipeline pipeline_;
};

}  // namespace proxygi::gpu
