#pragma once
// The stability study's metrics (../shared/notes/stability.md §2), on images or receiver sets
// held as ref::Plane (a receiver set is a width x 1 plane). Values are linear shading (irradiance
// or radiance) unless a function says otherwise.
//
// u, the display step: 1/255 of the unshadowed shade of the same receiver (notes: "u = 1/255 of
// the unshadowed shade"). Bounds and steps are counted in u so thresholds read like the notes'.
//
// Regions (masks, ref::ReceiverMask conventions): shadow (reference darker than unshadowed by more
// than 1 %), edge band (pixels within a radius of a depth discontinuity), labels (character as
// receiver, thin features: an id image), contact band (distance to the nearest proxy surface
// below a multiple of its radius).
//
// Temporal metrics take exact reprojections: for each pixel of one frame, the index of the pixel
// showing the same world point in another frame, or -1 (disoccluded / off screen), as the
// rasterizer's world positions give them. Disoccluded pixels do not enter the means.
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "ref/metrics.h"
#include "ref/metrics_plane.h"

namespace proxygi::study {

inline constexpr double kDisplayStep = 1.0 / 255.0;  // u, as a fraction of the unshadowed shade

// Bounds of a shaded output against its unshadowed shade, pixel by pixel (mask: every pixel when null).
struct BoundsCounts {
  std::size_t pixels = 0;           // pixels looked at
  std::size_t negative = 0;         // ψ < 0
  std::size_t over_unshadowed = 0;  // ψ > ψ_unshadowed (1 + 1/255): brighter than no blocker by more than 1u
  std::size_t non_finite = 0;       // NaN or ±Inf
  double max_overshoot_u = 0.0;     // max (ψ − ψ_unshadowed) / u over finite pixels (≤ 0: never brighter)
  double min_value = 0.0;           // min ψ over finite pixels
  bool ok() const { return negative == 0 && over_unshadowed == 0 && non_finite == 0; }
  void merge(const BoundsCounts& other);  // sums counts, keeps the extremes
};
// shaded and unshadowed must have the same size (checked).
BoundsCounts count_bounds(const ref::Plane& shaded, const ref::Plane& unshadowed, const ref::ReceiverMask* mask = nullptr);

// Shadow: reference < (1 − fraction) × unshadowed.
ref::ReceiverMask shadow_mask(const ref::Plane& reference, const ref::Plane& unshadowed, double fraction = 0.01);
// Edge band: pixels within `radius` pixels (Chebyshev) of a pixel pair (4-neighbours) that is a
// depth discontinuity: one is background (depth ≤ 0) and the other not, or their eye depths differ
// by more than `relative_jump` × the nearer one.
ref::ReceiverMask edge_band_mask(const ref::Plane& eye_depth, int radius, double relative_jump = 0.1);
// Pixels within `radius` pixels of a label change between 4-neighbours (silhouettes of objects
// against each other and the background, whatever their depths).
ref::ReceiverMask label_edge_band_mask(int width, int height, std::span<const int> labels, int radius);
// Pixels whose label equals `label` (labels.size() = width * height).
ref::ReceiverMask label_mask(int width, int height, std::span<const int> labels, int label);
// Contact band: distance to the nearest proxy surface / that proxy's radius below `limit` (d < r).
ref::ReceiverMask contact_band_mask(const ref::Plane& distance_over_radius, double limit = 1.0);
// Pixels in both masks (same size, checked).
ref::ReceiverMask mask_and(const ref::ReceiverMask& a, const ref::ReceiverMask& b);
ref::ReceiverMask mask_and_not(const ref::ReceiverMask& a, const ref::ReceiverMask& b);

// Mean and max of |x − r| over the mask (every pixel when null); pixels = how many entered.
struct ErrorSummary {
  double mean = 0.0;
  double max = 0.0;
  std::size_t pixels = 0;
};
ErrorSummary absolute_error(const ref::Plane& test, const ref::Plane& reference, const ref::ReceiverMask* mask = nullptr);

struct Reprojection {
  int width = 0;
  int height = 0;
  std::vector<int> source;  // per pixel of this frame: pixel index in the other frame, or -1
  static Reprojection identity(int width, int height);  // a static world seen by a static camera
};

// Temporal-gradient error E_Δ: mean and max over pixels p of frame t with a valid source q in t−1 of
// |(x_t(p) − x_{t−1}(q)) − (r_t(p) − r_{t−1}(q))|.
ErrorSummary temporal_gradient_error(const ref::Plane& x_previous, const ref::Plane& x_current, const ref::Plane& r_previous,
                                     const ref::Plane& r_current, const Reprojection& current_to_previous);
// Pop E_a: mean and max of |a_t(x) − a_t(r)|, a_t = x_{t+1} − 2 x_t + x_{t−1} at the world point of
// each pixel of frame t (sources in t−1 and t+1 both valid).
ErrorSummary pop_error(std::span<const ref::Plane, 3> x, std::span<const ref::Plane, 3> r, const Reprojection& current_to_previous,
                       const Reprojection& current_to_next);

// Flicker on a static world: F = mean over the world points of frame 0 seen in every frame of the
// standard deviation over frames of x_t at that point (to_frame[t] maps frame 0's pixels into frame
// t; to_frame[0] is the identity). p99 = the 99th percentile of the per-point deviations.
struct FlickerSummary {
  double mean = 0.0;
  double p99 = 0.0;
  double max = 0.0;
  std::size_t points = 0;
};
FlickerSummary flicker(std::span<const ref::Plane> frames, std::span<const Reprojection> to_frame);

}  // namespace proxygi::study
