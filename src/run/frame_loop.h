#pragma once
// Whole-frame timing shared by `bench frame` and `bench chart`: frames rendered pipelined with
// two in flight (as `record` runs), wall time per frame with the CPU clock (lavapipe's GPU
// timestamps are unreliable, rendering-notes §4.2), after two warm-up frames.
#include "base/result.h"
#include "gpu/scene_renderer.h"

namespace proxygi::app {

// Renders frames first .. first + 1 to warm up, then `frames` frames from first + 2 pipelined;
// returns milliseconds per frame.
Result<double> time_pipelined_frames(gpu::SceneRenderer& renderer, int first, int frames);

}  // namespace proxygi::app
