#pragma once
// The cached UI overlay (no window, no GPU: the rules and the CPU twin of its blend).
//
// Dear ImGui's panels change a few times a second, not every frame, and rasterizing them costs
// llvmpipe more than the rest of the UI. So the UI pass draws ImGui into an overlay image
// (transparent black first) only when redraw_due() says so, and every frame blends the overlay
// over the frame in the rectangles it covers (covering_rects). The overlay is premultiplied:
// ImGui's blend (colour SRC_ALPHA, ONE_MINUS_SRC_ALPHA; alpha ONE, ONE_MINUS_SRC_ALPHA) over
// (0, 0, 0, 0) leaves P = Σ layers' premultiplied colour and A = 1 − Π(1 − αᵢ), and
// P + (1 − A) · frame is what drawing the layers onto the frame gives (up to 8-bit rounding).
#include <cstdint>
#include <span>
#include <vector>

namespace proxygi::view {

// How long the panels' numbers (fps, frame times and plot, time and frame, loading progress)
// may lag without input: they are redrawn at most 4 times a second unless something else asks.
inline constexpr double kOverlayPanelPeriodS = 0.25;
// Side of the squares the covered area is rounded out to (pixels): fewer, larger scissors.
inline constexpr int kOverlayTile = 32;

// What changed since the overlay was last drawn.
struct OverlayChange {
  bool cached = false;         // an overlay of this size exists
  bool exact = false;          // a screenshot with the UI: it shows this frame's UI
  bool scene_changed = false;  // the scene overlays (proxies, skeleton, grid, wireframe) moved
  bool panels_changed = false; // the panels' draw lists differ
  bool input = false;          // an input event arrived this frame (a click must show at once)
  double since_draw_s = 0.0;   // UI clock since the overlay was drawn (wall time; a script's step)
};
// Scene overlays follow the frame under them, input and screenshots show at once; the panels
// alone wait for kOverlayPanelPeriodS. Nothing changed: never (equal draw lists, equal pixels).
bool redraw_due(const OverlayChange& change);

// A pixel rectangle, half-open: [x0, x1) × [y0, y1), row 0 on top.
struct PixelRect {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  bool empty() const { return x1 <= x0 || y1 <= y0; }
  bool operator==(const PixelRect&) const = default;
};
// Disjoint rectangles covering every pixel of `touched` (clamped to width × height): the
// kOverlayTile squares they reach, merged into runs along each row of squares, and runs of
// consecutive rows spanning the same columns into one rectangle. Disjoint, so blending each once
// is exact; pixels outside are the overlay's transparent black.
std::vector<PixelRect> covering_rects(std::span<const PixelRect> touched, int width, int height,
                                      int tile = kOverlayTile);

// CPU twin of overlay_blend.frag with its (ONE, ONE_MINUS_SRC_ALPHA) blend: frame ← P + (1 − A)
// · frame per channel, 8-bit unorm, rounded to nearest (alpha too). Both RGBA8 of one size.
void blend_overlay(std::span<const std::uint8_t> overlay, std::span<std::uint8_t> frame);

}  // namespace proxygi::view
