#pragma once
// Rendering a list of scene frames on a gpu::SceneRenderer, the way every command does it:
// up to the renderer's ring size in flight (frame t+1 is prepared and submitted before frame t's
// callback runs), a callback per finished frame in order, a stop flag checked between frames;
// and whole-frame timing of a pipelined run (lavapipe's GPU timestamps are unreliable,
// rendering-notes §4.2, so the CPU clock times fenced frames).
#include <csignal>
#include <functional>
#include <span>

#include "base/result.h"
#include "gpu/scene_renderer.h"

namespace proxygi::run {

using FrameCallback = std::function<Status(gpu::FinishedFrame& frame)>;

struct FrameLoopOptions {
  gpu::FrameOutput output = gpu::FrameOutput::readback();  // what each frame copies out
  std::size_t in_flight = 0;                // frames on the GPU at once; 0: the renderer's ring size
  const volatile std::sig_atomic_t* stop = nullptr;  // nonzero: begin no further frame
};

// Renders `frames` (scene frame numbers, any order) and calls on_finished for each, in order.
// The callback's error stops the loop (frames still in flight are finished and dropped).
Status render_frames(gpu::SceneRenderer& renderer, std::span<const int> frames, const FrameLoopOptions& options,
                     const FrameCallback& on_finished);

// Frames rendered before any is timed (the viewer's steady frame times skip as many).
inline constexpr int kWarmupFrames = 2;

// Renders frames first .. first + kWarmupFrames − 1 to warm up, then `frames` frames from
// first + kWarmupFrames pipelined (two in flight, as `record` runs; LDR and HDR read back as
// `record --exr` does, or with `hdr` false the LDR frame alone, as `record` without EXR and the
// viewer); returns milliseconds per frame.
Result<double> time_pipelined_frames(gpu::SceneRenderer& renderer, int first, int frames, bool hdr = true);

}  // namespace proxygi::run
