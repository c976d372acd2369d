// MeasureBlocks (`view --measure-blocks N`): the cycle of frame endings and the block means that
// leave out each block's warm-up frames. Pure bookkeeping, no GPU (label unit).
#include <gtest/gtest.h>

#include "view/measure_blocks.h"

namespace proxygi::view {
namespace {

TEST(MeasureBlocks, BlocksCycleThroughEveryEndingAndSkipTheirWarmUp) {
  MeasureBlocks blocks(4, true);
  const FrameEnd cycle[] = {FrameEnd::window, FrameEnd::window_no_ui, FrameEnd::offscreen, FrameEnd::readback};
  for (int frame = 0; frame < 32; ++frame) {
    EXPECT_EQ(blocks.next(), cycle[(frame / 4) % 4]) << "frame " << frame;
    blocks.add(frame);  // each frame "takes" its index in ms
  }
  // Window blocks: frames 0–3 and 16–19; the first two of each are warm-up.
  EXPECT_EQ(blocks.block_means(FrameEnd::window), (std::vector<double>{2.5, 18.5}));
  EXPECT_EQ(blocks.block_means(FrameEnd::window_no_ui), (std::vector<double>{6.5, 22.5}));
  EXPECT_EQ(blocks.block_means(FrameEnd::offscreen), (std::vector<double>{10.5, 26.5}));
  EXPECT_EQ(blocks.block_means(FrameEnd::readback), (std::vector<double>{14.5, 30.5}));
}

TEST(MeasureBlocks, WithoutAWindowOffscreenAndReadbackAlternateAndPartialBlocksAreLeftOut) {
  MeasureBlocks blocks(3, false);
  for (int frame = 0; frame < 8; ++frame) {
    EXPECT_EQ(blocks.next(), (frame / 3) % 2 == 0 ? FrameEnd::offscreen : FrameEnd::readback) << "frame " << frame;
    blocks.add(10.0 * frame);
  }
  EXPECT_TRUE(blocks.block_means(FrameEnd::window).empty());
  EXPECT_EQ(blocks.block_means(FrameEnd::offscreen), (std::vector<double>{20.0}));  // frames 6, 7: unfinished
  EXPECT_EQ(blocks.block_means(FrameEnd::readback), (std::vector<double>{50.0}));
}

}  // namespace
}  // namespace proxygi::view
