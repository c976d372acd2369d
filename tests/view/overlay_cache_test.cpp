// The cached UI overlay's rules without a GPU: when it is drawn again, the rectangles it is
// blended in, and the CPU twin of its blend.
#include <gtest/gtest.h>

#include <vector>

#include "view/overlay_cache.h"

namespace proxygi::view {
namespace {

TEST(OverlayCache, RedrawnWhenTheSceneOverlaysMoveInputArrivesOrThePanelPeriodIsOver) {
  OverlayChange change;
  EXPECT_TRUE(redraw_due(change));  // nothing cached yet
  change.cached = true;
  EXPECT_FALSE(redraw_due(change));  // nothing changed
  change.input = change.exact = true;
  change.since_draw_s = 10.0;
  EXPECT_FALSE(redraw_due(change));  // equal draw lists draw equal pixels
  change = {.cached = true, .panels_changed = true, .since_draw_s = 0.5 * kOverlayPanelPeriodS};
  EXPECT_FALSE(redraw_due(change));  // the numbers may lag a little
  change.since_draw_s = kOverlayPanelPeriodS;
  EXPECT_TRUE(redraw_due(change));
  change.since_draw_s = 0.0;
  change.input = true;
  EXPECT_TRUE(redraw_due(change));
  change.input = false, change.exact = true;
  EXPECT_TRUE(redraw_due(change));  // a screenshot shows its own frame's UI
  change = {.cached = true, .scene_changed = true};
  EXPECT_TRUE(redraw_due(change));  // proxies and skeleton follow the frame
}

TEST(OverlayCache, CoveringRectsAreDisjointInsideTheImageAndCoverEveryTouchedPixel) {
  const int width = 100, height = 70, tile = 16;
  const std::vector<PixelRect> touched = {{-5, -5, 3, 4}, {10, 10, 40, 12}, {30, 5, 50, 20}, {95, 60, 130, 90}, {60, 40, 60, 50}};
  const auto rects = covering_rects(touched, width, height, tile);
  std::vector<int> covered(std::size_t(width) * height, 0);
  for (const PixelRect& rect : rects) {
    EXPECT_FALSE(rect.empty());
    EXPECT_GE(rect.x0, 0);
    EXPECT_GE(rect.y0, 0);
    EXPECT_LE(rect.x1, width);
    EXPECT_LE(rect.y1, height);
    for (int y = rect.y0; y < rect.y1; ++y)
      for (int x = rect.x0; x < rect.x1; ++x) ++covered[std::size_t(y) * width + std::size_t(x)];
  }
  for (int c : covered) EXPECT_LE(c, 1);  // disjoint: each pixel blended at most once
  for (const PixelRect& rect : touched)
    for (int y = std::max(rect.y0, 0); y < std::min(rect.y1, height); ++y)
      for (int x = std::max(rect.x0, 0); x < std::min(rect.x1, width); ++x)
        EXPECT_EQ(covered[std::size_t(y) * width + std::size_t(x)], 1) << x << ", " << y;
  // Only the squares reached: the empty rectangle and far corners add nothing.
  int area = 0;
  for (int c : covered) area += c;
  EXPECT_LT(area, width * height / 2);
  EXPECT_TRUE(covering_rects({}, width, height, tile).empty());
}

TEST(OverlayCache, RowsSpanningTheSameColumnsMergeIntoOneRect) {
  // A panel: one rectangle, however many rows of squares it spans; a narrower bottom part stays
  // its own rectangle (the rects stay disjoint, checked for every case above).
  const std::vector<PixelRect> panel = {{5, 3, 100, 100}};
  EXPECT_EQ(covering_rects(panel, 256, 256, 32), (std::vector<PixelRect>{{0, 0, 128, 128}}));
  const std::vector<PixelRect> two = {{0, 0, 100, 64}, {0, 64, 40, 90}};
  EXPECT_EQ(covering_rects(two, 256, 256, 32), (std::vector<PixelRect>{{0, 0, 128, 64}, {0, 64, 64, 96}}));
  const std::vector<PixelRect> apart = {{0, 0, 30, 30}, {200, 0, 230, 90}};
  EXPECT_EQ(covering_rects(apart, 256, 256, 32), (std::vector<PixelRect>{{0, 0, 32, 32}, {192, 0, 256, 96}}));
}

TEST(OverlayCache, BlendIsPremultipliedOver) {
  // Transparent black keeps the frame; opaque replaces it; a half-covered layer mixes.
  std::vector<std::uint8_t> frame = {200, 100, 50, 255, 200, 100, 50, 255, 200, 100, 50, 255};
  const std::vector<std::uint8_t> overlay = {0, 0, 0, 0, 10, 20, 30, 255, 60, 0, 30, 128};
  blend_overlay(overlay, frame);
  const std::vector<std::uint8_t> expected = {200, 100, 50, 255, 10, 20, 30, 255,
                                              std::uint8_t(60 + 200 * 127 / 255.0 + 0.5), std::uint8_t(100 * 127 / 255.0 + 0.5),
                                              std::uint8_t(30 + 50 * 127 / 255.0 + 0.5), 255};
  EXPECT_EQ(frame, expected);
}

}  // namespace
}  // namespace proxygi::view
