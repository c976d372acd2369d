#include "run/frame_loop.h"

#include <algorithm>
#include <chrono>
#include <csignal>
#include <deque>
#include <vector>

namespace proxygi::run {

Status render_frames(gpu::SceneRenderer& renderer, std::span<const int> frames, const FrameLoopOptions& options,
                     const FrameCallback& on_finished) {
  const std::size_t ring = std::max<std::size_t>(renderer.frame().slot_count(), 1);
  const std::size_t in_flight = options.in_flight == 0 ? ring : std::min(options.in_flight, ring);
  std::deque<gpu::FrameTicket> pending;
  Status failure;
  auto finish_oldest = [&]() -> Status {
    const gpu::FrameTicket ticket = pending.front();
    pending.pop_front();
    auto finished = renderer.finish(ticket);
    if (!finished) return finished.error();
    return failure ? on_finished(*finished) : Status{};
  };
  for (int frame : frames) {
    if (options.stop != nullptr && *options.stop != 0) break;
    while (pending.size() >= in_flight)
      if (Status s = finish_oldest(); !s && failure) failure = s;
    if (!failure) break;
    gpu::FrameRequest request;
    request.time_s = scene::frame_time_s(renderer.scene().output, frame);
    request.frame = frame;
    request.output = options.output;
    auto ticket = renderer.begin(request);
    if (!ticket) {
      failure = ticket.error();
      break;
    }
    pending.push_back(*ticket);
  }
  while (!pending.empty())
    if (Status s = finish_oldest(); !s && failure) failure = s;
  return failure;
}

Result<double> time_pipelined_frames(gpu::SceneRenderer& renderer, int first, int frames, bool hdr) {
  for (int warm = 0; warm < kWarmupFrames; ++warm)
    if (auto done = renderer.render(first + warm); !done) return done.error();
  std::vector<int> timed(static_cast<std::size_t>(frames));
  for (int i = 0; i < frames; ++i) timed[std::size_t(i)] = first + kWarmupFrames + i;
  FrameLoopOptions options;
  options.output = gpu::FrameOutput::readback(hdr);  // hdr: as record with EXR (the chart's timings)
  options.output.float_targets = false;               // as record: no AOV
  options.in_flight = 2;
  const auto start = std::chrono::steady_clock::now();
  if (Status done = render_frames(renderer, timed, options, [](gpu::FinishedFrame&) { return Status{}; }); !done)
    return done.error();
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count() / frames;
}

}  // namespace proxygi::run
