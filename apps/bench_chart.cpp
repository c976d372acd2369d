// proxygi bench chart [--json] [--out DIR] [--cache DIR] [--size N] [--frames N (3)] [--timing-frames N (8)]
//   [--reference-spp N] [--scenes a,b] [--shared DIR] [--lighting sh|full] [--quick]
//   [--references-only] [--shard I/N] [--regions]
// proxygi bench chart --merge SHARD_DIR... [--out DIR] [--json] [--timings-from FILE]
// The speed–accuracy chart: for the default scene and each shared character, a few frames of
// motion, every proxy setting, the vertex and AO baselines, and path tracing at 1, 4, 16, 64 spp
// with and without the guided filter: ms per frame against the error to a converged path-traced
// reference, measured in one run on this machine. Writes DIR/bench-chart.csv, .md and .png
// (log–log, Pareto front named), -scores.json and -timings.json, prints the table (or JSON with
// --json), and reports the goals. References are cached under --cache and reused (or continued)
// by later runs. --shard measures one shard of the chart's units into DIR/bench-chart-shard.json;
// --merge joins shards into the chart a single run writes (bench_chart_shards.h). A single run
// and a merge also write the bounce chart, DIR/bench-chart-bounce.csv, .md and .png
// (bench_chart_bounce.h); shards carry its rows. --regions scores every row also per region of the
// reference and counts its bounds (study/chart_regions.h): columns in the CSV and JSON, a table per
// scene in the markdown.
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <limits>

#include <nlohmann/json.hpp>

#include "apps/bench_chart_bounce.h"
#include "apps/bench_chart_report.h"
#include "apps/bench_chart_shards.h"
#include "apps/chart_methods.h"
#include "apps/commands.h"
#include "settings/limits.h"
#include "base/atomic_file.h"
#include "base/log.h"

namespace proxygi::app {
namespace {

struct ChartArgs {
  bool json = false;
  std::string out = "out/chart";
  std::string cache = "out/chart-cache";
  int size = 192;
  int frames = 3;
  int timing_frames = 8;
  int reference_spp = 1024;
  std::vector<std::string> scenes;
  std::string shared = "../shared";
  std::string lighting = "sh";
  bool quick = false;
  bool references_only = false;
  std::string shard;
  std::vector<std::string> merge;
  std::string timings_from;
  std::string device;
  bool unshadowed_senders = false;
  bool regions = false;
};

// Path-tracing rows of one scene: per (samples, guided) the mean over its frames.
void add_path_tracing_rows(const std::string& scene, std::size_t unit,
                           const std::vector<std::vector<study::PathTracingScore>>& frames, std::vector<UnitRow>& rows) {
  if (frames.empty()) return;
  for (std::size_t i = 0; i < frames.front().size(); ++i) {
    study::ChartRow row;
    row.scene = scene;
    row.method = frames.front()[i].guided ? "path+guided" : "path";
    row.samples = frames.front()[i].samples;
    const double count = double(frames.size());
    for (const auto& frame : frames) {
      row.milliseconds += frame[i].milliseconds / count;
      study::add_scores(row, frame[i].scores, 1.0 / count);
    }
    rows.push_back({unit, row});
  }
}

// Means over scenes, Pareto fronts, the files and the printed summary: the same for a single
// run and a merge of shards.
int finish_chart(const ChartArgs& args, std::vector<study::ChartRow> rows, const ChartReportContext& report,
                 std::vector<study::BounceRow> bounce_rows = {}) {
  if (!bounce_rows.empty()) {
    if (report.scenes.size() > 1) {
      std::vector<study::BounceRow> means = study::mean_bounce_over_scenes(bounce_rows);
      bounce_rows.insert(bounce_rows.begin(), means.begin(), means.end());
    }
    if (Status written = write_bounce_report(args.out, bounce_rows, report); !written)
      return fail_runtime("bench chart: " + written.message());
  }
  if (report.scenes.size() > 1) {
    std::vector<study::ChartRow> means = study::mean_over_scenes(rows);
    rows.insert(rows.begin(), means.begin(), means.end());
  }
  study::mark_pareto_fronts(rows);
  if (Status written = write_chart_report(args.out, rows, report); !written)
    return fail_runtime("bench chart: " + written.message());
  if (args.json)
    std::printf("%s\n", chart_report_json(rows, report).dump(2).c_str());
  else
    std::printf("%s", chart_summary_text(rows, report).c_str());
  return kExitOk;
}

int run_merge(const ChartArgs& args) {
  if (!args.shard.empty()) return fail_bad_input("bench chart: --merge and --shard exclude each other");
  std::vector<ChartShard> shards;
  for (const std::string& dir : args.merge) {
    const std::filesystem::path path = std::filesystem::path(dir) / kChartShardFile;
    auto bytes = read_file(path, 1u << 28);
    if (!bytes) return fail_bad_input("bench chart --merge: " + bytes.message());
    auto shard = shard_from_json(std::string_view(reinterpret_cast<const char*>(bytes->data()), bytes->size()), path.string());
    if (!shard) return fail_bad_input("bench chart --merge: " + shard.message());
    shards.push_back(std::move(*shard));
  }
  ChartReportContext report;
  std::vector<study::BounceRow> bounce_rows;
  auto rows = merge_shards(shards, report, &bounce_rows);
  if (!rows) return fail_bad_input("bench chart " + rows.message());
  if (!args.timings_from.empty()) {
    auto bytes = read_file(args.timings_from, 1u << 28);
    if (!bytes) return fail_bad_input("bench chart --timings-from: " + bytes.message());
    if (Status s = replace_timings(*rows, std::string_view(reinterpret_cast<const char*>(bytes->data()), bytes->size()),
                                   args.timings_from);
        !s)
      return fail_bad_input("bench chart --timings-from: " + s.message());
    if (Status s = replace_timings(bounce_rows, std::string_view(reinterpret_cast<const char*>(bytes->data()), bytes->size()),
                                   args.timings_from);
        !s)
      return fail_bad_input("bench chart --timings-from: " + s.message());
  }
  return finish_chart(args, std::move(*rows), report, std::move(bounce_rows));
}

int run_bench_chart(const ChartArgs& args) {
  if (!args.merge.empty()) return run_merge(args);
  if (!args.timings_from.empty()) return fail_bad_input("bench chart: --timings-from needs --merge");
  run::Shard shard;
  if (!args.shard.empty()) {
    auto parsed = run::parse_shard(args.shard);
    if (!parsed) return fail_bad_input("bench chart: " + parsed.message());
    shard = *parsed;
  }
  study::ChartSceneOptions scene_options;
  scene_options.size = args.size;
  scene_options.frame_count = args.frames;
  scene_options.shared_dir = args.shared;
  scene_options.assets_dir = assets_dir();
  scene_options.rig_cache_dir = std::filesystem::path(args.cache) / "rigs";
  scene_options.only = args.scenes;
  std::error_code error;
  std::filesystem::create_directories(scene_options.rig_cache_dir, error);
  if (error) return fail_runtime(args.cache + ": cannot create: " + error.message());
  auto scenes = study::chart_scenes(scene_options);
  if (!scenes) return fail_bad_input("bench chart: " + scenes.message());
  if (scenes->empty()) return fail_bad_input("bench chart: no scene selected");

  study::ReferenceOptions reference_options;
  reference_options.reference_spp = args.reference_spp;
  reference_options.lighting = args.lighting == "full" ? ref::LightingKind::full : ref::LightingKind::sh;
  reference_options.cache_dir = args.cache;
  reference_options.assets_dir = assets_dir();
  reference_options.guided_radius = std::max(2, args.size / 24);
  reference_options.unshadowed_senders = args.unshadowed_senders;
  const bool terminal = isatty(fileno(stderr)) != 0;
  reference_options.progress = !args.json && !quiet() && terminal;  // the tracer's progress is one \r line
  const std::vector<int> sample_counts = args.quick ? std::vector<int>{1, 4} : std::vector<int>{1, 4, 16, 64};

  std::unique_ptr<gpu::Context> context;
  if (!args.references_only) {
    auto created = gpu::Context::create({.device_request = args.device});
    if (!created) return fail_runtime(created.message());
    context = std::move(*created);
  }
  std::vector<UnitRow> rows;
  std::vector<UnitBounceRow> bounce_rows;
  // A setting rendered only to score the bounce chart (the scene's none setting, in a shard that
  // holds other bounce settings of the scene but not that one): no row of its own.
  constexpr std::size_t kNoUnit = std::numeric_limits<std::size_t>::max();
  const std::vector<MethodSetting> grid = method_grid(args.quick);
  const std::size_t units_per_scene = grid.size() + 1;  // path tracing, then each setting
  const std::size_t units = scenes->size() * units_per_scene;
  const run::IndexRange slice = run::shard_slice(units, shard);
  for (std::size_t s = 0; s < scenes->size(); ++s) {
    const study::ChartScene& chart = (*scenes)[s];
    const std::size_t first_unit = s * units_per_scene;
    const bool path_tracing = slice.contains(first_unit);
    std::vector<MethodSetting> grid_part;
    std::vector<std::size_t> setting_units;
    for (std::size_t k = 0; k < grid.size(); ++k)
      if (slice.contains(first_unit + 1 + k)) grid_part.push_back(grid[k]), setting_units.push_back(first_unit + 1 + k);
    if (!path_tracing && grid_part.empty()) continue;  // another shard's scene: not even its references
    // The bounce chart (bench_chart_bounce.h) needs each frame's reference without character
    // senders and the none setting's frames, for the bounce settings this run measures.
    const bool bounce_chart = std::any_of(grid_part.begin(), grid_part.end(), bounce_row_setting);
    if (bounce_chart && std::none_of(grid_part.begin(), grid_part.end(), [](const MethodSetting& setting) {
          return bounce_row_setting(setting) && setting.indirect_method == settings::IndirectMethod::none;
        }))
      for (const MethodSetting& setting : grid)
        if (bounce_row_setting(setting) && setting.indirect_method == settings::IndirectMethod::none)
          grid_part.push_back(setting), setting_units.push_back(kNoUnit);
    std::vector<study::FrameReference> references;
    std::vector<study::BounceReference> bounce_references;
    std::vector<std::vector<study::PathTracingScore>> path_tracing_scores;
    auto sources = study::load_scene_sources(chart, reference_options);
    if (!sources) return fail_runtime("bench chart: " + chart.name + ": " + sources.message());
    for (int frame : chart.frames) {
      auto tracer = study::FrameTracer::create(*sources, frame, true, reference_options.unshadowed_senders);
      if (!tracer) return fail_runtime("bench chart: " + chart.name + ": " + tracer.message());
      auto reference = study::load_or_render_reference(chart, frame, **tracer, reference_options);
      if (!reference) return fail_runtime("bench chart: " + chart.name + " reference: " + reference.message());
      if (args.regions && !args.references_only)
        if (Status attached = study::attach_chart_regions(*reference, *sources, reference_options); !attached)
          return fail_runtime("bench chart: " + chart.name + " regions: " + attached.message());
      if (!args.references_only && path_tracing) {
        auto scores = study::score_path_tracing(**tracer, *reference, sample_counts, reference_options);
        if (!scores) return fail_runtime("bench chart: " + chart.name + " path tracing: " + scores.message());
        path_tracing_scores.push_back(std::move(*scores));
      }
      if (bounce_chart) {
        auto without = study::FrameTracer::create(*sources, frame, false);
        if (!without) return fail_runtime("bench chart: " + chart.name + ": " + without.message());
        auto senderless = study::load_or_render_reference(chart, frame, **without, reference_options);
        if (!senderless) return fail_runtime("bench chart: " + chart.name + " reference: " + senderless.message());
        auto bounce = study::make_bounce_reference(*reference, *senderless);
        if (!bounce) return fail_runtime("bench chart: " + chart.name + ": " + bounce.message());
        bounce_references.push_back(std::move(*bounce));
      }
      references.push_back(std::move(*reference));
    }
    if (args.references_only) continue;
    add_path_tracing_rows(chart.name, first_unit, path_tracing_scores, rows);
    std::vector<std::pair<std::size_t, study::BounceRow>> scene_bounce_rows;
    const Status measured = run_raster_methods(
        *context, chart, grid_part, references,
        {args.timing_frames, bounce_chart ? &bounce_references : nullptr, bounce_chart ? &scene_bounce_rows : nullptr},
        [&](std::size_t i, const study::ChartRow& row) {
          if (setting_units[i] == kNoUnit) return;
          // One line rewritten with \r on a terminal, a line per row into a file or pipe.
          if (!args.json && !quiet())
            std::fprintf(stderr, "%s  %s: %zu/%zu %-40s %8.2f ms  relMSE %.4g%s", terminal ? "\r" : "", chart.name.c_str(), i + 1,
                         grid_part.size(), study::row_label(row).c_str(), row.milliseconds, row.relative_mse, terminal ? "   " : "\n");
          rows.push_back({setting_units[i], row});
        });
    if (!measured) return fail_runtime("bench chart: " + chart.name + ", " + measured.message());
    for (auto& [index, row] : scene_bounce_rows)
      if (setting_units[index] != kNoUnit) bounce_rows.push_back({setting_units[index], std::move(row)});
    if (!args.json && !quiet() && terminal && !grid_part.empty()) std::fprintf(stderr, "\n");
  }
  if (args.references_only) {
    std::printf("bench chart: references ready under %s\n", args.cache.c_str());
    return kExitOk;
  }
  // With PROXYGI_VALIDATION=1 (the tests) any validation message fails the run.
  if (const std::vector<std::string> messages = context->validation_messages(); !messages.empty()) {
    for (const std::string& message : messages) std::fprintf(stderr, "validation: %s\n", message.c_str());
    return fail_runtime("bench chart: " + std::to_string(messages.size()) + " Vulkan validation messages");
  }

  ChartReportContext report;
  report.device = context->report().name;
  report.driver = context->report().driver;
  report.size = args.size;
  report.frames = args.frames;
  report.timing_frames = args.timing_frames;
  report.reference_spp = args.reference_spp;
  report.lighting = args.lighting == "full" ? "full environment" : "environment band-limited to SH order 6";
  if (args.unshadowed_senders) report.lighting += ", characters lit without shadows where they reflect light";
  for (const study::ChartScene& chart : *scenes) report.scenes.push_back(chart.name);
  report.regions = args.regions;
  if (!args.shard.empty()) {
    const ChartShard measured{report, args.quick, shard, units, std::move(rows), std::move(bounce_rows)};
    std::error_code created;
    std::filesystem::create_directories(args.out, created);
    if (created) return fail_runtime("bench chart: " + args.out + ": cannot create: " + created.message());
    const std::filesystem::path path = std::filesystem::path(args.out) / kChartShardFile;
    if (Status s = write_file_atomically(path, std::string_view(shard_to_json(measured))); !s)
      return fail_runtime("bench chart: " + s.message());
    std::printf("bench chart: shard %s measured units %zu..%zu of %zu (%zu rows) into %s\n", args.shard.c_str(), slice.begin,
                slice.end, units, measured.rows.size(), path.string().c_str());
    return kExitOk;
  }
  std::vector<study::ChartRow> chart_rows;
  for (UnitRow& r : rows) chart_rows.push_back(std::move(r.row));
  std::vector<study::BounceRow> bounce_chart_rows;  // in unit order, as a merge of shards lists them
  std::stable_sort(bounce_rows.begin(), bounce_rows.end(),
                   [](const UnitBounceRow& a, const UnitBounceRow& b) { return a.unit < b.unit; });
  for (UnitBounceRow& r : bounce_rows) bounce_chart_rows.push_back(std::move(r.row));
  return finish_chart(args, std::move(chart_rows), report, std::move(bounce_chart_rows));
}

}  // namespace

void add_bench_chart_command(CLI::App& bench, CommandRunner& runner) {
  auto args = std::make_shared<ChartArgs>();
  auto* command = bench.add_subcommand("chart", "Speed against error to a path-traced reference, every method and setting");
  command->add_flag("--json", args->json, "Print the rows and goals as JSON on stdout");
  command->add_option("--out", args->out, "Folder for bench-chart.csv, .md and .png")->capture_default_str();
  command->add_option("--cache", args->cache, "Folder of cached references and proxy rigs")->capture_default_str();
  command->add_option("--size", args->size, "Square image size in pixels")->check(CLI::Range(settings::kMinImageSize, settings::kMaxImageSize))->capture_default_str();
  command->add_option("--frames", args->frames, "Frames of motion per scene")->check(CLI::Range(1, 16))->capture_default_str();
  command->add_option("--timing-frames", args->timing_frames, "Pipelined frames timed per setting")
      ->check(CLI::Range(1, 1000))
      ->capture_default_str();
  command->add_option("--reference-spp", args->reference_spp, "Samples per pixel of the references")
      ->check(CLI::Range(1, settings::kMaxSamplesPerPixel))
      ->capture_default_str();
  command->add_option("--scenes", args->scenes,
                      "Only these scenes (default, CesiumMan, Fox, RiggedSimple; only when named: pair and the bounce "
                      "study's contact, wall (wall-0.5, -1, -2, -4), pair-distance (pair-0.5, -1, -2, -5), crowd)")
      ->delimiter(',')
      ->check(CLI::IsMember(study::chart_scene_names()));
  command->add_option("--shared", args->shared, "Folder holding assets/gltf with the sample characters")
      ->capture_default_str();
  command->add_option("--lighting", args->lighting, "Reference lighting: sh (order 6) or full")
      ->check(CLI::IsMember({"sh", "full"}))
      ->capture_default_str();
  command->add_flag("--unshadowed-senders", args->unshadowed_senders,
                    "References light the characters without shadows where they reflect light (the bounce methods' "
                    "assumption; not physical)");
  command->add_flag("--quick", args->quick, "A small grid (default setting and each baseline), 1 and 4 spp");
  command->add_flag("--regions", args->regions,
                    "Also score every row per region (shadow, edge, thin, character, contact) and count its bounds "
                    "(negative, above unshadowed, NaN/Inf)");
  command->add_flag("--references-only", args->references_only, "Only render (or complete) the cached references");
  command->add_option("--shard", args->shard, "I/N: measure only the I-th (0-based) of N contiguous runs of the chart's "
                                              "units (scene x path tracing or setting) into OUT/bench-chart-shard.json");
  command->add_option("--merge", args->merge, "Join shard folders (their bench-chart-shard.json) into the chart in --out")
      ->expected(1, -1);
  command->add_option("--timings-from", args->timings_from,
                      "With --merge: take each row's ms per frame from this bench-chart-timings.json (to compare a "
                      "merge with a single run byte for byte)");
  add_device_option(*command, args->device);
  add_quiet_flag(*command);
  command->callback([&runner, args] { runner = [args] { return run_bench_chart(*args); }; });
}

}  // namespace proxygi::app
