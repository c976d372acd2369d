#pragma once
// Exponentiate (frame step 5, exponentiate.comp, compiled per SH order): O_p = exp*(f) by HYB (or
// OL alone when τ is the float maximum) and direct E = O_p · LH(N) from the lighting cubes.
// CPU twin: render::exponentiate_and_shade. The static-transfer variants (render.static_transfer
// ratio, l1: "exponentiate.comp:order<n>:<level>") also read the PRT field and give receivers on
// a PRT triangle its E instead (static_transfer.glsl; CPU twin prt::static_receiver_direct), and
// other receivers inside the static meshes' visibility grid (O_p ∗ V_s) · LH(N)
// (prt::character_receiver_direct).
#include "base/result.h"
#include "gpu/frame_passes.h"
#include "gpu/pass_barriers.h"
#include "gpu/resources.h"
#include "settings/render_settings.h"

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
    // The static-transfer variants only (layouts.h kExponentiateBindStatic*; SoftGiFrame::StaticTransfer).
    const Buffer* static_positions = nullptr;
    const Buffer* static_triangles = nullptr;
    const Buffer* static_grid = nullptr;
    const Buffer* static_records = nullptr;
    const Buffer* static_visibility = nullptr;  // the static meshes' visibility grid (kStaticVisibilityHeader)
  };
  struct Outputs {
    const Buffer* direct = nullptr;  // vec4 per receiver: rgb E_direct, a (O_p)_0
  };
  static constexpr FramePass kPass = FramePass::exponentiate;

  static Result<ExponentiatePass> create(const Context& context, int order,
                                         settings::StaticTransfer level = settings::StaticTransfer::l0);
  std::vector<ResourceAccess> accesses(const Inputs& in, const Outputs& out) const;
  void record(const Context& context, VkCommandBuffer commands, const Inputs& in, const Outputs& out) const;

 private:
  Pipeline pipeline_;
  bool static_transfer_ = false;
};

}  // namespace proxygi::gpu
