// The stability metrics on hand-made images; every expected value is derived in the comment.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "study/stability_metrics.h"

namespace proxygi::study {
namespace {

ref::Plane row(std::vector<float> values) {
  ref::Plane plane(int(values.size()), 1);
  plane.values = std::move(values);
  return plane;
}

TEST(StabilityBounds, CountsNegativeOverUnshadowedAndNonFinite) {
  // Unshadowed 1 everywhere: -0.1 is negative; 1.01 > 1 + 1/255 = 1.0039 is over; 1.003 is not;
  // NaN is non-finite. Max overshoot (1.01 - 1) / (1/255) = 2.55u, min -0.1.
  const ref::Plane shaded = row({-0.1f, 1.0f, 1.01f, 1.003f, std::numeric_limits<float>::quiet_NaN(), 0.5f});
  const ref::Plane open = row({1, 1, 1, 1, 1, 1});
  const BoundsCounts counts = count_bounds(shaded, open);
  EXPECT_EQ(counts.pixels, 6u);
  EXPECT_EQ(counts.negative, 1u);
  EXPECT_EQ(counts.over_unshadowed, 1u);
  EXPECT_EQ(counts.non_finite, 1u);
  EXPECT_NEAR(counts.max_overshoot_u, 2.55, 1e-4);
  EXPECT_FLOAT_EQ(float(counts.min_value), -0.1f);
  EXPECT_FALSE(counts.ok());
  // Masked to the last two pixels: only the NaN remains.
  const ref::ReceiverMask mask = ref::mask_where(6, 1, [](int x, int) { return x >= 4; });
  const BoundsCounts masked = count_bounds(shaded, open, &mask);
  EXPECT_EQ(masked.pixels, 2u);
  EXPECT_EQ(masked.negative + masked.over_unshadowed, 0u);
  EXPECT_EQ(masked.non_finite, 1u);
}

TEST(StabilityBounds, MergeSumsCountsAndKeepsExtremes) {
  BoundsCounts a = count_bounds(row({0.5f}), row({1.0f}));   // overshoot (0.5 - 1) * 255 = -127.5u
  const BoundsCounts b = count_bounds(row({1.02f}), row({1.0f}));  // 5.1u, over
  a.merge(b);
  EXPECT_EQ(a.pixels, 2u);
  EXPECT_EQ(a.over_unshadowed, 1u);
  EXPECT_NEAR(a.max_overshoot_u, 5.1, 1e-4);
  EXPECT_FLOAT_EQ(float(a.min_value), 0.5f);
}

TEST(StabilityRegions, ShadowMaskIsOnePercentBelowUnshadowed) {
  // 0.5 and 0.98 are below 0.99; 0.995 and 1 are not.
  const ref::ReceiverMask mask = shadow_mask(row({0.5f, 0.98f, 0.995f, 1.0f}), row({1, 1, 1, 1}));
  EXPECT_EQ(mask.receiver, (std::vector<std::uint8_t>{1, 1, 0, 0}));
}

TEST(StabilityRegions, EdgeBandMarksBothSidesOfDepthJumpsAndWidensByRadius) {
  // Depths 1,1,2,2,0: 1 -> 2 is a jump of 100 % (> 10 %) between pixels 1 and 2; 2 -> background
  // between 3 and 4. Radius 0 marks exactly those pixels.
  EXPECT_EQ(edge_band_mask(row({1, 1, 2, 2, 0}), 0).receiver, (std::vector<std::uint8_t>{0, 1, 1, 1, 1}));
  // A 5 % change is no edge: nothing marked.
  EXPECT_EQ(edge_band_mask(row({1, 1.05f, 1.1f}), 0).count(), 0u);
  // One jump between pixels 3 and 4 of 8, radius 1: pixels 2..5.
  EXPECT_EQ(edge_band_mask(row({1, 1, 1, 1, 3, 3, 3, 3}), 1).receiver, (std::vector<std::uint8_t>{0, 0, 1, 1, 1, 1, 0, 0}));
  // Vertical neighbours count too (2 x 2, top row near, bottom row far).
  ref::Plane square(2, 2);
  square.values = {1, 1, 5, 5};
  EXPECT_EQ(edge_band_mask(square, 0).count(), 4u);
}

TEST(StabilityRegions, LabelEdgeBandFollowsLabelChangesWhateverTheDepth) {
  // Labels -1, 0, 0, 1, 1, 1: changes between pixels 0|1 and 2|3; radius 0 marks 0..3.
  const std::vector<int> labels = {-1, 0, 0, 1, 1, 1};
  EXPECT_EQ(label_edge_band_mask(6, 1, labels, 0).receiver, (std::vector<std::uint8_t>{1, 1, 1, 1, 0, 0}));
  // Radius 1 widens it by one pixel: 0..4.
  EXPECT_EQ(label_edge_band_mask(6, 1, labels, 1).receiver, (std::vector<std::uint8_t>{1, 1, 1, 1, 1, 0}));
}

TEST(StabilityRegions, LabelsContactBandAndCombinations) {
  const std::vector<int> labels = {0, 1, 1, 2};
  const ref::ReceiverMask character = label_mask(4, 1, labels, 1);
  EXPECT_EQ(character.receiver, (std::vector<std::uint8_t>{0, 1, 1, 0}));
  const ref::ReceiverMask contact = contact_band_mask(row({0.5f, 2.0f, 0.99f, 1.0f}));  // d/r < 1
  EXPECT_EQ(contact.receiver, (std::vector<std::uint8_t>{1, 0, 1, 0}));
  EXPECT_EQ(mask_and(character, contact).receiver, (std::vector<std::uint8_t>{0, 0, 1, 0}));
  EXPECT_EQ(mask_and_not(character, contact).receiver, (std::vector<std::uint8_t>{0, 1, 0, 0}));
}

TEST(StabilityErrors, AbsoluteErrorMeanAndMax) {
  // |1-0| = 1, |2-2| = 0, |0-3| = 3: mean 4/3, max 3.
  const ErrorSummary e = absolute_error(row({1, 2, 0}), row({0, 2, 3}));
  EXPECT_EQ(e.pixels, 3u);
  EXPECT_NEAR(e.mean, 4.0 / 3.0, 1e-12);
  EXPECT_EQ(e.max, 3.0);
}

TEST(StabilityTemporal, GradientErrorFollowsTheReprojection) {
  // The world moves one pixel right: pixel p of frame t shows what pixel p-1 showed (pixel 0 is
  // disoccluded). Pixel 1: dx = 2 - 0 = 2, dr = 2 - 0 = 2 -> 0. Pixel 2: dx = 5 - 1 = 4, dr = 3 - 1
  // = 2 -> 2. Mean 1 over 2 pixels, max 2.
  const Reprojection to_previous{3, 1, {-1, 0, 1}};
  const ErrorSummary e = temporal_gradient_error(row({0, 1, 2}), row({1, 2, 5}), row({0, 1, 2}), row({1, 2, 3}), to_previous);
  EXPECT_EQ(e.pixels, 2u);
  EXPECT_DOUBLE_EQ(e.mean, 1.0);
  EXPECT_DOUBLE_EQ(e.max, 2.0);
  // Identical sequences have no error whatever the motion.
  EXPECT_EQ(temporal_gradient_error(row({0, 1, 2}), row({1, 2, 5}), row({0, 1, 2}), row({1, 2, 5}), to_previous).max, 0.0);
}

TEST(StabilityTemporal, PopIsTheSecondDifferenceAgainstTheReference) {
  // x: 0, 1, 3 -> a = 3 - 2 + 0 = 1; r: 0, 1, 2 -> a = 0. Error 1. A linear ramp in both: 0.
  const ref::Plane x[3] = {row({0}), row({1}), row({3})};
  const ref::Plane r[3] = {row({0}), row({1}), row({2})};
  const Reprojection same = Reprojection::identity(1, 1);
  EXPECT_DOUBLE_EQ(pop_error(std::span<const ref::Plane, 3>(x, 3), std::span<const ref::Plane, 3>(r, 3), same, same).mean, 1.0);
  EXPECT_DOUBLE_EQ(pop_error(std::span<const ref::Plane, 3>(r, 3), std::span<const ref::Plane, 3>(r, 3), same, same).max, 0.0);
  // A disoccluded neighbour leaves the pixel out.
  const Reprojection gone{1, 1, {-1}};
  EXPECT_EQ(pop_error(std::span<const ref::Plane, 3>(x, 3), std::span<const ref::Plane, 3>(r, 3), gone, same).pixels, 0u);
}

TEST(StabilityTemporal, FlickerIsTheMeanDeviationOverFrames) {
  // Point 0 constant (deviation 0); point 1 alternates 0, 2 (population std 1). Mean 0.5, max 1.
  const std::vector<ref::Plane> frames = {row({1, 0}), row({1, 2}), row({1, 0}), row({1, 2})};
  std::vector<Reprojection> same(4, Reprojection::identity(2, 1));
  const FlickerSummary f = flicker(frames, same);
  EXPECT_EQ(f.points, 2u);
  EXPECT_DOUBLE_EQ(f.mean, 0.5);
  EXPECT_DOUBLE_EQ(f.max, 1.0);
  EXPECT_DOUBLE_EQ(f.p99, 1.0);
  // Point 0 not visible in frame 2: only point 1 is scored.
  same[2].source = {-1, 1};
  EXPECT_EQ(flicker(frames, same).points, 1u);
  EXPECT_DOUBLE_EQ(flicker(frames, same).mean, 1.0);
  // The camera moved: frame 1 shows the points swapped, and the reprojection undoes it.
  const std::vector<ref::Plane> moved = {row({1, 0}), row({2, 1})};
  const std::vector<Reprojection> swap = {Reprojection::identity(2, 1), Reprojection{2, 1, {1, 0}}};
  EXPECT_DOUBLE_EQ(flicker(moved, swap).mean, 0.5);  // point 0: 1, 1 -> 0; point 1: 0, 2 -> 1
}

}  // namespace
}  // namespace proxygi::study
