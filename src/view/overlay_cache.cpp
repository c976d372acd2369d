#include "view/overlay_cache.h"

#include <algorithm>
#include <cmath>

namespace proxygi::view {

bool redraw_due(const OverlayChange& change) {
  if (!change.cached || change.scene_changed) return true;
  if (!change.panels_changed) return false;
  return change.exact || change.input || change.since_draw_s >= kOverlayPanelPeriodS;
}

std::vector<PixelRect> covering_rects(std::span<const PixelRect> touched, int width, int height, int tile) {
  std::vector<PixelRect> rects;
  if (width <= 0 || height <= 0 || tile <= 0) return rects;
  const int columns = (width + tile - 1) / tile, rows = (height + tile - 1) / tile;
  std::vector<std::uint8_t> marked(std::size_t(columns) * std::size_t(rows), 0);
  for (const PixelRect& rect : touched) {
    const PixelRect clamped{std::max(rect.x0, 0), std::max(rect.y0, 0), std::min(rect.x1, width), std::min(rect.y1, height)};
    if (clamped.empty()) continue;
    for (int row = clamped.y0 / tile; row <= (clamped.y1 - 1) / tile; ++row)
      for (int column = clamped.x0 / tile; column <= (clamped.x1 - 1) / tile; ++column)
        marked[std::size_t(row) * std::size_t(columns) + std::size_t(column)] = 1;
  }
  for (int row = 0; row < rows; ++row) {
    for (int column = 0; column < columns;) {
      if (!marked[std::size_t(row) * std::size_t(columns) + std::size_t(column)]) {
        ++column;
        continue;
      }
      const int first = column;
      while (column < columns && marked[std::size_t(row) * std::size_t(columns) + std::size_t(column)]) ++column;
      const PixelRect run{first * tile, row * tile, std::min(column * tile, width), std::min((row + 1) * tile, height)};
      // A run spanning the same columns as a rect ending at the row above extends it (fewer,
      // taller rects: each is a draw of its own).
      const auto above = std::find_if(rects.begin(), rects.end(), [&](const PixelRect& r) {
        return r.x0 == run.x0 && r.x1 == run.x1 && r.y1 == run.y0;
      });
      if (above != rects.end()) above->y1 = run.y1;
      else rects.push_back(run);
    }
  }
  return rects;
}

void blend_overlay(std::span<const std::uint8_t> overlay, std::span<std::uint8_t> frame) {
  const std::size_t count = std::min(overlay.size(), frame.size()) / 4 * 4;
  for (std::size_t pixel = 0; pixel < count; pixel += 4) {
    const double keep = 1.0 - overlay[pixel + 3] / 255.0;
    for (std::size_t c = 0; c < 4; ++c) {
      const double value = overlay[pixel + c] / 255.0 + keep * (frame[pixel + c] / 255.0);
      frame[pixel + c] = std::uint8_t(std::lround(std::clamp(value, 0.0, 1.0) * 255.0));
    }
  }
}

}  // namespace proxygi::view
