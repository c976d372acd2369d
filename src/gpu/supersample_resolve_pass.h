#pragma once
// Supersampling resolve (render.antialiasing; supersample_resolve.comp): the display frame as the
// box mean of each pixel's f × f shading samples, HDR (mean radiance) and 8-bit (mean displayed
// colour, a resolve after the tonemap). Recorded after upsample_composite when f > 1; with
// antialiasing off the composite writes the display frame itself and this pass records nothing.
// CPU twin: render::resolve_supersampled.
#include "base/result.h"
#include "gpu/frame_passes.h"
#include "gpu/pass_barriers.h"
#include "gpu/resources.h"

namespace proxygi::gpu {

class SupersampleResolvePass {
 public:
  struct Inputs {
    const Buffer* sample_hdr = nullptr;  // vec4 linear radiance per shading sample, (width·f) × (height·f)
    const Buffer* sample_ldr = nullptr;  // packed RGBA8 sRGB per shading sample (R, G, B, A byte order)
    std::uint32_t width = 0, height = 0;  // display pixels
    std::uint32_t factor = 1;             // f
    bool ldr_bgra = false;                // the 8-bit frame out in B8G8R8A8 byte order
  };
  struct Outputs {
    const Buffer* hdr = nullptr;  // vec4 per display pixel
    const Buffer* ldr = nullptr;  // packed 8-bit per display pixel
  };
  static constexpr FramePass kPass = FramePass::supersample_resolve;

  static Result<SupersampleResolvePass> create(const Context& context);
  std::vector<ResourceAccess> accesses(const Inputs& in, const Outputs& out) const;
  void record(const Context& context, VkCommandBuffer commands, const Inputs& in, const Outputs& out) const;

 private:
  Pipeline pipeline_;
};

}  // namespace proxygi::gpu
