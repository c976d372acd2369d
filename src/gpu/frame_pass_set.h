#pragma once
// The pass objects one frame configuration records (frame_passes.h): only those its method uses,
// built for its SH order, indirect operator and splat, and (the raster splat) its sizes.
#include <memory>
#include <optional>

#include "base/result.h"
#include "gpu/ambient_occlusion_pass.h"
#include "gpu/exponentiate_pass.h"
#include "gpu/frame_config.h"
#include "gpu/gbuffer_pass.h"
#include "gpu/indirect_pass.h"
#include "gpu/receivers_pass.h"
#include "gpu/shadow_gather_pass.h"
#include "gpu/shadow_splat_pass.h"
#include "gpu/supersample_resolve_pass.h"
#include "gpu/upsample_composite_pass.h"
#include "gpu/vertex_receivers_pass.h"
#include "gpu/rsm_pass.h"
#include "gpu/vsgl_lights_pass.h"

namespace proxygi::gpu {

struct FramePassSet {
  std::optional<GbufferPass> gbuffer;
  std::optional<ReceiversPass> receivers;                // image-space and AO receivers
  std::optional<VertexReceiversPass> vertex_receivers;   // vertex method
  std::optional<ShadowGatherPass> shadow_gather;         // compute gather (and the vertex method)
  std::unique_ptr<ShadowSplatPass> shadow_splat;         // SplatMethod::raster, image space only
  std::optional<AmbientOcclusionPass> ambient_occlusion; // AO method
  std::optional<ExponentiatePass> exponentiate;
  std::optional<IndirectPass> indirect;
  std::optional<VsglLightsPass> vsgl_lights;             // indirect_method vsgl
  std::optional<RsmPass> rsm;                            // indirect_method vsgl, vsgl_sun auto
  std::optional<UpsampleCompositePass> upsample_composite;
  std::optional<SupersampleResolvePass> supersample_resolve;  // antialiasing ssaa* (sized: made with the targets)

  static Result<FramePassSet> create(Context& context, const FrameConfig& config);
  // The raster splat is sized by the receivers and the resolve exists with supersampled targets:
  // both rebuilt when only the targets change.
  Status rebuild_sized(Context& context, const FrameConfig& config);
};

// Whether `config` splats by rasterizing (the raster splat needs image-space receivers).
bool uses_raster_splat(const FrameConfig& config);

}  // namespace proxygi::gpu
