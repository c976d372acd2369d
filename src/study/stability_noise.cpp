// S10: the path tracer's noise floor on the chart's default scene, two seeds per sample count.
#include <chrono>

#include "study/chart_scenes.h"
#include "study/reference_study.h"
#include "study/stability_sweep_parts.h"

namespace proxygi::study {
namespace {

image::ImageF mean_image(const ref::SampleSums& sums) {
  image::ImageF out(sums.width, sums.height);
  for (int y = 0; y < sums.height; ++y)
    for (int x = 0; x < sums.width; ++x) {
      const glm::dvec3 v = sums.radiance[std::size_t(y) * std::size_t(sums.width) + std::size_t(x)] / double(sums.samples);
      out.at(x, y) = glm::vec4(glm::vec3(v), 1.0f);
    }
  return out;
}

}  // namespace

Result<SweepResult> sweep_noise_floor(const StabilityOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  SweepResult sweep;
  sweep.id = "S10";
  sweep.title = "noise floor: the chart's default scene path-traced with two seeds (relative MSE of one image, RGB)";
  sweep.x_label = "samples per pixel";
  sweep.log_x = true;
  const double threshold = options.noise_threshold > 0.0 ? options.noise_threshold : INFINITY;
  sweep.metrics = {{"noise floor (relative MSE of one reference)", "relMSE", threshold}};
  ChartSceneOptions scene_options;
  scene_options.size = options.noise_size;
  scene_options.frame_count = 1;
  scene_options.assets_dir = options.assets_dir;
  scene_options.rig_cache_dir = options.cache_dir;
  scene_options.only = {"default"};
  auto scenes = chart_scenes(scene_options);
  if (!scenes) return make_error("S10: " + scenes.message());
  if (scenes->empty()) return make_error("S10: the default chart scene is missing");
  ReferenceOptions reference_options;
  reference_options.assets_dir = options.assets_dir;
  reference_options.progress = false;
  auto sources = load_scene_sources(scenes->front(), reference_options);
  if (!sources) return make_error("S10: " + sources.message());
  auto tracer = FrameTracer::create(*sources, scenes->front().frames.front());
  if (!tracer) return make_error("S10: " + tracer.message());
  const ref::ReceiverMask receivers = ref::mask_from_alpha((*tracer)->features().mask);
  const std::vector<int> counts = options.quick ? std::vector<int>{16, 64, 256} : std::vector<int>{64, 256, 1024, 4096};
  for (int spp : counts) {
    auto a = (*tracer)->trace(spp, kReferenceSeed, 0, nullptr, false);
    auto b = a ? (*tracer)->trace(spp, kReferenceSeed + 1000, 0, nullptr, false) : a;
    if (!a || !b) return make_error("S10: " + (a ? b.message() : a.message()));
    const image::ImageF first = mean_image(*a), second = mean_image(*b);
    auto error = ref::relative_mse(first, second, &receivers);
    if (!error) return make_error("S10: " + error.message());
    // E[(a − b)²] = 2 Var: one reference's floor is half the two seeds' relative MSE.
    add_point(sweep, "path", "path tracer, " + std::to_string(options.noise_size) + " px", spp, 0, error->mean / 2.0);
  }
  if (options.noise_threshold > 0.0)
    sweep.notes.push_back("threshold: a third of the smallest relative MSE the committed chart ranks (docs/bench-chart.csv)");
  sweep.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return sweep;
}

}  // namespace proxygi::study
