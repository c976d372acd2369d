#pragma once
// MeasureBlocks (`proxygi view --measure-blocks N`, scripts/viewer-measure.sh): the viewer's
// frames in blocks of N that cycle through the ways a frame can end, in one process, so each
// compares with its neighbours under the same machine state (separate processes a minute apart
// differed by ±20 % on this 2-core machine with the same code):
//   window     the frame into the swapchain image, the UI over it, presented (what a person sees)
//   window_no_ui  the same without the UI (what the present alone costs)
//   offscreen  the frame into an image of the same size and format, no UI, nothing presented
//   readback   as `bench frame` times it: the LDR and HDR read back, no UI, nothing presented
// Without a window only offscreen and readback alternate. Each block's mean frame time leaves
// out its first warm-up frames (the switch from the block before).
#include <array>
#include <cstddef>
#include <vector>

namespace proxygi::view {

enum class FrameEnd { window, window_no_ui, offscreen, readback, count };
const char* frame_end_name(FrameEnd end);

class MeasureBlocks {
 public:
  static constexpr int kWarmupFrames = 2;  // per block
  // block_frames > kWarmupFrames; with_window false: the window blocks are skipped.
  MeasureBlocks(int block_frames, bool with_window);
  int block_frames() const { return block_frames_; }
  // How the next frame ends.
  FrameEnd next() const;
  // The wall time of the frame that ended as next() said before this call.
  void add(double ms);
  // Per kind, the mean frame time of each whole block, in order (blocks k of every kind are
  // neighbours: window k, window_no_ui k, offscreen k, readback k).
  const std::vector<double>& block_means(FrameEnd end) const { return means_[std::size_t(end)]; }

 private:
  int block_frames_ = 0;
  std::vector<FrameEnd> cycle_;
  long frame_ = 0;  // frames added
  double sum_ = 0.0;
  std::array<std::vector<double>, std::size_t(FrameEnd::count)> means_;
};

}  // namespace proxygi::view
