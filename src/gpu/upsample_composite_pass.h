#pragma once
// Upsample + composite (frame steps 7 and 8 fused, upsample_composite.comp): display-resolution
// irradiance from the 2×2 surrounding receivers (joint-bilateral eq. 11 or bilinear; the vertex
// method's G-buffer already holds it), radiance = albedo/π · E on covered pixels and the
// environment elsewhere, HDR and tonemapped sRGB out; or one of the viewer's views (layouts.h
// kDebugView*). Outputs the caller does not read (Inputs::irradiance_aov, hdr) are not written.
// CPU twins: render::upsample, render::tonemap.
#include "base/result.h"
#include "gpu/frame_passes.h"
#include "gpu/pass_barriers.h"
#include "gpu/resources.h"

namespace proxygi::gpu {

class UpsampleCompositePass {
 public:
  struct Inputs {
    const Buffer* constants = nullptr;      // FrameConstants (composite mode, ε, exposure, tonemap)
    const Image* position_depth = nullptr;  // G-buffer, GENERAL layout
    const Image* normal = nullptr;          // normal (or the vertex method's irradiance)
    const Image* albedo = nullptr;
    const Buffer* receivers = nullptr;      // read as texels: each needs its texel_view() (rgba32f)
    const Buffer* shaded = nullptr;
    const Buffer* direct = nullptr;         // the views: (E_direct, visibility DC) per receiver
    const Buffer* indirect = nullptr;       // (E_indirect, ω) per receiver
    const Buffer* tile_counts = nullptr;    // the heat map: uint per 8×8-receiver tile
    const Buffer* environment = nullptr;    // equirectangular vec4 radiance (texels too)
    std::uint32_t environment_width = 0, environment_height = 0;
    std::uint32_t width = 0, height = 0;    // display
    bool ldr_bgra = false;                  // the 8-bit frame in B8G8R8A8 byte order
    bool debug_view = false;                // frame.debug_view is not kDebugViewFinal: the views' pipeline
    bool irradiance_aov = true;             // write Outputs::irradiance (false: ":no_aov")
    bool hdr = true;                        // write Outputs::hdr (false, with no AOV: ":ldr_only")
  };
  struct Outputs {
    const Buffer* irradiance = nullptr;  // vec4 per display pixel (AOV)
    const Buffer* hdr = nullptr;         // vec4 linear radiance
    const Buffer* ldr = nullptr;         // packed RGBA8 sRGB
  };
  static constexpr FramePass kPass = FramePass::upsample_composite;

  static Result<UpsampleCompositePass> create(const Context& context);
  std::vector<ResourceAccess> accesses(const Inputs& in, const Outputs& out) const;
  void record(const Context& context, VkCommandBuffer commands, const Inputs& in, const Outputs& out) const;

 private:
  Pipeline pipeline_;           // the final frame only, every output
  Pipeline no_aov_pipeline_;    // without the irradiance AOV
  Pipeline ldr_only_pipeline_;  // the sRGB frame alone
  Pipeline views_pipeline_;     // with the viewer's views ("upsample_composite.comp:views"), every output
};

}  // namespace proxygi::gpu
