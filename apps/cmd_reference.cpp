// proxygi reference SCENE --frame F --spp N -o OUT.exr [--mode direct|one-bounce|multi-bounce]
//   [--lighting sh|full] [--lighting-order N] [--width W --height H] [--seed S] [--sampler sobol|random] [--threads T] [--accumulate]
//   [--guided-filter [--filter-radius R]] [--quiet]
// Path-traces one frame of a scene with Embree (the ground truth of the accuracy study) and
// writes OUT.exr plus its feature and statistics files (ref/reference_render_io.h lists them).
// Ctrl-C (SIGINT, SIGTERM) stops after the sample in progress and keeps the whole samples so far
// (OUT.* with OUT.partial, the exact sums); the same command with --accumulate finishes them, to
// the bits an uninterrupted run writes.
// SCENE is a scene file, or "default" / "crowd" for a built-in scene (a file by that name wins).
// The scene is loaded and posed by world::World (the GPU renderer's rules), without proxy rigs.
// Bad arguments or scenes exit 2, failures while rendering or writing exit 1.
#include <unistd.h>

#include <algorithm>
#include <csignal>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

#include "apps/commands.h"
#include "settings/limits.h"
#include "image/image.h"
#include "ref/embree_scene.h"
#include "apps/scene_input.h"
#include "ref/scene_geometry.h"
#include "ref/path_tracer.h"
#include "ref/path_tracer_lighting.h"
#include "ref/reference_render.h"
#include "ref/reference_render_io.h"
#include "scene/camera.h"
#include "scene/scene_defaults.h"
#include "scene/scene_parse.h"
#include "sh/basis.h"
#include "world/world.h"

namespace proxygi::app {
namespace {

struct ReferenceArgs {
  SceneArgs scene;
  int frame = 0;
  int spp = 64;
  std::string output;
  std::string mode = "one-bounce";
  std::string lighting = "sh";
  int lighting_order = 0;  // 0: the scene's render.sh_order
  int width = 0;   // 0: the scene's output size
  int height = 0;
  std::uint32_t seed = 0;
  std::string sampler = "sobol";
  int threads = 0;
  bool accumulate = false;
  bool guided_filter = false;
  int filter_radius = 24;
  std::string preview;  // optional PNG of OUT.exr (clamped, sRGB), for a quick look
  int stop_after_samples = 0;  // test hook: raise SIGINT after this many samples of this run
};

volatile std::sig_atomic_t g_interrupted = 0;
extern "C" void on_reference_interrupt(int signal) {
  g_interrupted = 1;
  std::signal(signal, SIG_DFL);  // a second Ctrl-C ends the process at once
}

std::string format_duration(double seconds) {
  char text[32];
  if (seconds >= 3600.0) std::snprintf(text, sizeof text, "%dh%02dm", int(seconds / 3600.0), int(std::fmod(seconds, 3600.0) / 60.0));
  else if (seconds >= 60.0) std::snprintf(text, sizeof text, "%dm%02ds", int(seconds / 60.0), int(std::fmod(seconds, 60.0)));
  else std::snprintf(text, sizeof text, "%.1fs", seconds);
  return text;
}

int run_reference(const ReferenceArgs& args) {
  {
    std::string extension = std::filesystem::path(args.output).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    if (extension != ".exr")
      return fail_bad_input("-o '" + args.output + "': the reference is linear radiance, written as .exr (use --preview FILE.png "
                            "for a PNG to look at)");
  }
  auto loaded = open_scene(args.scene);
  if (!loaded) return fail_bad_input(loaded.message());
  const scene::Scene& scene = *loaded;
  const int last = scene::last_frame(scene.output);
  if (args.frame < scene.output.first_frame || args.frame > last)
    return fail_bad_input("--frame " + std::to_string(args.frame) + " is outside the scene's frames " +
                          std::to_string(scene.output.first_frame) + ":" + std::to_string(last));
  const int width = args.width > 0 ? args.width : scene.output.width;
  const int height = args.height > 0 ? args.height : scene.output.height;

  ref::PathTracerSettings settings;
  if (args.mode == "direct") settings.transport = ref::LightTransport::direct;
  else if (args.mode == "one-bounce") settings.transport = ref::LightTransport::one_bounce;
  else settings.transport = ref::LightTransport::multi_bounce;
  const ref::LightingKind lighting_kind = args.lighting == "sh" ? ref::LightingKind::sh : ref::LightingKind::full;
  const int lighting_order = args.lighting_order > 0 ? args.lighting_order : scene.render.sh_order;

  ref::ReferenceRecord record;
  record.scene = args.scene.scene.empty() ? std::string("default") : args.scene.scene;
  record.frame = args.frame;
  record.time_s = scene::frame_time_s(scene.output, args.frame);
  record.width = width;
  record.height = height;
  record.transport = args.mode;
  record.lighting = args.lighting;
  record.sh_order = lighting_order;
  record.seed = args.seed;
  record.sampler = args.sampler;
  record.guided_filter = args.guided_filter;

  const ref::ReferencePaths paths = ref::reference_paths(args.output);
  if (const std::filesystem::path folder = paths.radiance.parent_path(); !folder.empty()) {
    std::error_code error;
    std::filesystem::create_directories(folder, error);
    if (error) return fail_runtime(folder.string() + ": cannot create the output folder: " + error.message());
  }
  std::optional<ref::SampleSums> previous;
  int spp = args.spp;  // samples this run traces
  if (args.accumulate && std::filesystem::exists(paths.record)) {
    auto old = ref::read_record(paths.record);
    if (!old) return fail_bad_input(old.message());
    if (std::string why = ref::record_mismatch(*old, record); !why.empty())
      return fail_bad_input("--accumulate: " + paths.record.string() + " describes another image (" + why + ")");
    auto sums = ref::read_previous_sums(paths, *old);
    if (!sums) return fail_bad_input("--accumulate: " + sums.message());
    previous = std::move(*sums);
    record.samples = old->samples;
    record.seconds = old->seconds;
    record.rays = old->rays;
    if (old->target_samples > old->samples) {  // an interrupted run: finish what it was asked for
      spp = int(old->target_samples - old->samples);
      if (!quiet())
        std::fprintf(stderr, "reference: resuming an interrupted run: %u of %u samples done, tracing the %d missing%s\n",
                     old->samples, old->target_samples, spp, args.spp != spp ? " (instead of --spp)" : "");
    }
  }
  if (std::uint64_t(record.samples) + std::uint64_t(spp) > std::uint64_t(settings::kMaxSamplesPerPixel))
    return fail_bad_input("--accumulate: " + std::to_string(record.samples) + " + " + std::to_string(spp) +
                          " samples is more than the limit of " + std::to_string(settings::kMaxSamplesPerPixel) + " per pixel");
  record.target_samples = record.samples + std::uint32_t(spp);

  auto world = world::World::load(scene, {.assets_dir = assets_dir(), .load_rigs = false});
  if (!world) return fail_bad_input(record.scene + ": " + world.message());
  world::WorldState state;
  if (Status evaluated = (*world)->evaluate(record.time_s, std::nullopt, state); !evaluated)
    return fail_bad_input(evaluated.message());
  auto meshes = ref::world_meshes(**world, state, ref::make_scene_geometry(**world));
  if (!meshes) return fail_bad_input(meshes.message());
  auto geometry = ref::EmbreeScene::build(std::move(*meshes));
  if (!geometry) return fail_runtime(geometry.message());
  auto lighting = ref::EnvironmentLight::from_scene(scene, lighting_kind, lighting_order);
  if (!lighting) return fail_bad_input(lighting.message());
  auto background = ref::EnvironmentLight::from_scene(scene, ref::LightingKind::full, lighting_order);
  if (!background) return fail_bad_input(background.message());
  const ref::PathTracer tracer(*geometry, *lighting, *background, settings);
  const scene::CameraState& camera = state.camera;

  if (!quiet())
    std::fprintf(stderr, "reference: %s frame %d (t = %.3f s), %d triangles, %dx%d, %d spp (samples %u..%u), %s, %s lighting\n",
                 record.scene.c_str(), args.frame, record.time_s, int(geometry->triangle_count()), width, height, spp,
                 record.samples, record.target_samples - 1, args.mode.c_str(), args.lighting.c_str());
  ref::RenderJob job;
  job.width = width;
  job.height = height;
  job.spp = spp;
  job.first_sample = record.samples;
  job.seed = args.seed;
  job.sampler = args.sampler == "random" ? ref::Sampler::random : ref::Sampler::sobol;
  job.threads = args.threads;
  job.stop = &g_interrupted;
  ref::RenderStats stats;
  // On a terminal one line rewritten with \r; into a file or pipe a line per tenth of the work.
  const bool terminal = isatty(fileno(stderr)) != 0;
  int last_tenth = -1;
  auto progress = [terminal, &last_tenth, &args](const ref::RenderProgress& p) {
    if (args.stop_after_samples > 0 && p.samples_done >= std::uint32_t(args.stop_after_samples) && !g_interrupted)
      std::raise(SIGINT);
    if (quiet()) return;
    const double percent = 100.0 * p.tiles_done / std::max(p.tiles_total, 1);
    if (!terminal) {
      if (int(percent / 10.0) == last_tenth) return;
      last_tenth = int(percent / 10.0);
    }
    std::fprintf(stderr, "%s  %5.1f%%  %s elapsed  ETA %s  %.2f Mrays/s%s", terminal ? "\r" : "", percent,
                 format_duration(p.elapsed_s).c_str(), format_duration(p.eta_s).c_str(),
                 p.elapsed_s > 0.0 ? double(p.rays) / p.elapsed_s * 1e-6 : 0.0, terminal ? "   " : "\n");
    std::fflush(stderr);
  };
  ref::SampleSums sums;
  if (previous) {
    sums = std::move(*previous);
  } else {
    sums.width = width;
    sums.height = height;
    const std::size_t pixels = std::size_t(width) * std::size_t(height);
    sums.radiance.assign(pixels, glm::dvec3(0.0));
    sums.radiance_squared.assign(pixels, glm::dvec3(0.0));
    sums.indirect.assign(pixels, glm::dvec3(0.0));
  }
  std::signal(SIGINT, on_reference_interrupt);
  std::signal(SIGTERM, on_reference_interrupt);
  const std::uint32_t samples_before = sums.samples;
  const Status traced = ref::accumulate_samples(tracer, camera, job, sums, &stats, progress);
  std::signal(SIGINT, SIG_DFL);  // writing the files below takes moments; they are atomic anyway
  std::signal(SIGTERM, SIG_DFL);
  if (terminal && !quiet()) std::fprintf(stderr, "\n");
  if (!traced) return fail_bad_input(traced.message());
  const bool finished = sums.samples == record.target_samples;
  if (!finished && sums.samples == samples_before)
    return fail_runtime("interrupted before the first sample was finished; " + paths.radiance.string() + " is unchanged");
  const int traced_spp = int(sums.samples - samples_before);
  record.samples = sums.samples;
  record.seconds += stats.seconds;
  record.rays += stats.rays;

  const ref::ReferenceImages images = ref::to_images(sums);
  const ref::PixelFeatures features = ref::render_features(*geometry, camera, width, height);
  std::optional<image::ImageF> filtered;
  if (args.guided_filter) {
    ref::GuidedFilterSettings filter;
    filter.radius = args.filter_radius;
    filter.depth_scale = scene.ground.enabled ? scene.ground.size : 20.0f;
    auto result = ref::guided_filter_reference(images, features, filter);
    if (!result) return fail_runtime(result.message());
    filtered = std::move(*result);
  }
  std::error_code ignored;
  if (!finished) {
    if (Status s = ref::write_partial_sums(paths.partial, sums); !s) return fail_runtime(s.message());
  }
  if (Status s = ref::write_reference(paths, images, features, record, filtered ? &*filtered : nullptr); !s)
    return fail_runtime(s.message());
  if (finished) std::filesystem::remove(paths.partial, ignored);
  if (!args.preview.empty()) {
    const image::ImageF& shown = filtered ? *filtered : images.radiance;
    if (Status s = image::write_png(args.preview, shown); !s) return fail_runtime(s.message());
  }
  if (!finished)
    return fail_runtime("interrupted: kept " + std::to_string(record.samples) + " of " + std::to_string(record.target_samples) +
                        " samples in " + paths.radiance.string() + "; run the same command with --accumulate to finish");
  std::printf("%s: %u spp, %.2f s tracing (%.1f ms per spp), %.3g rays, %.2f Mrays/s\n", paths.radiance.string().c_str(),
              record.samples, stats.seconds, 1e3 * stats.seconds / std::max(traced_spp, 1), double(stats.rays),
              stats.mrays_per_second());
  return kExitOk;
}

}  // namespace

void add_reference_command(CLI::App& app, CommandRunner& runner) {
  auto args = std::make_shared<ReferenceArgs>();
  CLI::App* command = app.add_subcommand("reference", "Path-trace a ground-truth frame with Embree");
  add_scene_options(*command, args->scene, false);
  command->add_option("--frame", args->frame, "Frame index (scene time = frame / fps)")->required();
  command->add_option("--spp", args->spp, "Samples (paths) per pixel to trace in this run")
      ->required()
      ->check(CLI::Range(1, settings::kMaxSamplesPerPixel));
  command->add_option("-o,--output", args->output, "Output radiance EXR (feature files are written next to it)")
      ->required();
  command->add_option("--mode", args->mode, "Light transport: direct, one-bounce or multi-bounce")
      ->check(CLI::IsMember({"direct", "one-bounce", "multi-bounce"}))
      ->capture_default_str();
  command->add_option("--lighting", args->lighting,
                      "sh: the environment band-limited to --lighting-order and windowed, as the proxy "
                      "method sees it; full: the environment itself (sun sampled with MIS)")
      ->check(CLI::IsMember({"sh", "full"}))
      ->capture_default_str();
  command->add_option("--lighting-order", args->lighting_order,
                      "SH order (bands) of the sh lighting, the reference's own band limit (default: the scene's "
                      "render.sh_order)")
      ->check(CLI::Range(sh::kMinOrder, sh::kMaxOrder));
  command->add_option("--width", args->width, "Image width (default: the scene's)")->check(CLI::Range(settings::kMinImageSize, settings::kMaxImageSize));
  command->add_option("--height", args->height, "Image height (default: the scene's)")->check(CLI::Range(settings::kMinImageSize, settings::kMaxImageSize));
  command->add_option("--seed", args->seed, "Random seed; the same seed gives the same image")->capture_default_str();
  command->add_option("--sampler", args->sampler,
                      "sobol: Owen-scrambled Sobol pairs (default); random: plain Monte Carlo (before 2026-12)")
      ->check(CLI::IsMember({"sobol", "random"}))
      ->capture_default_str();
  command->add_option("--threads", args->threads, "Worker threads (default: all cores)")->check(CLI::Range(0, 1024));
  command->add_flag("--accumulate", args->accumulate,
                    "Continue from OUT's previous samples (same scene, frame, size, mode, lighting and seed); "
                    "after an interrupted run, trace the samples it was missing");
  command->add_flag("--guided-filter", args->guided_filter,
                    "Guided-filter the indirect part by normal and depth (the denoised low-spp method)");
  command->add_option("--filter-radius", args->filter_radius, "Guided filter window radius in pixels")
      ->check(CLI::Range(1, 256))
      ->capture_default_str();
  command->add_option("--preview", args->preview, "Also write this PNG of the radiance (clamped to [0, 1], sRGB)");
  // Test hook (not in --help): behave as if Ctrl-C came after N samples of this run.
  command->add_option("--stop-after-samples", args->stop_after_samples)->group("")->check(CLI::Range(1, settings::kMaxSamplesPerPixel));
  add_quiet_flag(*command);
  command->callback([args, &runner] { runner = [args] { return run_reference(*args); }; });
}

}  // namespace proxygi::app
