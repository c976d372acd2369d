#pragma once
// study::GpuReceiverShader on the GPU library: the stability sweeps' ground receiver rendered by
// gpu::SoftGiFrame (see study/stability_gpu.h; only that header's interface is used, so the run
// library does not link the study library).
#include <memory>

#include "gpu/context.h"
#include "study/stability_gpu.h"

namespace proxygi::run {

// A 20 m ground quad and a narrow camera looking down at the origin from (0, 2, 0.5): the centre
// pixel of a 15² frame (k = 1) is the receiver at the origin, to within 2.5 mm.
Result<std::unique_ptr<study::GpuReceiverShader>> make_gpu_receiver_shader(gpu::Context& context);

}  // namespace proxygi::run
