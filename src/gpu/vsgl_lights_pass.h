#pragma once
// VSGL lights (render.indirect_method vsgl; vsgl_lights.comp): each character's skinned triangles
// as diffuse VPLs lit by the unshadowed SH irradiance, reduced on the GPU into K virtual
// spherical Gaussian lights per character (DrawItem::vsgl_light; K = render.vsgl_lights, the
// triangles split into K index ranges or, render.vsgl_grouping bone_groups, the K bone groups of
// DrawItem::vsgl_group_first), which indirect.comp:vsgl then
// evaluates at every receiver. Recorded inside frame step 6 (its timing is the indirect pass's).
//   inputs : frame constants (L̃ order 3), the draws' world positions, normals and indices, and
//            their sender exposures (DrawItem::vsgl_exposure, ref/sender_exposure.h) where present
//   outputs: partials (kVsglMaxPartials VsglPartial, scratch), lights (uvec4 count, then
//            kVsglMaxLights VsglLight)
// Sums are deterministic: a fixed tree per workgroup, partials summed in order per light.
// CPU twin: sh::triangle_light / sh::add_light / sh::fit_vsgl (the same VPLs from the same triangles).
#include <span>

#include "base/result.h"
#include "gpu/draw_item.h"
#include "gpu/frame_passes.h"
#include "gpu/pass_barriers.h"

namespace proxygi::gpu {

// The triangles [first, last) of `indices` (of draw `draw`) that light `light` summarises, for
// every sender draw and each of its lights_per_sender ranges (the split Inputs describes), in
// recording order; lights ≥ kVsglMaxLights are left out. Shared with the sun map (rsm_pass.h).
struct VsglLightRange {
  std::size_t draw = 0;
  const Buffer* indices = nullptr;
  std::uint32_t light = 0, first = 0, last = 0;
};
std::vector<VsglLightRange> vsgl_light_ranges(std::span<const DrawItem> draws, std::uint32_t lights_per_sender);
// One more than the largest light index of the ranges' senders (capped at kVsglMaxLights).
std::uint32_t vsgl_light_count(std::span<const DrawItem> draws, std::uint32_t lights_per_sender);

class VsglLightsPass {
 public:
  struct Inputs {
    const Buffer* constants = nullptr;  // FrameConstants (vsgl_sender_sh)
    std::span<const DrawItem> draws;    // only those with vsgl_light ≥ 0 are senders
    // render.vsgl_lights: triangles [k T/K, (k+1) T/K) of each draw of sender s are light s·K + k
    // (integer division, T the draw's triangle count), or with bone groups (the draw's
    // vsgl_group_first, K + 1 entries) triangles [first[k], first[k+1]) of its vsgl_indices.
    // Lights ≥ kVsglMaxLights are skipped; a light without triangles is fitted as zero.
    std::uint32_t lights_per_sender = 1;
    // Partials [0, first_partial) already hold sums of these lights (the sun map's, render.vsgl_sun):
    // the fit adds them; this pass writes its own after them.
    std::uint32_t first_partial = 0;
  };
  struct Outputs {
    const Buffer* partials = nullptr;
    const Buffer* lights = nullptr;
  };
  static constexpr FramePass kPass = FramePass::indirect;
  // Bytes of the two outputs.
  static std::size_t partials_bytes();
  static std::size_t lights_bytes();

  static Result<VsglLightsPass> create(const Context& context);
  std::vector<ResourceAccess> accesses(const Inputs& in, const Outputs& out) const;
  void record(const Context& context, VkCommandBuffer commands, const Inputs& in, const Outputs& out) const;

 private:
  Pipeline pipeline_;
};

}  // namespace proxygi::gpu
