#include "view/measure_blocks.h"

namespace proxygi::view {

const char* frame_end_name(FrameEnd end) {
  switch (end) {
    case FrameEnd::window: return "window";
    case FrameEnd::window_no_ui: return "window_no_ui";
    case FrameEnd::offscreen: return "offscreen";
    case FrameEnd::readback: return "readback";
    case FrameEnd::count: break;
  }
  return "?";
}

MeasureBlocks::MeasureBlocks(int block_frames, bool with_window)
    : block_frames_(block_frames),
      cycle_(with_window ? std::vector<FrameEnd>{FrameEnd::window, FrameEnd::window_no_ui, FrameEnd::offscreen, FrameEnd::readback}
                         : std::vector<FrameEnd>{FrameEnd::offscreen, FrameEnd::readback}) {}

FrameEnd MeasureBlocks::next() const { return cycle_[std::size_t(frame_ / block_frames_) % cycle_.size()]; }

void MeasureBlocks::add(double ms) {
  const FrameEnd end = next();
  const int position = int(frame_ % block_frames_);
  if (position >= kWarmupFrames) sum_ += ms;
  if (position == block_frames_ - 1) {
    means_[std::size_t(end)].push_back(sum_ / (block_frames_ - kWarmupFrames));
    sum_ = 0.0;
  }
  ++frame_;
}

}  // namespace proxygi::view
