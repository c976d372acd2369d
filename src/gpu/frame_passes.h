#pragma once
// The pipelines of the soft-GI frame, one per pass, each named after its shader (debug labels and
// timing use the names). Inputs and outputs of each pass are the bindings listed in its shader:
//   gbuffer      frame constants, positions, normals, uvs, base color texture
//                                                        → position+depth, normal, albedo, depth
//   receivers    position+depth, normal images           → receivers (1/k)
//   shadow       receivers, proxies, log-occlusion table → log-occlusion SH per receiver
//   exponentiate receivers, log SH, OL table, LH cubes   → direct E and (O_p)_0 per receiver
//   indirect     receivers, proxies, visibility table, direct, exact-operator table → indirect E
//                and ω_p per receiver,
//                and the packed shaded buffer (E_direct + E_indirect, eye depth)
//   upsample_composite  G-buffer, receiver normals, shaded, environment → display-resolution
//                irradiance (AOV), HDR radiance and tonemapped sRGB (steps 7 and 8 fused)
// The baselines (frame_settings.h ShadingMethod) reuse the passes under the same names:
//   vertex       receivers = vertex_receivers.comp (mesh vertices → receivers), then shadow,
//                exponentiate, indirect as above, then gbuffer with the vertex irradiance
//                interpolated into its second target, then the composite
//   ambient_occlusion  shadow = ambient_occlusion.comp (A and E per receiver); no exponentiate
//                or indirect
#include <array>
#include <span>

#include "gpu/frame_settings.h"
#include "gpu/pipeline.h"
#include "render/shading.h"

namespace proxygi::gpu {

class Context;

enum class FramePass { skin, gbuffer, receivers, shadow, exponentiate, indirect, upsample_composite, count };
const char* frame_pass_name(FramePass pass);
// The passes a method records, in order (skinning, run by the caller, excluded).
std::span<const FramePass> frame_pass_order(ShadingMethod method);

struct FramePipelines {
  // The G-buffer comes in an untextured and a textured pipeline. Only draws with a base color
  // texture use the textured one: on lavapipe (Mesa 22.3) a layout holding a sampled image makes
  // every per-draw descriptor push re-bind it, which cost the 20-mannequin crowd ~200 ms per
  // G-buffer pass on a quiet machine (30 ms without the binding).
  Pipeline gbuffer;
  Pipeline gbuffer_textured;
  Pipeline receivers;
  Pipeline shadow;
  Pipeline exponentiate;
  Pipeline indirect;
  Pipeline upsample_composite;
  Pipeline vertex_receivers;   // vertex method only
  Pipeline vertex_gbuffer;     // vertex method only
  Pipeline vertex_gbuffer_textured;  // vertex method only
  Pipeline ambient_occlusion;  // AO method only

  // Builds the pipelines `method` uses for SH order 3..6 (the order-dependent shaders are
  // embedded per order) with the indirect gather of one operator (embedded per operator).
  static Result<FramePipelines> create(const Context& context, int order,
                                       render::IndirectOperator indirect_operator = render::IndirectOperator::averaged,
                                       ShadingMethod method = ShadingMethod::image_space);
};

inline constexpr VkFormat kGbufferFormat = VK_FORMAT_R32G32B32A32_SFLOAT;
inline constexpr VkFormat kDepthFormat = VK_FORMAT_D32_SFLOAT;

}  // namespace proxygi::gpu
