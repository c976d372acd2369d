#pragma once
// The sun map of the VSGL sun variant (render.vsgl_sun auto with the sun above the horizon;
// rsm.vert/.frag then rsm_sums.comp; sh/vsgl_sun.h): the senders' triangles, each light's ranges
// as VsglLightsPass splits them (vsgl_light_ranges), rasterized orthographically from the sun
// (FrameConstants::rsm_view_projection) into a kRsmSize² reflective shadow map, then summed per
// light into VsglPartials 0 .. partial_count − 1 that VsglLightsPass's fit adds to the vertex
// VPLs' sums. Recorded inside frame step 6 before VsglLightsPass (its timing is the indirect
// pass's).
//   inputs : frame constants (rsm_*), the draws' world positions, normals and indices
//   outputs: position (xyz m, w light + 1; 0: no sender), normal, flux (rgb W) images
//            (kGbufferFormat, GENERAL after the pass), depth (kDepthFormat), partials
// Only the texels a sun ray reaches first are in the map: a sender in its own (or another
// character's) sun shadow sends no sun light. Albedo is the draw's base color factor (as the
// vertex VPLs'). Deterministic: a fixed tree per workgroup.
// CPU twin: sh::rsm_texel_light / sh::add_vsgl_sun (the texels from sh::RsmView's centre rays).
#include <span>

#include "base/result.h"
#include "gpu/draw_item.h"
#include "gpu/frame_passes.h"
#include "gpu/pass_barriers.h"

namespace proxygi::gpu {

class RsmPass {
 public:
  struct Inputs {
    const Buffer* constants = nullptr;  // FrameConstants (rsm_view_projection, rsm_toward_sun, rsm_texel_flux)
    std::span<const DrawItem> draws;    // only those with vsgl_light ≥ 0 are senders
    std::uint32_t lights_per_sender = 1;  // render.vsgl_lights (VsglLightsPass::Inputs)
  };
  struct Outputs {
    const Image* position = nullptr;
    const Image* normal = nullptr;
    const Image* flux = nullptr;
    const Image* depth = nullptr;
    const Buffer* partials = nullptr;  // VsglLightsPass's partials
  };
  static constexpr FramePass kPass = FramePass::indirect;
  // Partials the pass writes for these draws (kRsmGroupsPerLight per light, lights 0 .. count − 1).
  static std::uint32_t partial_count(std::span<const DrawItem> draws, std::uint32_t lights_per_sender);

  static Result<RsmPass> create(const Context& context);
  std::vector<ResourceAccess> accesses(const Inputs& in, const Outputs& out) const;
  void record(const Context& context, VkCommandBuffer commands, const Inputs& in, const Outputs& out) const;

 private:
  Pipeline raster_, sums_;
};

}  // namespace proxygi::gpu
