#pragma once
// Scoring the light the characters bounce, alone (issue 20, the second chart).
//
// The reference's bounce = the chart reference minus the same path trace (same seed, same
// samples) in which the characters reflect nothing after the first vertex (FrameTracer with
// character_senders = false): every path is the same, so the noise of the two largely cancels
// and what remains is exactly the light that reached a pixel off a character. A frame's bounce =
// the frame with its indirect method minus the frame with render.indirect_method none, every
// other setting the same. Both are linear RGB, same size.
//
// Error: over a mask, sum_{p, c} (x - r)^2 / sum_{p, c} r^2 (an MSE relative to the reference
// bounce's own mean square): 0 is exact, and "none" (x = 0) scores exactly 1, so a method below 1
// adds more right than wrong. Scored where the bounce is significant (kSignificantBounce of the
// pixel's reference radiance), and over each whole region (character, contact, ground, other:
// the remaining receivers, e.g. a wall), where the bounce is a small part of the light but its
// spread matters; there the reference's noise bounds how far below 1 a method can score.
#include <cstddef>
#include <vector>

#include "base/result.h"
#include "image/image.h"
#include "ref/metrics.h"
#include "study/reference_study.h"

namespace proxygi::study {

// A receiver's bounce is significant when its luminance is at least this fraction of the
// luminance of the pixel's reference radiance (and positive).
inline constexpr double kSignificantBounce = 0.02;

struct BounceReference {
  image::ImageF bounce;            // with - without character senders, linear RGB, alpha 1
  ref::ReceiverMask significant;   // receivers with a significant reference bounce
  ref::ReceiverMask character;     // FrameReference::character
  ref::ReceiverMask contact;       // FrameReference::contact
  ref::ReceiverMask ground;        // FrameReference::ground
  ref::ReceiverMask other;         // FrameReference::other (static meshes: the wall)
};

// with - without per RGB channel, alpha 1. Fails when the sizes differ.
Result<image::ImageF> bounce_image(const image::ImageF& with, const image::ImageF& without);

// Receivers where luminance(bounce) > 0 and >= fraction × luminance(full).
ref::ReceiverMask significant_bounce(const image::ImageF& bounce, const image::ImageF& full,
                                     const ref::ReceiverMask& receivers, double fraction = kSignificantBounce);

// `full` and `without_senders` are the same frame's two references (same size and samples).
Result<BounceReference> make_bounce_reference(const FrameReference& full, const FrameReference& without_senders);

struct BounceError {
  double relative_mse = -1.0;     // sum (x - r)^2 / sum r^2 over the mask; -1: empty mask
  double luminance_ratio = -1.0;  // sum lum(x) / sum lum(r) over the mask (1 = as much bounce); -1: empty
  std::size_t pixels = 0;
};
// Fails when sizes differ. An empty mask, or one where the reference bounce is 0, gives -1s.
Result<BounceError> bounce_error(const image::ImageF& test, const image::ImageF& reference, const ref::ReceiverMask& mask);

struct BounceScores {
  BounceError significant;  // every receiver with a significant bounce
  BounceError character;
  BounceError contact;
  BounceError ground;
  BounceError other;
};
Result<BounceScores> score_bounce(const image::ImageF& test_bounce, const BounceReference& reference);

// Per region, the mean over the frames whose mask was not empty (-1 where none was).
BounceScores mean_bounce_scores(const std::vector<BounceScores>& frames);

}  // namespace proxygi::study
