// proxygi bench sampler [--size 96] [--spp 16,64,256,1024] [--scenes default,...] [--json]:
// the reference path tracer's noise with the Owen-scrambled Sobol sampler against plain Monte
// Carlo (the sampler before 2026-12), measured in one run on the chart's references (first frame
// of motion of each chart scene, one bounce, SH order 6 lighting, as `bench chart`).
//
// For each sampler and spp it renders the frame twice, with seeds 1 and 2, and estimates the
// per-pixel variance of the mean as (A − B)² / 2 averaged over receiver pixels and channels (an
// unbiased estimate for any sampler; the per-pixel sample variance is not, for quasi-random
// points). Reported: that variance, its ratio random / sobol at equal spp (= how many times
// fewer samples sobol needs for the same noise), the relative per-pixel noise
// sqrt(var) / mean radiance, tracing time, and the difference of the two samplers' image means
// in units of its standard error (should be within a few: same mean).
#include <cmath>
#include <cstdio>

#include <nlohmann/json.hpp>

#include "apps/commands.h"
#include "settings/limits.h"
#include "study/chart_scenes.h"
#include "study/reference_study.h"

namespace proxygi::app {
namespace {

struct SamplerBenchOptions {
  int size = 96;
  std::vector<int> spp = {16, 64, 256, 1024};
  std::vector<std::string> scenes = {"default"};
  std::string shared = "../shared";  // as bench chart
  bool json = false;
};

struct Measured {
  double variance = 0.0;   // per pixel and channel, of the mean of spp samples
  double mean = 0.0;       // mean radiance over receivers (both seeds)
  double mean_var = 0.0;   // variance of `mean` (from the per-pixel variances, pixels independent)
  double seconds = 0.0;    // both renders
};

Result<Measured> measure(const study::FrameTracer& tracer, const ref::ReceiverMask& mask, int spp, ref::Sampler sampler) {
  Measured out;
  ref::RenderStats stats_a, stats_b;
  auto a = tracer.trace(spp, 1u, 0u, &stats_a, false, sampler);
  if (!a) return a.error();
  auto b = tracer.trace(spp, 2u, 0u, &stats_b, false, sampler);
  if (!b) return b.error();
  out.seconds = stats_a.seconds + stats_b.seconds;
  double squared = 0.0, sum = 0.0;
  std::size_t count = 0;
  const double n = double(spp);
  for (std::size_t i = 0; i < a->radiance.size(); ++i) {
    if (!mask.contains(i)) continue;
    const glm::dvec3 ma = a->radiance[i] / n, mb = b->radiance[i] / n;
    const glm::dvec3 d = ma - mb;
    squared += (d.x * d.x + d.y * d.y + d.z * d.z) / 2.0;
    sum += (ma.x + ma.y + ma.z + mb.x + mb.y + mb.z) / 2.0;
    count += 3;
  }
  if (count == 0) return make_error("bench sampler: no receiver pixels");
  out.variance = squared / double(count);
  out.mean = sum / double(count);
  out.mean_var = out.variance / 2.0 / double(count);  // mean of 2 images × count channel-pixels
  return out;
}

int run_bench_sampler(const SamplerBenchOptions& options) {
  study::ChartSceneOptions scene_options;
  scene_options.size = options.size;
  scene_options.frame_count = 1;
  scene_options.assets_dir = assets_dir();
  scene_options.shared_dir = options.shared;
  scene_options.only = options.scenes;
  auto scenes = study::chart_scenes(scene_options);
  if (!scenes) return fail_runtime(scenes.message());
  study::ReferenceOptions reference;
  reference.assets_dir = assets_dir();
  nlohmann::json out;
  if (!options.json)
    std::printf("%-12s %5s %12s %12s %8s %9s %9s %8s %8s %7s\n", "scene", "spp", "var random", "var sobol",
                "ratio", "noise rnd", "noise sob", "s random", "s sobol", "mean dz");
  for (const study::ChartScene& chart : *scenes) {
    auto sources = study::load_scene_sources(chart, reference);
    if (!sources) return fail_runtime(chart.name + ": " + sources.message());
    auto tracer = study::FrameTracer::create(*sources, chart.frames.front());
    if (!tracer) return fail_runtime(chart.name + ": " + tracer.message());
    const ref::PixelFeatures features = (*tracer)->features();
    const ref::ReceiverMask mask = ref::mask_from_image(features.mask);
    for (int spp : options.spp) {
      auto random = measure(**tracer, mask, spp, ref::Sampler::random);
      if (!random) return fail_runtime(random.message());
      auto sobol = measure(**tracer, mask, spp, ref::Sampler::sobol);
      if (!sobol) return fail_runtime(sobol.message());
      const double ratio = sobol->variance > 0.0 ? random->variance / sobol->variance : 0.0;
      const double noise_random = std::sqrt(random->variance) / random->mean;
      const double noise_sobol = std::sqrt(sobol->variance) / sobol->mean;
      const double z = (sobol->mean - random->mean) / std::sqrt(sobol->mean_var + random->mean_var);
      if (options.json) {
        out["results"].push_back({{"scene", chart.name}, {"spp", spp}, {"size", options.size},
                                  {"variance_random", random->variance}, {"variance_sobol", sobol->variance},
                                  {"variance_ratio", ratio}, {"relative_noise_random", noise_random},
                                  {"relative_noise_sobol", noise_sobol}, {"seconds_random", random->seconds},
                                  {"seconds_sobol", sobol->seconds}, {"mean_random", random->mean},
                                  {"mean_sobol", sobol->mean}, {"mean_difference_z", z}});
      } else {
        std::printf("%-12s %5d %12.4e %12.4e %7.2fx %8.2f%% %8.2f%% %8.2f %8.2f %7.2f\n", chart.name.c_str(), spp,
                    random->variance, sobol->variance, ratio, 100.0 * noise_random, 100.0 * noise_sobol,
                    random->seconds, sobol->seconds, z);
        std::fflush(stdout);
      }
    }
  }
  if (options.json) std::printf("%s\n", out.dump(2).c_str());
  return kExitOk;
}

}  // namespace

void add_bench_sampler_command(CLI::App& bench, CommandRunner& runner) {
  auto options = std::make_shared<SamplerBenchOptions>();
  auto* command = bench.add_subcommand(
      "sampler", "Reference noise at equal spp: Owen-scrambled Sobol against plain Monte Carlo (two seeds each)");
  command->add_option("--size", options->size, "Square image size")->check(CLI::Range(settings::kMinImageSize, settings::kMaxImageSize));
  command->add_option("--spp", options->spp, "Samples per pixel to measure")->delimiter(',')->check(CLI::Range(1, settings::kMaxSamplesPerPixel));
  command->add_option("--scenes", options->scenes, "Chart scenes (default, CesiumMan, Fox, RiggedSimple)")
      ->delimiter(',');
  command->add_option("--shared", options->shared, "Folder holding assets/gltf with the sample characters");
  command->add_flag("--json", options->json, "Machine-readable output");
  add_quiet_flag(*command);
  command->callback([&runner, options] { runner = [options] { return run_bench_sampler(*options); }; });
}

}  // namespace proxygi::app
