#pragma once
// The GPU half of the stability sweeps: one ground receiver (world origin, normal +y) shaded by a
// real frame (gpu::SoftGiFrame: receivers, shadow gather or raster splat, exponentiate), one frame
// per sphere set, so a sweep can run the passes themselves beside their CPU twins. The study
// library does not link Vulkan: `proxygi bench stability` implements this with the GPU library
// (run/gpu_receiver_shader.h) and hands it to the sweeps through StabilityOptions::gpu.
#include <span>
#include <vector>

#include "base/result.h"
#include "render/frame_tables.h"
#include "render/shading.h"
#include "settings/render_settings.h"

namespace proxygi::study {

// Rec. 709 luminance of the receiver's direct irradiance E (as read back from the frame), with
// and without the frame's spheres.
struct GpuReceiverShade {
  double shadowed = 0.0;
  double unshadowed = 0.0;
};

class GpuReceiverShader {
 public:
  virtual ~GpuReceiverShader() = default;
  // Renders one frame per entry of `frames` with the frame tables `tables` (their settings:
  // order, η, τ, exponential) and the given splat method, receivers at k = 1, no indirect light.
  virtual Result<std::vector<GpuReceiverShade>> shade(const render::FrameTables& tables, settings::SplatMethod splat,
                                                      std::span<const std::vector<render::Sphere>> frames) = 0;
};

}  // namespace proxygi::study
