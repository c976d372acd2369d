#pragma once
// SSIM (Wang, Bovik, Sheikh, Simoncelli 2004) with the paper's settings: an 11x11 Gaussian window
// (sigma 1.5, weights normalized to 1), K1 = 0.01, K2 = 0.03, data range L = 1, population
// (not sample) variances.
//
// What it is computed on: each of R, G, B separately, after mapping linear radiance to display
// values v -> linear_to_srgb(clamp(exposure * v, 0, 1)), i.e. what an sRGB display shows, so the
// data range is exactly 1 for LDR and HDR input alike (HDR highlights above 1 saturate: use
// exposure < 1 to look at them). The per-pixel map is the mean over R, G, B of the channel SSIM.
//
// Borders: like Wang's reference code ('valid' filtering), SSIM exists only where the whole
// window fits, i.e. pixels at least 5 from every border; others get 0 in the map and are left out
// of the mean. Images smaller than 11x11 are refused. With a ReceiverMask, windows still see every
// pixel; the mask selects which window centers are averaged.
#include "ref/metrics.h"

namespace proxygi::ref {

struct SsimOptions {
  float exposure = 1.0f;  // linear scale applied before the display clamp
};

Result<MetricResult> ssim(const image::ImageF& test, const image::ImageF& reference, const ReceiverMask* mask = nullptr,
                          const SsimOptions& options = {});

}  // namespace proxygi::ref
