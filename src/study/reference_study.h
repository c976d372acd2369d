#pragma once
// The ground-truth side of the speed–accuracy chart: converged references (cached on disk),
// image scores against them, and path tracing at low sample counts with and without the guided
// filter, timed on this machine.
//
// Reference: `proxygi reference`'s path tracer, one diffuse bounce, lighting = the environment
// band-limited to SH order `reference_order` (LightingKind::sh) or the full environment, at
// `reference_spp` samples with seed kReferenceSeed. Cached as
//   cache_dir/<scene>/frame<F>-<lighting>[-n<order>]-<W>x<H>.exr (+ its record and features),
// reused when the record matches and holds at least `reference_spp` samples, continued
// (exact accumulation) when it holds fewer.
// Scores: relative MSE, RMSE, SSIM and HDR-FLIP over receiver pixels (the reference's primary-ray
// coverage; the environment behind is not scored), ref/metrics.h conventions.
#include <cstdint>
#include <filesystem>
#include <memory>
#include <vector>

#include "base/result.h"
#include "image/image.h"
#include "ref/metrics.h"
#include "ref/path_tracer_lighting.h"
#include "ref/reference_render.h"
#include "ref/scene_geometry.h"
#include "study/chart_rows.h"
#include "study/chart_scenes.h"
#include "world/world.h"

namespace proxygi::study {

struct ChartRegions;  // study/chart_regions.h

inline constexpr std::uint32_t kReferenceSeed = 1;
inline constexpr std::uint32_t kTestSeed = 977;  // path-tracing rows: independent of the reference
inline constexpr float kContactRadiusM = 0.3f;   // the "contact" region: ground this close to a character
// The near_wall and open_floor regions (scenes with static meshes): ground within kNearWallM of a
// static mesh's triangles, and ground farther than kOpenFloorM from all of them.
inline constexpr float kNearWallM = 0.5f;
inline constexpr float kOpenFloorM = 1.0f;

struct ReferenceOptions {
  int reference_spp = 1024;
  int reference_order = 6;  // SH order of the sh reference lighting (its own band limit, not render.sh_order)
  ref::LightingKind lighting = ref::LightingKind::sh;
  std::filesystem::path cache_dir;
  std::filesystem::path assets_dir;
  int guided_radius = 8;            // pixels (Bauszat: 24–32 at 512², scaled to the chart size)
  float guided_depth_scale = 20.0f; // meters: the character stage's extent
  bool progress = true;             // progress line on stderr while tracing
  // Characters lit without shadows as senders (ref::PathTracerSettings::unshadowed_character_senders),
  // the bounce methods' assumption; cached as "...-unshadowed-...". Not physical: a study option.
  bool unshadowed_senders = false;
};

struct FrameReference {
  image::ImageF radiance;      // linear, mean of all samples
  image::ImageF indirect;      // its part that bounced at least once
  ref::PixelFeatures features; // pixel-center features (guide of the filter)
  ref::ReceiverMask receivers; // pixels the center ray hits
  ref::ReceiverMask character; // pixels the center ray hits a character in (the "character" region)
  ref::ReceiverMask ground;    // pixels the center ray hits the ground plane (y = 0) in
  ref::ReceiverMask contact;   // ground pixels within kContactRadiusM of a character's vertex
  ref::ReceiverMask other;     // pixels the center ray hits neither a character nor the ground in (a wall)
  ref::ReceiverMask near_wall; // ground pixels within kNearWallM of a static mesh (none without static meshes)
  ref::ReceiverMask open_floor;// ground pixels farther than kOpenFloorM from every static mesh (same)
  std::uint32_t samples = 0;
  double trace_seconds = 0.0;  // all runs together
  // bench chart --regions: the region masks (attach_chart_regions); null: regions not scored.
  std::shared_ptr<const ChartRegions> regions;
};

struct ImageScores {
  double relative_mse = 0.0;
  double rmse = 0.0;
  double ssim = 0.0;
  double flip = 0.0;  // HDR-FLIP
  // Over the character region (0 when the frame shows no character): relative MSE, and the mean
  // luminance of the test over the reference's.
  double character_relative_mse = 0.0;
  double character_luminance_ratio = 0.0;
  RegionErrors regions;  // when the reference carries regions
};

// What every frame of one chart scene shares: the scene as the chart gives it, its world (models
// imported once, no rigs) and decoded textures, and the reference lighting (SH order
// options.reference_order) and background. Made once per scene.
struct SceneSources {
  scene::Scene scene;
  std::unique_ptr<world::World> world;
  ref::SceneGeometry geometry;
  std::unique_ptr<ref::EnvironmentLight> lighting;    // options.lighting
  std::unique_ptr<ref::EnvironmentLight> background;  // the full environment, seen by missing rays
};
Result<SceneSources> load_scene_sources(const ChartScene& chart, const ReferenceOptions& options);

// The path tracer set up for one frame of a chart scene (the world evaluated at the frame's time).
// `sources` must outlive the tracer. character_senders = false: the characters reflect no light
// after the first vertex (ref::PathTracerSettings), the reference the bounce is measured against;
// its cache file is named "...-nosend-..." apart from the full reference.
class FrameTracer {
 public:
  static Result<std::unique_ptr<FrameTracer>> create(const SceneSources& sources, int frame,
                                                     bool character_senders = true, bool unshadowed_senders = false);
  ~FrameTracer();
  // Traces `spp` samples with `seed` from sample 0 (all cores); seconds = tracing wall time.
  Result<ref::SampleSums> trace(int spp, std::uint32_t seed, std::uint32_t first_sample, ref::RenderStats* stats,
                                bool progress, ref::Sampler sampler = ref::Sampler::sobol) const;
  ref::PixelFeatures features() const;
  // The ground, contact, other, near_wall and open_floor regions of FrameReference (pixel-center
  // rays, as the character region).
  void region_masks(FrameReference& reference) const;
  bool character_senders() const;
  bool unshadowed_senders() const;
  int width() const;
  int height() const;

 private:
  struct State;
  explicit FrameTracer(std::unique_ptr<State> state);
  std::unique_ptr<State> state_;
};

Result<FrameReference> load_or_render_reference(const ChartScene& chart, int frame, const FrameTracer& tracer,
                                                const ReferenceOptions& options);

// Makes the reference's region masks (chart_regions.h) from its features and the scene's
// reference lighting; score_image then scores every row on them.
Status attach_chart_regions(FrameReference& reference, const SceneSources& sources, const ReferenceOptions& options);

Result<ImageScores> score_image(const image::ImageF& test, const FrameReference& reference);
// Adds weight × scores to the row's errors (a mean over n frames: weight 1/n per frame).
void add_scores(ChartRow& row, const ImageScores& scores, double weight);

struct PathTracingScore {
  int samples = 0;
  bool guided = false;
  double milliseconds = 0.0;  // tracing (+ features and filter when guided), wall time, all cores
  ImageScores scores;
};
// Path tracing at each sample count in `sample_counts`, plain and guided-filtered.
Result<std::vector<PathTracingScore>> score_path_tracing(const FrameTracer& tracer, const FrameReference& reference,
                                                         const std::vector<int>& sample_counts,
                                                         const ReferenceOptions& options);

}  // namespace proxygi::study
