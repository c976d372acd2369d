// proxygi bench stability [--json] [--sweeps S1,S2,...] [--quick] [--out DIR] [--cache DIR]
//   [--chart-csv FILE] [--no-gpu] [--device NAME]
// The stability study (study/stability_sweeps.h, ../shared/notes/stability.md): each stress sweep
// on the frame's CPU twins scored against the exact answer, with its thresholds and pass/fail;
// S6 also on the GPU frame (shadow gather and raster splat) unless --no-gpu.
// Writes DIR/bench-stability.json and .md, a chart per sweep (threshold lines) and the
// robustness–speed chart; prints a summary (or the JSON with --json). Exit 0 whether or not points
// fail (the study reports them), 1 when a sweep cannot run or a file cannot be written, 2 on bad
// options.
#include <cstdio>

#include "apps/bench_stability_report.h"
#include "apps/commands.h"
#include "run/gpu_receiver_shader.h"
#include "settings/limits.h"

namespace proxygi::app {
namespace {

struct StabilityArgs {
  bool json = false;
  bool quick = false;
  std::vector<std::string> sweeps;
  std::string out = "out/stability";
  std::string cache = "out/chart-cache";
  std::string chart_csv;  // empty: the committed docs/bench-chart.csv beside assets/
  int noise_size = 96;
  bool no_gpu = false;
  std::string device;
};

int run_bench_stability(const StabilityArgs& args) {
  std::vector<std::string> ids = args.sweeps.empty() ? study::stability_sweep_ids() : args.sweeps;
  for (const std::string& id : ids) {
    const std::vector<std::string> known = study::stability_sweep_ids();
    if (std::find(known.begin(), known.end(), id) == known.end()) {
      std::string list;
      for (const std::string& k : known) list += (list.empty() ? "" : ", ") + k;
      return fail_bad_input("bench stability: --sweeps: unknown sweep '" + id + "' (known: " + list + ")");
    }
  }
  double best_relative_mse = 0.0;
  const std::string chart_csv =
      args.chart_csv.empty() ? (assets_dir().parent_path() / "docs" / "bench-chart.csv").string() : args.chart_csv;
  const MethodTimings timings = timings_from_chart_csv(chart_csv, &best_relative_mse);
  study::StabilityOptions options;
  options.quick = args.quick;
  options.assets_dir = assets_dir();
  options.cache_dir = std::filesystem::path(args.cache) / "rigs";
  options.noise_size = args.noise_size;
  options.noise_threshold = best_relative_mse / 3.0;
  std::error_code error;
  std::filesystem::create_directories(options.cache_dir, error);
  if (error) return fail_runtime(args.cache + ": cannot create: " + error.message());
  // The GPU frame for the sweeps that run it (S6); with PROXYGI_VALIDATION=1 (the tests) any
  // validation message fails the run.
  std::unique_ptr<gpu::Context> context;
  std::unique_ptr<study::GpuReceiverShader> gpu_shader;
  if (!args.no_gpu && std::find(ids.begin(), ids.end(), "S6") != ids.end()) {
    auto created = gpu::Context::create({.device_request = args.device});
    if (!created) return fail_runtime("bench stability: " + created.message() + " (--no-gpu runs the CPU twins alone)");
    context = std::move(*created);
    auto shader = run::make_gpu_receiver_shader(*context);
    if (!shader) return fail_runtime("bench stability: " + shader.message());
    gpu_shader = std::move(*shader);
    options.gpu = gpu_shader.get();
  }
  std::vector<study::SweepResult> sweeps;
  for (const std::string& id : ids) {
    if (!args.json && !quiet()) std::fprintf(stderr, "bench stability: %s ...\n", id.c_str());
    auto sweep = study::run_stability_sweep(id, options);
    if (!sweep) return fail_runtime("bench stability: " + sweep.message());
    sweeps.push_back(std::move(*sweep));
  }
  if (context) {
    if (const std::vector<std::string> messages = context->validation_messages(); !messages.empty()) {
      for (const std::string& message : messages) std::fprintf(stderr, "validation: %s\n", message.c_str());
      return fail_runtime("bench stability: " + std::to_string(messages.size()) + " Vulkan validation messages");
    }
  }
  if (Status written = write_stability_report(args.out, sweeps, timings); !written)
    return fail_runtime("bench stability: " + written.message());
  if (args.json)
    std::printf("%s\n", stability_json(sweeps, timings).dump(2).c_str());
  else
    std::printf("%s", stability_summary_text(sweeps).c_str());
  return kExitOk;
}

}  // namespace

void add_bench_stability_command(CLI::App& bench, CommandRunner& runner) {
  auto args = std::make_shared<StabilityArgs>();
  auto* command = bench.add_subcommand("stability", "Stress sweeps where the methods fail, against the exact answer");
  command->add_flag("--json", args->json, "Print every sweep point as JSON on stdout");
  command->add_flag("--quick", args->quick, "Fewer points, coarser quadrature, 16-256 spp for S10 (a few minutes)");
  command->add_option("--sweeps", args->sweeps, "Only these sweeps (S1,...,S10)")->delimiter(',');
  command->add_option("--out", args->out, "Folder for bench-stability.json, .md and the charts")->capture_default_str();
  command->add_option("--cache", args->cache, "Folder of cached proxy rigs (S10's scene)")->capture_default_str();
  command->add_option("--chart-csv", args->chart_csv, "bench-chart.csv giving ms per frame (robustness-speed chart) and S10's threshold "
                      "(default: the committed docs/bench-chart.csv)");
  command->add_option("--noise-size", args->noise_size, "S10: square image size in pixels")
      ->check(CLI::Range(settings::kMinImageSize, settings::kMaxImageSize))
      ->capture_default_str();
  command->add_flag("--no-gpu", args->no_gpu, "Run the sweeps on the CPU twins alone (S6 skips the GPU frame's gather and splat)");
  command->add_option("--device", args->device, "Vulkan device for the GPU frame (name substring or index; default: $PROXYGI_DEVICE)");
  add_quiet_flag(*command);
  command->callback([&runner, args] { runner = [args] { return run_bench_stability(*args); }; });
}

}  // namespace proxygi::app
