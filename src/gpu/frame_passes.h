#pragma once
// The passes of the soft-GI frame (DESIGN.md "One frame", steps 2–8), each its own object in a
// file named like its shader, with a struct of named inputs and outputs, the accesses it makes
// (from which PassBarriers derives the barriers between passes) and a record():
//   gbuffer_pass.h             gbuffer.vert/.frag        draws → position+depth, normal, albedo, depth
//   receivers_pass.h           receivers.comp            G-buffer → receivers (1/k)
//   shadow_gather_pass.h       shadow_gather.comp        receivers, proxies, log table → log-occlusion
//   shadow_splat_pass.h        shadow_splat.vert/.frag   the same by rasterizing spheres of influence
//   exponentiate_pass.h        exponentiate.comp         log-occlusion, OL table, LH cubes → direct E, (O_p)_0
//   indirect_pass.h            indirect.comp             proxies, visibility, direct → indirect E, ω_p, shaded
//   vsgl_lights_pass.h         vsgl_lights.comp          (indirect_method vsgl, in step 6) draws → VSGL lights
//   rsm_pass.h                 rsm.vert/.frag, rsm_sums.comp  (vsgl_sun auto, sun up; before it) draws → sun map → sums
//   upsample_composite_pass.h  upsample_composite.comp   G-buffer, shaded, environment → irradiance, HDR, sRGB
//   supersample_resolve_pass.h supersample_resolve.comp  (antialiasing ssaa*) f × f samples → display HDR, sRGB
//   vertex_receivers_pass.h    vertex_receivers.comp     (vertex baseline) mesh vertices → receivers
//   ambient_occlusion_pass.h   ambient_occlusion.comp    (AO baseline) receivers, proxies → direct, shaded
// SoftGiFrame records them in frame_pass_order(method); the baselines reuse the slots' names
// (the vertex method's "receivers" is vertex_receivers, the AO method's "shadow" is
// ambient_occlusion), so timings line up across methods.
#include <span>
#include <string>

#include "gpu/pipeline.h"
#include "gpu/resources.h"
#include "settings/render_settings.h"

namespace proxygi::gpu {

class Context;

enum class FramePass { skin, gbuffer, receivers, shadow, exponentiate, indirect, upsample_composite, supersample_resolve, count };
const char* frame_pass_name(FramePass pass);
// The passes a method records, in order (skinning, run by the caller, excluded; the supersample
// resolve records nothing when antialiasing is off).
std::span<const FramePass> frame_pass_order(settings::ShadingMethod method);

inline constexpr VkFormat kGbufferFormat = VK_FORMAT_R32G32B32A32_SFLOAT;
inline constexpr VkFormat kDepthFormat = VK_FORMAT_D32_SFLOAT;

// A compute pipeline whose bindings are (binding number, type) pairs, all in the compute stage.
struct ComputeBinding {
  std::uint32_t binding = 0;
  VkDescriptorType type = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
};
Result<Pipeline> make_compute_pipeline(const Context& context, const std::string& shader,
                                       std::span<const ComputeBinding> bindings, std::uint32_t push_bytes = 0);
// Dispatches kFrameLocalSize² workgroups over a width × height grid.
void dispatch_grid(VkCommandBuffer commands, std::uint32_t width, std::uint32_t height);

// A dynamic-rendering attachment of the whole image, stored after the pass.
VkRenderingAttachmentInfo attachment_info(const Image& image, VkImageLayout layout, VkAttachmentLoadOp load);

// Begins dynamic rendering into up to 4 colour targets and a depth target, all of extent
// width × height: the images move from UNDEFINED (their old contents are not kept), colours are
// cleared to 0 (a 0 in .w marks "nothing drawn here" to the readers), depth to 1 and not stored;
// viewport and scissor cover the whole extent. The caller ends the rendering.
void begin_cleared_rendering(VkCommandBuffer commands, std::span<const Image* const> colors, const Image& depth,
                             std::uint32_t width, std::uint32_t height);

// Embedded shader names of the order- and operator-dependent variants.
std::string order_variant(const std::string& shader, int order);  // "shadow_gather.comp:order4"

}  // namespace proxygi::gpu
