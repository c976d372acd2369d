#pragma once
// The fixed-cost stages of the raster shadow splat, timed on their own for `proxygi bench frame`:
// the receiver-depth set-up and the resolve of the colour targets into the log-occlusion buffer
// (the copy the raster splat pays so exponentiate.comp keeps the gather's input layout). Neither
// depends on the proxies, so they run on placeholder buffers of the frame's receiver count.
#include <cstdint>

#include "base/result.h"
#include "gpu/context.h"

namespace proxygi::app {

struct SplatStageTimes {
  double depth_ms = 0.0;    // median of fenced submits, CPU clock
  double resolve_ms = 0.0;
};

Result<SplatStageTimes> time_splat_stages(gpu::Context& context, int order, std::uint32_t size,
                                          std::uint32_t receiver_scale, int repeats);

}  // namespace proxygi::app
