#pragma once
// Guided image filter (He, Sun, Tang, ECCV 2010) with a multi-channel guide, used as Bauszat,
// Eisemann, Magnor, "Guided Image Filtering for Interactive High-quality Global Illumination"
// (EGSR 2011) use it for path tracing.
//
// Who guides whom (Bauszat §3.3): inside every (2r+1)^2 window w_k the output is a linear function
// of the noise-free *feature* image I (normal and depth, optionally albedo): q_i = a_k . I_i + b_k,
// with a_k, b_k the ridge-regularized least-squares fit of that linear function to the *noisy*
// indirect illumination p in w_k:
//     a_k = (Sigma_k + diag(epsilon))^-1 cov_k(I, p),   b_k = mean_k(p) - a_k . mean_k(I),
// then a, b are averaged over all windows covering a pixel. In He et al.'s terms the features are
// the guide and the noisy image the filter input; Bauszat's paper words it the other way round
// ("the noisy image guides the fit of the feature image") but it is the same computation. The
// output has no noise of its own (it is built from the features), keeps edges present in the
// features, and cannot reproduce detail absent from them (contact shadows, caustics).
//
// Each color channel is fitted on its own. Every mean is a box mean over the window cut to the
// image, from summed-area tables: O(pixels * d^2) whatever the radius.
//
// Apply it to the *indirect* term only (Bauszat §3.1): direct light has high frequencies the
// features do not explain. The caller adds the (separately estimated) direct term afterwards.
#include <span>
#include <vector>

#include "base/result.h"
#include "image/image.h"
#include "ref/metrics_plane.h"

namespace proxygi::ref {

// Bauszat's feature channels, each scaled to about [0, 1] as in the paper.
struct GuideFeatures {
  const image::ImageF* normal = nullptr;  // rgb = unit normal (any fixed space) in [-1, 1]; used as (n + 1) / 2
  const image::ImageF* depth = nullptr;   // r = linear depth; used as depth / depth_scale
  float depth_scale = 1.0f;               // a constant of the scene's extent (not per frame)
  const image::ImageF* albedo = nullptr;  // optional: rgb albedo in [0, 1]
};

// Defaults from Bauszat §4: radius 24-32 pixels, epsilon 0.01 for normals, 0.01-0.03 for depth.
struct GuidedFilterOptions {
  int radius = 24;
  float epsilon_normal = 0.01f;
  float epsilon_depth = 0.02f;
  float epsilon_albedo = 0.01f;
};

// Filters rgb of `noisy_indirect` (alpha copied) with the features that are given (at least one).
// Fails when sizes differ, no feature is given, radius < 1 or an epsilon is not positive.
Result<image::ImageF> guided_filter_indirect(const image::ImageF& noisy_indirect, const GuideFeatures& features,
                                             const GuidedFilterOptions& options = {});

// General form: guide = d planes (1 <= d <= 8), epsilon = one regularizer per plane (> 0).
Result<image::ImageF> guided_filter(const image::ImageF& input, std::span<const Plane> guide,
                                    std::span<const float> epsilon, int radius);

}  // namespace proxygi::ref
