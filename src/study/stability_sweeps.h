#pragma once
// The stability study's stress sweeps (../shared/notes/stability.md §3), run by
// `proxygi bench stability`. Each sweep is a synthetic receiver set (receivers with normals, sphere
// proxies) shaded by the frame's CPU twins (render/shading.h: the formulas the GPU passes are
// tested against) and scored against the exact answer: the true visibility of the spheres
// integrated against the same band-limited lighting (a cap quadrature for one sphere, ray-tested
// sphere quadrature for several), or the SH projection of the true product for SH-vector errors.
// S5 and S7 render a small CPU frame (stability_frame.h) and score it against its own k = 1 image
// (S5) or by its flicker (S7). S10 scores the path tracer against itself (two seeds) on the
// chart's default scene.
//
//   S1 overlap stack     m = 1..32 spheres, jitter δ: shadow error (u), indirect growth (u)
//   S2 pass-through      a sphere through the receiver: excess step (u), error for |h| < r (%)
//   S3 large caps, HYB   α = 1..89.9°, 2..12 spheres: SH-vector error (%); HYB switch jump (u)
//   S4 order and window  n = 3..6 × window: overshoot above unshadowed (u), negativity (u), before the F4 clamp
//   S5 silhouettes       k = 2..8 × upsampler × camera distance: edge-band and thin-pole error over interior error, no-match pixels
//   S6 influence fade    a sphere from 40r to 2r, η × light: entry step (u), missing shadow (u)
//   S7 camera crawl      static world, moving camera, k × upsampler: flicker (u) of the error against k = 1 and F, exact reprojection
//   S8 LOD switch        64 → 8 spheres, hard vs cross-fade: pop (u)
//   S9 crowd             1..20 characters, 2 m → 0.4 m apart: shadow error (u) against redundant blocking, slopes
//   S10 noise floor      path tracing at 2 seeds: relative-MSE floor per spp
// u = 1/255 of the receiver's unshadowed shade (stability_metrics.h). Shading is Rec. 709 luminance
// of the irradiance. Every sweep also counts the bounds of the frame's output (clamped, as the GPU
// writes it): negative, brighter than unshadowed, NaN/Inf.
#include <filesystem>
#include <string>
#include <vector>

#include "base/result.h"
#include "study/stability_gpu.h"
#include "study/stability_metrics.h"

namespace proxygi::study {

struct SweepMetric {
  std::string name;        // "shadow error"
  std::string unit;        // "u", "%", "relMSE"
  double threshold = 0.0;  // a point fails when its value > threshold
};

struct SweepPoint {
  std::string method;   // "hyb", "ol", "product", "exact", "ps8", "hard", "fade4", "path"
  std::string series;   // legend label within the sweep: method plus the fixed parameters
  double x = 0.0;       // the swept value (sweep.x_label)
  int metric = 0;       // index into SweepResult::metrics
  double value = 0.0;
  bool pass = true;
};

// Curves (per frame in S6–S8; S5: error against pole width / k) and per-pixel error images at a method's worst point (S5, S7, S9),
// drawn by `bench stability` as stability-<id>-traces.png and stability-<id>-heatmaps.png.
struct SweepTrace {
  std::string panel;   // the y quantity, with its unit: traces of one panel share an axis
  std::string series;
  std::vector<double> x, y;
};
struct SweepHeatMap {
  std::string title;   // method and point
  std::string unit;
  ref::Plane values;   // top row first; NaN where nothing is scored (drawn blank)
};

struct SweepResult {
  std::string id;       // "S1"
  std::string title;
  std::string x_label;
  bool log_x = false;
  std::vector<SweepMetric> metrics;
  std::vector<SweepPoint> points;
  BoundsCounts bounds;                // the frame's outputs over the whole sweep
  std::vector<std::string> notes;     // measured facts beyond the metrics, one sentence each
  std::string trace_x_label;
  bool trace_log_x = false;
  std::vector<SweepTrace> traces;
  std::vector<SweepHeatMap> heat_maps;
  double seconds = 0.0;
  std::size_t failures() const;
};

struct StabilityOptions {
  bool quick = false;       // fewer points and a coarser quadrature (a few minutes on 2 cores)
  // S10: the chart's default scene (assets_dir holds the mannequin), traced at `noise_size`².
  std::filesystem::path assets_dir;
  std::filesystem::path cache_dir;  // rig cache for the chart scene
  int noise_size = 96;
  // S10's threshold: the smallest relative MSE the chart ranks (its best proxy row) / 3; ≤ 0: none.
  double noise_threshold = 0.0;
  // When set, S6 also runs on the GPU frame (shadow gather and raster splat; stability_gpu.h).
  GpuReceiverShader* gpu = nullptr;
};

// "S1" .. "S10" in order.
std::vector<std::string> stability_sweep_ids();
// Fails on an unknown id (message names it and lists the known ones) or when S10's scene cannot load.
Result<SweepResult> run_stability_sweep(const std::string& id, const StabilityOptions& options);

// The sweeps' parts, exposed for the tests.
SweepResult sweep_overlap_stack(const StabilityOptions& options);     // S1
SweepResult sweep_pass_through(const StabilityOptions& options);      // S2
SweepResult sweep_large_caps(const StabilityOptions& options);        // S3
SweepResult sweep_order_window(const StabilityOptions& options);      // S4
SweepResult sweep_silhouettes(const StabilityOptions& options);       // S5
SweepResult sweep_influence_fade(const StabilityOptions& options);    // S6
SweepResult sweep_camera_crawl(const StabilityOptions& options);      // S7
SweepResult sweep_lod_switch(const StabilityOptions& options);        // S8
SweepResult sweep_crowd(const StabilityOptions& options);             // S9
Result<SweepResult> sweep_noise_floor(const StabilityOptions& options);  // S10

}  // namespace proxygi::study
