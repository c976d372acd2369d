// FrameRequest::pass_timestamps: GPU timestamps in the frame itself, read when it finishes, for
// a live HUD that must not stall the pipeline (time_passes fences and renders a frame of its own).
#include <chrono>
#include <cstdio>
#include <utility>

#include "gpu/scene_renderer.h"

namespace proxygi::gpu {

const TimestampQueries* SceneRenderer::arm_timestamps(SlotState& slot) {
  slot.timestamps_written = 0;
  slot.timestamps_note.clear();
  slot.timed_passes = frame_pass_order(frame_->settings().method);
  // Before skinning, after it and after each pass; the largest pass list fits every method.
  const std::uint32_t needed = std::uint32_t(FramePass::count) + 1;
  if (!slot.timestamps) {
    auto made = TimestampQueries::create(context_, needed);
    if (!made) {
      slot.timestamps_note = made.message();
      return nullptr;
    }
    slot.timestamps = std::move(*made);
  }
  slot.timestamps_written = std::uint32_t(slot.timed_passes.size()) + 2;
  return &*slot.timestamps;
}

PassTimings SceneRenderer::read_timestamps(SlotState& slot) {
  PassTimings timings;
  timings.cpu_prepare_ms = slot.statistics.cpu_prepare_ms;
  timings.proxies = slot.statistics.proxies;
  const std::uint32_t written = std::exchange(slot.timestamps_written, 0);
  timings.note = std::exchange(slot.timestamps_note, {});
  if (written == 0) return timings;
  auto intervals = slot.timestamps->intervals_ms(written);
  if (!intervals) {
    timings.note = intervals.message();
    return timings;
  }
  // The device cannot have spent longer on the frame than from its submit to now.
  const double wall_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - slot.submitted).count();
  double sum = 0.0;
  for (double ms : *intervals) sum += ms;
  if (!(sum > 0.0) || sum > wall_ms) {
    char note[160];
    std::snprintf(note, sizeof note, "timestamps implausible: %.3g ms, %.3g ms from submit to finish", sum, wall_ms);
    timings.note = note;
    return timings;
  }
  timings.timestamps = true;
  timings.milliseconds[std::size_t(FramePass::skin)] = (*intervals)[0];
  for (std::size_t p = 0; p < slot.timed_passes.size(); ++p)
    timings.milliseconds[std::size_t(slot.timed_passes[p])] = (*intervals)[p + 1];
  return timings;
}

}  // namespace proxygi::gpu
