#pragma once
// Temporal metrics of a rendered frame sequence against a reference sequence of the same scene
// (`proxygi compare --sequence`; notes/stability.md §2), with exact reprojection: each pixel
// centre's primary hit (Embree on the world posed at that frame, ref::world_meshes) is the same
// triangle and barycentrics in every other frame, moved with the skinned meshes and projected with
// that frame's camera; it is kept where that frame's own primary hit at the pixel lies within 1 %
// of its depth (disocclusions masked). Values are Rec. 709 luminance of linear radiance.
//
//   auto frames = trace_sequence(world, geometry, first, last, width, height);   // per frame
//   auto scores = score_sequence(test_luminance, reference_luminance, *frames);
#include <vector>

#include "base/result.h"
#include "ref/scene_geometry.h"
#include "study/stability_metrics.h"
#include "world/world.h"

namespace proxygi::study {

// One frame's primary hits at pixel centres, and its posed meshes (for the points' positions).
struct SequenceFrame {
  int frame = 0;
  scene::CameraState camera;
  std::vector<ref::TriangleMesh> meshes;
  std::vector<ref::SurfaceHit> hits;  // width × height, row-major; mesh == kNoTriangle: background
  std::vector<float> depth;           // eye depth of the hit, m; 0: background
  std::vector<std::uint8_t> character;  // 1 where a character's mesh is hit
};
struct TracedSequence {
  int width = 0, height = 0;
  std::vector<SequenceFrame> frames;  // first..last
};
// Traces frames first..last (scene frame numbers) of `world` at width × height.
Result<TracedSequence> trace_sequence(const world::World& world, const ref::SceneGeometry& geometry, int first, int last,
                                      int width, int height);

// Pixel p of frame `from` → the pixel of frame `to` showing the same surface point, or -1.
Reprojection reproject_exact(const TracedSequence& sequence, std::size_t from, std::size_t to);

// Over all scored pixels, the character's and the rest ("static": ground and static meshes).
struct TemporalScores {
  ErrorSummary gradient;        // E_Δ: per frame pair t−1 → t, mean of the means, max of the maxima
  ErrorSummary pop;             // E_a over frames with both neighbours
  FlickerSummary flicker_test;  // F of the test on the static world's points seen in every frame
  FlickerSummary flicker_reference;  // the same for the reference (its noise floor)
  FlickerSummary flicker_error;      // F of test − reference
  std::size_t reprojected = 0;  // pixel pairs scored by E_Δ (all frame pairs)
  double reference_mean = 0.0;  // the reference's mean over the region's pixels and frames (scale for the above)
};
struct SequenceScores {
  TemporalScores all, character, static_world;
};
// test[i] and reference[i] are frame i's luminance planes (width × height of the sequence).
Result<SequenceScores> score_sequence(std::span<const ref::Plane> test, std::span<const ref::Plane> reference,
                                      const TracedSequence& sequence);

}  // namespace proxygi::study
