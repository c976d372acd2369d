#pragma once
// Rows of the speed–accuracy chart (`proxygi bench chart`) and what is derived from them: the
// Pareto front per scene, the mean over scenes, the two goals, and the CSV, JSON and
// markdown tables. Pure data, no rendering: tests build rows by hand.
//
// A row is one method at one setting on one scene, averaged over the chart's frames:
// milliseconds per frame (lower is better) against the error of its image to the converged
// reference (relative MSE over receiver pixels; lower is better). RMSE, SSIM and HDR-FLIP are
// carried along for the table.
#include <array>
#include <string>
#include <vector>

namespace proxygi::study {

inline constexpr const char* kAllScenes = "all";  // the scene name of rows averaged over scenes

// `bench chart --regions` (study/chart_regions.h): per region, the sum of the per-pixel relative
// MSE and the pixel count; per-frame means when added with weight 1/frames. A region's relative
// MSE is their ratio (NaN when the region is empty on every frame). Bounds: pixels per frame.
enum class ChartRegion { shadow, edge, thin, character, contact, near_wall, open_floor };
inline constexpr int kChartRegionCount = 7;
inline constexpr std::array<const char*, kChartRegionCount> kChartRegionNames = {
    "shadow", "edge", "thin", "character", "contact", "near_wall", "open_floor"};
struct RegionErrors {
  bool measured = false;
  std::array<double, kChartRegionCount> error_sum{};
  std::array<double, kChartRegionCount> pixels{};
  double negative = 0.0;          // pixels with a channel < 0
  double above_unshadowed = 0.0;  // pixels with a channel above unshadowed + the reference's bounce by > 1/255
  double non_finite = 0.0;        // pixels with a NaN or Inf channel
  double relative_mse(ChartRegion region) const;
  void add(const RegionErrors& other, double weight);
};

// One chart frame of a rasterized row (the scene's chart frames, in order).
struct ChartFrame {
  double relative_mse = 0.0;
  // Method "quality" only: this frame's own pipelined ms per frame (timed from this frame with the
  // settings chosen for it) and the sh_order, receiver_scale and upsampling render.quality chose
  // for its shot (upsampling empty at k = 1, as the swept rows' labels); else 0 / empty.
  double milliseconds = 0.0;
  int sh_order = 0;
  int receiver_scale = 0;
  std::string upsampling;
};

struct ChartRow {
  std::string scene;
  std::string method;     // "proxy", "vertex", "ao", "path", "path+guided", "quality" (render.quality with a target)
  int sh_order = 0;       // proxy methods: SH order; path tracing: 0
  int receiver_scale = 0; // proxy/ao: k; vertex: 0
  std::string upsampling; // "bilateral" / "bilinear"; empty where it does not apply
  std::string indirect;   // "point" / "averaged" / "exact" / "vsgl1".."vsgl8" / "none"; empty where it does not apply
  int samples = 0;        // path tracing: samples per pixel; else 0
  double milliseconds = 0.0;  // per frame
  double relative_mse = 0.0;
  double rmse = 0.0;
  double ssim = 0.0;
  double flip = 0.0;      // HDR-FLIP mean
  // The "character" region (pixels whose center ray hits a character in the reference): relative
  // MSE there, and the mean luminance of the row's image over the reference's (1 = as bright).
  double character_relative_mse = 0.0;
  double character_luminance_ratio = 0.0;
  RegionErrors regions;       // measured only with --regions
  bool ground_bounce = true;  // proxy/ao/vertex: render.ground_bounce (label "no-ground-bounce" when off)
  std::string antialiasing;  // render.antialiasing when not off ("ssaa2", "ssaa4": appended to the label); else empty
  std::string static_transfer = "l0";  // proxy: render.static_transfer (label "static-ratio", "static-l1"; l0: none)
  bool mask_sender_light = true;  // proxy: render.mask_sender_light (label "paper-senders" when off)
  // Method "quality": the render.quality level as named ("draft", "balanced", "high") and its
  // target relative MSE; the row's ms and errors are means over its frames, each frame rendered
  // with the settings chosen for that frame's shot (study/quality_rows.h scores the choices).
  std::string quality;
  double quality_target = 0.0;
  std::vector<ChartFrame> frames;  // rasterized rows (proxy, vertex, ao, quality); empty for path tracing and means
  bool pareto = false;    // on its scene's Pareto front (set by mark_pareto_fronts)
  bool is_default = false;  // the proxy method at the product's default setting (method "proxy" only)
};

// "proxy n4 k4 bilateral averaged", "proxy n4 k4 bilateral averaged no-ground-bounce", "proxy n4 k4 bilateral
// averaged ssaa2", "proxy n4 k4 bilateral averaged paper-senders", "path+guided 64 spp", "quality balanced", ...
std::string row_label(const ChartRow& row);

// Marks, within each scene separately, the rows no other row beats in both milliseconds and
// relative MSE (ties in both keep both). Resets `pareto` first.
void mark_pareto_fronts(std::vector<ChartRow>& rows);

// One row per (method, setting) present on every scene: arithmetic means of time and errors over
// the scenes, scene = kAllScenes. Settings missing on some scene are skipped. A region's relative
// MSE is the mean over the scenes where it is not empty.
std::vector<ChartRow> mean_over_scenes(const std::vector<ChartRow>& rows);

// The goals, evaluated on one scene's rows (normally kAllScenes).
struct GoalResult {
  bool evaluated = false;  // the rows needed were present
  bool met = false;
  double ratio = 0.0;      // speed ratio achieved (how many times faster)
  std::string compared;    // the row compared against, as row_label
  std::string note;        // one sentence of what was found
};
// 50×: the default proxy row reaches the error of the guided path tracer at some sample count
// (a guided row with relative MSE ≥ the default's) in ≥ 50× less time. Ratio = the best such
// time ratio; when no guided row is as bad as the default, the goal is not met and the ratio is
// the one against the cheapest guided row.
GoalResult path_tracing_goal(const std::vector<ChartRow>& rows, const std::string& scene);
// 2×: the fastest image-space (proxy) row at SH order `sh_order` with relative MSE ≤ the vertex
// baseline's at that order runs ≥ 2× faster than it.
GoalResult vertex_goal(const std::vector<ChartRow>& rows, const std::string& scene, int sh_order);

// With regions measured (any row), the CSV and JSON carry them (columns / a "regions" object) and
// to_region_markdown tables them; without, the output is as before --regions existed.
std::string to_csv(const std::vector<ChartRow>& rows);
std::string to_markdown(const std::vector<ChartRow>& rows, const std::string& scene);
std::string to_region_markdown(const std::vector<ChartRow>& rows, const std::string& scene);
std::string to_json(const std::vector<ChartRow>& rows);  // array of objects, one per row

}  // namespace proxygi::study
