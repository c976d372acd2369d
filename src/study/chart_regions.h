#pragma once
// `bench chart --regions`: where in the image a row's error lies. Masks are made once per frame
// from the reference's feature images (pixel-center rays: depth, normal, albedo, what was hit)
// and its direct part (radiance − indirect); every row is then scored on each mask. Whole-image
// means hide the body (about 1 % of the receivers) and the contact shadow; these do not.
//
// Regions (all inside the reference's receivers, ref::ReceiverMask conventions):
//  - shadow: non-character receivers whose reference direct luminance is below (1 − fraction) ×
//    their unshadowed direct luminance U = albedo / π · E(N), E the irradiance of the reference's
//    own SH lighting (sh/convolution.h: E = Σ A_l L_lm y_lm(N), exact for band-limited light).
//    Character pixels are left out: the ground hides their lower hemisphere everywhere.
//  - edge: pixels within `edge_radius` (Chebyshev) of a 4-neighbour depth jump (> depth_jump of
//    the nearer depth, or hit against background) or normal jump (angle > normal_jump_degrees).
//  - thin: character pixels (center ray hits a character) in no thin_width × thin_width square of
//    character pixels: limbs narrower than thin_width pixels (F9: features narrower than k miss
//    the 1/k receivers; thin_width = the default k).
//  - character: the reference's character region (its center and 8 neighbours hit a character).
//  - contact: ground within study::kContactRadiusM of a character vertex.
//  - near_wall, open_floor (scenes with static meshes, else empty): ground within
//    study::kNearWallM of a static mesh triangle, and farther than study::kOpenFloorM from all.
// Bounds, per pixel over the receivers: any channel negative; any channel non-finite; any
// channel above (U + the reference's indirect) × (1 + 1/255): brighter than unshadowed light
// plus the reference's bounce. U is at the reference's lighting, so rows at lower SH orders can
// exceed it by their own band limit as well as by ringing.
#include <array>
#include <cstddef>
#include <optional>

#include "base/result.h"
#include "image/image.h"
#include "ref/metrics.h"
#include "ref/path_tracer_lighting.h"
#include "ref/reference_render.h"
#include "scene/scene.h"
#include "sh/environment.h"
#include "study/chart_rows.h"

namespace proxygi::study {

struct ChartRegionSettings {
  double shadow_fraction = 0.05;  // above the reference's per-pixel noise (~0.6 % at 1024 spp) and texture detail
  int edge_radius = 2;            // pixels
  double depth_jump = 0.1;        // relative to the nearer eye depth
  double normal_jump_degrees = 30.0;
  int thin_width = 4;             // pixels
};

struct ChartRegions {
  std::array<ref::ReceiverMask, kChartRegionCount> masks;  // index = ChartRegion
  image::ImageF upper_bound;  // per channel: unshadowed direct + the reference's indirect
  ref::ReceiverMask receivers;
};

// The lighting the reference path tracer used, in SH: kind sh, the scene's environment at
// `reference_order` windowed as the frame windows it; kind full, its order-8 projection
// (the sun's irradiance then truncated at band 8, under 1 % off).
Result<sh::RgbSh> reference_lighting_sh(const scene::Scene& scene, ref::LightingKind kind, int reference_order);

// Unshadowed direct radiance albedo / π · E(N) per receiver pixel (0 elsewhere); rgb, a = 1.
image::ImageF unshadowed_radiance(const ref::PixelFeatures& features, const sh::RgbSh& lighting);

// The pieces, each testable on hand-made images.
ref::ReceiverMask shadow_region(const image::ImageF& direct, const image::ImageF& unshadowed, const ref::ReceiverMask& where,
                                double fraction);
ref::ReceiverMask discontinuity_band(const image::ImageF& depth, const image::ImageF& normal, int radius, double depth_jump,
                                     double normal_jump_degrees);
// Pixels of `mask` in no width × width square entirely inside `mask` (the mask minus its opening).
ref::ReceiverMask thin_region(const ref::ReceiverMask& mask, int width);

struct ReferenceRegionInputs {
  const ref::PixelFeatures* features = nullptr;
  const image::ImageF* radiance = nullptr;  // the reference's mean radiance
  const image::ImageF* indirect = nullptr;  // its indirect part
  const ref::ReceiverMask* receivers = nullptr;
  const ref::ReceiverMask* character = nullptr;       // the character region (eroded)
  const ref::ReceiverMask* character_hits = nullptr;  // every pixel whose center ray hits a character
  const ref::ReceiverMask* contact = nullptr;
  const ref::ReceiverMask* near_wall = nullptr;   // null: the region is empty
  const ref::ReceiverMask* open_floor = nullptr;
};
ChartRegions make_chart_regions(const ReferenceRegionInputs& inputs, const sh::RgbSh& lighting,
                                const ChartRegionSettings& settings = {});

// One frame's region errors and bounds of `test` (RegionErrors with weight 1: sums of the
// per-pixel relative MSE and pixel counts per region).
Result<RegionErrors> score_regions(const image::ImageF& test, const image::ImageF& reference, const ChartRegions& regions);

}  // namespace proxygi::study
