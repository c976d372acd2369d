// proxygi bench frame [--json] [--indirect-operator point|averaged|exact] [--indirect-method
// proxy|vsgl|none]: milliseconds per pass
// and per frame, proxies, fps and the shadow accumulation's effective pixel-proxy pairs per
// second, for the default scene at 512×512 with receivers at 1/1, 1/2, 1/4, 1/8, the two
// baselines of the speed–accuracy chart on the default scene (vertex-based accumulation; scalar
// AO at 1/4) and the built-in crowd of 20 characters at 1/4, in one run, with the chosen indirect
// operator (default averaged). The image-space settings run with both shadow splats (compute
// gather and raster splat; the raster splat's depth set-up and resolve also timed on their own).
// Whole frames are timed pipelined (two frames in flight, as `record` runs); passes are timed one
// fenced submit each with the CPU clock (lavapipe's timestamps are unreliable).
#include <sys/resource.h>

#include <algorithm>
#include <cstdio>

#include <nlohmann/json.hpp>

#include "apps/bench_splat_stages.h"
#include "apps/commands.h"
#include "settings/limits.h"
#include "gpu/scene_renderer.h"
#include "run/frame_loop.h"
#include "world/world.h"
#include "scene/scene_defaults.h"
#include "scene/scene_names.h"
#include "scene/scene_parse.h"

namespace proxygi::app {
namespace {

struct BenchOptions {
  bool json = false;
  int frames = 6;
  int size = 512;
  std::string device;
  std::string indirect_operator = "averaged";  // scene names (scene::names::kIndirectOperator)
  std::string indirect_method = "proxy";       // settings::kIndirectMethodNames
  int vsgl_lights = 1;                         // render.vsgl_lights (indirect_method vsgl)
  std::string vsgl_grouping = "vertex_ranges"; // settings::kVsglGroupingNames
  std::string proxy_lod = "off";               // settings::kProxyLodNames (render.proxy_lod of every row)
  std::string antialiasing = "off";            // settings::kAntialiasingNames
  std::string readback = "hdr";                // hdr: LDR + HDR read back (record --exr); ldr: LDR only (record, viewer)
  bool hdr() const { return readback == "hdr"; }
  std::vector<std::string> only;               // empty: every row; else "default", "crowd", "baselines", "prt"
  bool runs(const std::string& part) const { return only.empty() || asked(part); }
  bool asked(const std::string& part) const { return std::find(only.begin(), only.end(), part) != only.end(); }
};

settings::IndirectOperator indirect_operator(const std::string& name) {
  for (const auto& [text, value] : scene::names::kIndirectOperator)
    if (text == name) return value;
  return settings::IndirectOperator::averaged;  // unreachable: the option is checked
}

settings::IndirectMethod indirect_method(const std::string& name) {
  for (const auto& [text, value] : settings::kIndirectMethodNames)
    if (text == name) return value;
  return settings::IndirectMethod::proxy;  // unreachable: the option is checked
}

struct ConfigResult {
  std::string name;
  std::string method;  // render.method: image, vertex, ao
  std::string splat;   // render.splat: compute, raster
  std::size_t receivers = 0;
  int receiver_scale = 0;
  std::size_t characters = 0;
  double frame_ms = 0.0;  // pipelined wall time per frame
  gpu::PassTimings passes;  // mean over the timed frames
  double pairs_per_second = 0.0;
  SplatStageTimes raster_stages;  // raster splat only
};

const char* splat_name(settings::SplatMethod method) {
  return method == settings::SplatMethod::raster ? "raster" : "compute";
}

// One world per scene, loaded once: every setting of that scene renders it.
Result<std::shared_ptr<const world::World>> load_world(const scene::Scene& scene) {
  auto world = world::World::load(scene, {.assets_dir = assets_dir(), .load_rigs = true, .write_rig_cache = true});
  if (!world) return world.error();
  return std::shared_ptr<const world::World>(std::move(*world));
}

// A setting of the table: the scene's settings at receiver scale 1/scale with the splat and the
// options that apply to every setting.
settings::RenderSettings setting_of(settings::RenderSettings render, int scale, settings::SplatMethod splat, const BenchOptions& options) {
  render.receiver_scale = scale;
  render.splat = splat;
  render.indirect_operator = indirect_operator(options.indirect_operator);
  render.indirect_method = indirect_method(options.indirect_method);
  render.vsgl_lights = options.vsgl_lights;
  for (const auto& [text, value] : settings::kVsglGroupingNames)
    if (text == options.vsgl_grouping) render.vsgl_grouping = value;
  for (const auto& [text, value] : settings::kAntialiasingNames)
    if (text == options.antialiasing) render.antialiasing = value;
  for (const auto& [text, value] : settings::kProxyLodNames)
    if (text == options.proxy_lod) render.proxy_lod = value;
  return render;
}

Result<ConfigResult> run_config(gpu::Context& context, const std::string& name,
                                const std::shared_ptr<const world::World>& world, settings::RenderSettings scene_render,
                                int scale, const BenchOptions& options,
                                settings::SplatMethod splat = settings::SplatMethod::compute) {
  const scene::Scene& scene = world->scene();
  const settings::RenderSettings render = setting_of(scene_render, scale, splat, options);
  auto renderer = gpu::SceneRenderer::create(context, world, render, std::uint32_t(options.size),
                                             std::uint32_t(options.size));
  if (!renderer) return renderer.error();
  ConfigResult result;
  result.name = name;
  result.method = std::string(settings::name_of(render.method));
  result.splat = splat_name(splat);
  result.receiver_scale = scale;
  const gpu::FrameConfig& config = (*renderer)->config();
  result.receivers = config.render.method == settings::ShadingMethod::vertex ? config.vertex_receivers
                                                                              : std::size_t(config.receiver_count());
  result.characters = scene.characters.size();
  const int first = scene.output.first_frame;
  auto frame_ms = run::time_pipelined_frames(**renderer, first, options.frames, options.hdr());
  if (!frame_ms) return frame_ms.error();
  result.frame_ms = *frame_ms;

  for (int i = 0; i < options.frames; ++i) {
    auto timings = (*renderer)->time_passes(first + 2 + i, gpu::PassClock::fenced_cpu, options.hdr());
    if (!timings) return timings.error();
    for (std::size_t p = 0; p < timings->milliseconds.size(); ++p)
      result.passes.milliseconds[p] += timings->milliseconds[p] / options.frames;
    for (std::size_t p = 0; p < timings->cpu_milliseconds.size(); ++p)
      result.passes.cpu_milliseconds[p] += timings->cpu_milliseconds[p] / options.frames;
    result.passes.cpu_prepare_ms += timings->cpu_prepare_ms / options.frames;
    result.passes.proxies = timings->proxies;
  }
  const double receivers = double(result.receivers);
  const double shadow_ms = result.passes.milliseconds[std::size_t(gpu::FramePass::shadow)];
  result.pairs_per_second = shadow_ms > 0.0 ? receivers * double(result.passes.proxies) / (shadow_ms * 1e-3) : 0.0;
  if (splat == settings::SplatMethod::raster) {
    auto stages = time_splat_stages(context, render.sh_order, std::uint32_t(options.size), std::uint32_t(scale),
                                    options.frames);
    if (!stages) return stages.error();
    result.raster_stages = *stages;
  }
  return result;
}

// 1/1 against 1/4 receivers of one setting, interleaved: `rounds` rounds of one timed block of
// each (run::time_pipelined_frames, warm-up included), both renderers alive throughout, so a
// slow drift of a shared machine's speed falls on both alike. The speedup is the ratio of the
// summed times; the rounds' own ratios show the spread.
constexpr int kPairedRounds = 4;
struct PairedSpeedup {
  double ratio = 0.0;
  std::vector<double> rounds;
};
Result<PairedSpeedup> paired_quarter_speedup(gpu::Context& context, const std::shared_ptr<const world::World>& world,
                                             const settings::RenderSettings& scene_render, settings::SplatMethod splat,
                                             const BenchOptions& options, int rounds) {
  std::unique_ptr<gpu::SceneRenderer> renderers[2];
  const int scales[2] = {1, 4};
  for (int i = 0; i < 2; ++i) {
    auto created = gpu::SceneRenderer::create(context, world, setting_of(scene_render, scales[i], splat, options),
                                              std::uint32_t(options.size), std::uint32_t(options.size));
    if (!created) return created.error();
    renderers[i] = std::move(*created);
  }
  PairedSpeedup out;
  double sums[2] = {0.0, 0.0};
  const int first = world->scene().output.first_frame;
  for (int round = 0; round < rounds; ++round) {
    double ms[2];
    for (int i = 0; i < 2; ++i) {
      auto timed = run::time_pipelined_frames(*renderers[i], first, options.frames, options.hdr());
      if (!timed) return timed.error();
      ms[i] = *timed, sums[i] += *timed;
    }
    out.rounds.push_back(ms[0] / ms[1]);
  }
  out.ratio = sums[0] / sums[1];
  return out;
}

int run_bench_frame(const BenchOptions& options) {
  auto context = gpu::Context::create({.device_request = options.device});
  if (!context) return fail_runtime(context.message());
  auto default_world = load_world(scene::default_scene());
  if (!default_world) return fail_runtime("bench frame: default scene: " + default_world.message());
  auto crowd_world = load_world(scene::crowd_scene());
  if (!crowd_world) return fail_runtime("bench frame: crowd scene: " + crowd_world.message());
  const settings::RenderSettings default_settings = (*default_world)->scene().render;
  const settings::RenderSettings crowd_settings = (*crowd_world)->scene().render;
  std::vector<ConfigResult> results;
  // --only prt: the wall corner (assets/scenes/wall_corner.json) at each render.static_transfer,
  // rows "wc:l0", "wc:ratio", "wc:l1" (the PRT read from its cache, computed on the first run).
  // Only when asked for: the first run precomputes for tens of seconds.
  if (options.asked("prt")) {
    auto corner_scene = scene::load_scene(assets_dir() / "scenes/wall_corner.json");
    if (!corner_scene) return fail_runtime("bench frame: " + corner_scene.message());
    auto corner_world = load_world(*corner_scene);
    if (!corner_world) return fail_runtime("bench frame: wall corner: " + corner_world.message());
    for (const auto& [level_name, level] : settings::kStaticTransferNames) {
      settings::RenderSettings corner = corner_scene->render;
      corner.static_transfer = level;
      auto result = run_config(**context, "wc:" + std::string(level_name), *corner_world, corner,
                               corner.receiver_scale, options);
      if (!result) return fail_runtime("bench frame: wall corner, " + std::string(level_name) + ": " + result.message());
      results.push_back(*result);
    }
  }
  constexpr settings::SplatMethod kSplats[] = {settings::SplatMethod::compute, settings::SplatMethod::raster};
  for (int scale : settings::kReceiverScales)
    for (settings::SplatMethod splat : kSplats) {
      if (!options.runs("default")) break;
      auto result = run_config(**context, "default", *default_world, default_settings, scale, options, splat);
      if (!result)
        return fail_runtime("bench frame: default scene, 1/" + std::to_string(scale) + ", " + splat_name(splat) +
                            " splat: " + result.message());
      results.push_back(*result);
    }
  for (auto method : {settings::ShadingMethod::vertex, settings::ShadingMethod::ambient_occlusion}) {
    if (!options.runs("baselines")) break;
    settings::RenderSettings baseline = default_settings;
    baseline.method = method;
    auto result = run_config(**context, "default", *default_world, baseline, 4, options);
    if (!result) return fail_runtime("bench frame: default scene, baseline: " + result.message());
    results.push_back(*result);
  }
  for (settings::SplatMethod splat : kSplats) {
    if (!options.runs("crowd")) break;
    auto crowd = run_config(**context, "crowd", *crowd_world, crowd_settings, 4, options, splat);
    if (!crowd)
      return fail_runtime("bench frame: crowd scene, " + std::string(splat_name(splat)) + " splat: " + crowd.message());
    results.push_back(*crowd);
  }

  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  const double peak_mib = double(usage.ru_maxrss) / 1024.0;
  const auto& report = (*context)->report();
  const settings::SplatMethod default_splat = scene::default_scene().render.splat;
  const std::size_t column = default_splat == settings::SplatMethod::raster ? 1 : 0;  // results: compute, raster pairs
  const bool has_default = options.runs("default");
  const std::size_t first_default = options.asked("prt") ? std::size(settings::kStaticTransferNames) : 0;
  const double k1 = has_default ? results[first_default + 0 + column].frame_ms : 0.0;
  const double k4 = has_default ? results[first_default + 4 + column].frame_ms : 1.0;
  PairedSpeedup paired;
  if (has_default) {
    auto measured = paired_quarter_speedup(**context, *default_world, default_settings, default_splat, options, kPairedRounds);
    if (!measured) return fail_runtime("bench frame: 1/1 against 1/4, interleaved: " + measured.message());
    paired = *measured;
  }

  if (options.json) {
    nlohmann::json out;
    out["device"] = report.name;
    out["driver"] = report.driver;
    out["size"] = options.size;
    out["frames"] = options.frames;
    out["indirect_operator"] = options.indirect_operator;
    out["indirect_method"] = options.indirect_method;
    out["vsgl_lights"] = options.vsgl_lights;
    out["vsgl_grouping"] = options.vsgl_grouping;
    out["antialiasing"] = options.antialiasing;
    out["proxy_lod"] = options.proxy_lod;
    out["readback"] = options.readback;
    out["peak_resident_mib"] = peak_mib;
    if (has_default) {
      out["speedup_quarter_over_full"] = paired.ratio;
      out["speedup_quarter_over_full_rounds"] = paired.rounds;
      out["speedup_quarter_over_full_sequential"] = k1 / k4;  // from the table's rows, timed minutes apart
    }
    for (const auto& result : results) {
      nlohmann::json entry = {{"scene", result.name},
                              {"method", result.method},
                              {"splat", result.splat},
                              {"receivers", result.receivers},
                              {"receiver_scale", result.receiver_scale},
                              {"characters", result.characters},
                              {"proxies", result.passes.proxies},
                              {"frame_ms", result.frame_ms},
                              {"fps", 1000.0 / result.frame_ms},
                              {"cpu_prepare_ms", result.passes.cpu_prepare_ms},
                              {"shadow_pairs_per_second", result.pairs_per_second}};
      for (std::size_t p = 0; p < result.passes.milliseconds.size(); ++p)
        entry["pass_ms"][gpu::frame_pass_name(gpu::FramePass(p))] = result.passes.milliseconds[p];
      for (std::size_t p = 0; p < result.passes.cpu_milliseconds.size(); ++p)
        entry["pass_cpu_ms"][gpu::frame_pass_name(gpu::FramePass(p))] = result.passes.cpu_milliseconds[p];
      if (result.splat == "raster")
        entry["raster_splat_stage_ms"] = {{"depth", result.raster_stages.depth_ms},
                                          {"resolve", result.raster_stages.resolve_ms}};
      out["results"].push_back(entry);
    }
    std::printf("%s\n", out.dump(2).c_str());
    return kExitOk;
  }
  std::printf("device: %s (%s), %dx%d, %d frames per setting, indirect %s (%s operator)", report.name.c_str(),
              report.driver.c_str(), options.size, options.size, options.frames, options.indirect_method.c_str(),
              options.indirect_operator.c_str());
  if (options.indirect_method == "vsgl")
    std::printf(", %d lights per character by %s", options.vsgl_lights, options.vsgl_grouping.c_str());
  if (options.antialiasing != "off") std::printf(", antialiasing %s", options.antialiasing.c_str());
  std::printf(", proxy_lod %s, readback %s\n", options.proxy_lod.c_str(), options.readback.c_str());
  std::printf("%-8s %-6s %-7s %3s %9s %5s %7s %9s %6s |", "scene", "method", "splat", "k", "receivers", "chars",
              "proxies", "frame ms", "fps");
  for (std::size_t p = 0; p < std::size_t(gpu::FramePass::count); ++p)
    std::printf(" %9.9s", gpu::frame_pass_name(gpu::FramePass(p)));
  std::printf(" | %s\n", "shadow Mpairs/s");
  for (const auto& result : results) {
    const std::string k = result.method == "vertex" ? "-" : "1/" + std::to_string(result.receiver_scale);
    std::printf("%-8s %-6s %-7s %3s %9zu %5zu %7zu %9.2f %6.1f |", result.name.c_str(), result.method.c_str(),
                result.splat.c_str(), k.c_str(), result.receivers, result.characters, result.passes.proxies,
                result.frame_ms, 1000.0 / result.frame_ms);
    for (double ms : result.passes.milliseconds) std::printf(" %9.2f", ms);
    std::printf(" | %.0f\n", result.pairs_per_second / 1e6);
  }
  std::printf("shadow pass: scene, k, compute gather ms (Mpairs/s), raster splat ms (Mpairs/s; of which depth "
              "set-up + resolve ms)\n");
  const auto shadow = [](const ConfigResult& r) { return r.passes.milliseconds[std::size_t(gpu::FramePass::shadow)]; };
  for (std::size_t i = 1; i < results.size(); ++i) {
    const ConfigResult& gather = results[i - 1];
    const ConfigResult& raster = results[i];
    if (raster.splat != "raster" || gather.splat != "compute" || gather.name != raster.name ||
        gather.method != raster.method || gather.receiver_scale != raster.receiver_scale)
      continue;
    std::printf("  %-8s 1/%d  %8.2f (%5.0f)  %8.2f (%5.0f; %.2f + %.2f)\n", gather.name.c_str(), gather.receiver_scale,
                shadow(gather), gather.pairs_per_second / 1e6, shadow(raster), raster.pairs_per_second / 1e6,
                raster.raster_stages.depth_ms, raster.raster_stages.resolve_ms);
  }
  if (has_default) {
    std::printf("1/4 receivers with %s upsampling vs 1/1 (%s splat): %.2fx faster per frame (%d interleaved rounds:", "bilateral",
                splat_name(default_splat), paired.ratio, kPairedRounds);
    for (double ratio : paired.rounds) std::printf(" %.2f", ratio);
    std::printf("; the table's rows give %.2fx)\n", k1 / k4);
  }
  std::printf("peak resident memory: %.0f MiB\n", peak_mib);
  return kExitOk;
}

}  // namespace

void add_bench_frame_command(CLI::App& bench, CommandRunner& runner) {
  auto options = std::make_shared<BenchOptions>();
  auto* command = bench.add_subcommand("frame", "Per-pass and per-frame time of the soft-GI frame (default and crowd scenes)");
  command->add_flag("--json", options->json, "Machine-readable output");
  command->add_option("--frames", options->frames, "Frames timed per setting")->check(CLI::Range(1, 1000));
  command->add_option("--size", options->size, "Square output size in pixels")->check(CLI::Range(settings::kMinImageSize, settings::kMaxImageSize));
  command->add_option("--indirect-operator", options->indirect_operator, "Indirect operator of every setting")
      ->check(CLI::IsMember({"point", "averaged", "exact"}));
  command->add_option("--indirect-method", options->indirect_method, "Bounce light of every setting (render.indirect_method)")
      ->check(CLI::IsMember({"proxy", "vsgl", "none"}));
  command->add_option("--vsgl-lights", options->vsgl_lights, "vsgl: lights per character (render.vsgl_lights)")
      ->check(CLI::IsMember(std::vector<int>(settings::kVsglLightsPerCharacter.begin(),
                                             settings::kVsglLightsPerCharacter.end())));
  command->add_option("--vsgl-grouping", options->vsgl_grouping, "vsgl: vertex_ranges or bone_groups (render.vsgl_grouping)")
      ->check(CLI::IsMember({"vertex_ranges", "bone_groups"}));
  command->add_option("--antialiasing", options->antialiasing, "Anti-aliasing of every setting (render.antialiasing)")
      ->check(CLI::IsMember({"off", "ssaa2", "ssaa4"}));
  command->add_option("--proxy-lod", options->proxy_lod, "Proxy levels of detail of every setting (render.proxy_lod)")
      ->check(CLI::IsMember({"off", "auto"}));
  command->add_option("--readback", options->readback,
                      "Frame output timed: hdr (LDR and HDR read back, as record --exr; default) or ldr (the LDR frame "
                      "alone, as record without --exr and the viewer)")
      ->check(CLI::IsMember({"hdr", "ldr"}));
  command->add_option("--only", options->only,
                      "Rows to run (default: all but prt): default, baselines, crowd, prt (the wall corner at each "
                      "render.static_transfer)")
      ->delimiter(',')
      ->check(CLI::IsMember({"default", "baselines", "crowd", "prt"}));
  add_device_option(*command, options->device);
  add_quiet_flag(*command);
  command->callback([&runner, options] { runner = [options] { return run_bench_frame(*options); }; });
}

}  // namespace proxygi::app
