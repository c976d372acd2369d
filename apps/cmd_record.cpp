// proxygi record [SCENE] -o DIR [--frames A:B] [--shard I/N] [--exr] [--mp4|--no-mp4] [--aov]
//                [--width W --height H] [--device NAME|INDEX]
// Renders a scene headless into DIR/frame_%05d.png (+ .exr, + aov/, + video.mp4), resumably:
// frames whose files exist are skipped, every file is written atomically, and shards split the
// frame range so independent processes fill one folder with the bytes a single run would write.
#include <algorithm>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <optional>

#include "apps/commands.h"
#include "settings/limits.h"
#include "base/log.h"
#include "apps/record_output.h"
#include "apps/record_progress.h"
#include "apps/record_video.h"
#include "apps/scene_input.h"
#include "gpu/scene_renderer.h"
#include "world/world.h"
#include "run/frame_loop.h"
#include "run/frame_plan.h"
#include "run/task_queue.h"
#include "scene/camera.h"
#include "scene/scene_defaults.h"
#include "scene/scene_parse.h"
#include "scene/scene_write.h"
#include "proxies/rig_file.h"

#ifndef PROXYGI_VERSION
#define PROXYGI_VERSION "unknown"
#endif

namespace proxygi::app {
namespace {

struct RecordArgs {
  SceneArgs scene;  // file, "default", "crowd", a model, or empty (default)
  std::string output;
  std::string frames;
  std::string shard;
  bool exr = false;
  bool mp4 = false;
  bool no_mp4 = false;
  bool aov = false;
  bool overwrite = false;
  bool refit = false;
  bool verify = false;
  int width = 0;   // 0: the scene's
  int height = 0;
  std::string device;
};

volatile std::sig_atomic_t g_interrupted = 0;
extern "C" void on_interrupt(int) { g_interrupted = 1; }

bool has_format(const scene::Output& output, scene::OutputFormat format) {
  return std::find(output.formats.begin(), output.formats.end(), format) != output.formats.end();
}

struct RecordPlan {
  std::filesystem::path dir;
  bool exr = false;
  bool aov = false;
  std::vector<int> frames;  // this process's share, not yet on disk
  int skipped = 0;
};

// Renders plan.frames with the renderer's ring of frames in flight (run::render_frames): frame
// t+1 is prepared and submitted before frame t is handed to the encoder threads, which write
// its files while the GPU renders on. The HDR readback is skipped when no EXR is written.
Status render_in_flight(gpu::SceneRenderer& renderer, const RecordPlan& plan, RecordProgress& progress) {
  const scene::Output& output = renderer.scene().output;
  run::FrameLoopOptions options;
  options.output = gpu::FrameOutput::readback(plan.exr);
  options.output.float_targets = false;  // no AOVs here: the composite writes only what is copied
  options.stop = &g_interrupted;
  const std::size_t encoders = run::default_encoder_threads();
  run::TaskQueue writer(encoders, 2 * encoders);  // a few frames queued at most: bounded memory
  const Status rendered = run::render_frames(renderer, plan.frames, options, [&](gpu::FinishedFrame& finished) -> Status {
    progress.frame_rendered(finished.frame, finished.statistics.proxies, finished.statistics.cpu_prepare_ms);
    return writer.push([&plan, &output, frame = finished.frame, ldr = std::move(finished.ldr),
                        hdr = std::move(finished.hdr)]() {
      return write_frame_files(plan.dir, frame, ldr, hdr, output.width, output.height, plan.exr);
    });
  });
  const Status written = writer.wait();
  return !rendered ? rendered : written;
}

// --aov: one frame at a time, since the intermediate buffers hold only the latest frame.
Status render_with_aovs(gpu::SceneRenderer& renderer, const RecordPlan& plan, RecordProgress& progress) {
  const scene::Scene& scene = renderer.scene();
  run::FrameLoopOptions options;
  options.output = gpu::FrameOutput::readback(plan.exr);
  options.in_flight = 1;
  options.stop = &g_interrupted;
  return run::render_frames(renderer, plan.frames, options, [&](gpu::FinishedFrame& finished) -> Status {
    const int frame = finished.frame;
    if (Status s = write_frame_files(plan.dir, frame, finished.ldr, finished.hdr, scene.output.width,
                                     scene.output.height, plan.exr);
        !s)
      return s;
    const auto camera = scene::evaluate_scene_camera(scene, finished.time_s);
    const image::ImageF final_frame = ldr_to_linear(finished.ldr, scene.output.width, scene.output.height);
    if (Status s = write_aovs(plan.dir, frame, renderer.frame(), final_frame, finished.spheres, camera); !s) return s;
    progress.frame_rendered(frame, finished.statistics.proxies, finished.statistics.cpu_prepare_ms);
    return {};
  });
}

// Encodes DIR/video.mp4 when every frame of the range is on disk. Missing ffmpeg only warns.
int encode_when_complete(const RecordPlan& plan, const run::FrameRange& range, double fps, bool rendered_any) {
  for (int frame = range.first; frame <= range.last; ++frame)
    if (!frame_done(plan.dir, frame, false, false)) {
      std::fprintf(stderr, "record: frame %d is missing; video.mp4 not encoded (run again to finish)\n", frame);
      return kExitOk;
    }
  std::error_code error;
  if (!rendered_any && std::filesystem::exists(video_file(plan.dir), error)) return kExitOk;  // already up to date
  const auto ffmpeg = find_program("ffmpeg");
  if (!ffmpeg) return fail_runtime("ffmpeg not found on PATH, so video.mp4 cannot be encoded (the frames are written; install ffmpeg "
                                   "and run again, or pass --no-mp4)");
  if (Status s = encode_video({*ffmpeg, plan.dir, range.first, range.last - range.first + 1, fps}); !s)
    return fail_runtime("video.mp4: " + s.message());
  if (!quiet()) std::fprintf(stderr, "record: wrote %s\n", video_file(plan.dir).c_str());
  return kExitOk;
}

int run_record(const RecordArgs& args) {
  Result<scene::Scene> loaded = open_scene(args.scene);
  if (!loaded) return fail_bad_input(loaded.message());
  scene::Scene scene = std::move(*loaded);
  if (args.width > 0) scene.output.width = args.width;
  if (args.height > 0) scene.output.height = args.height;

  std::optional<run::FrameRange> requested;
  if (!args.frames.empty()) {
    auto range = run::parse_frame_range(args.frames);
    if (!range) return fail_bad_input(range.message());
    requested = *range;
  }
  run::Shard shard;
  if (!args.shard.empty()) {
    auto parsed = run::parse_shard(args.shard);
    if (!parsed) return fail_bad_input(parsed.message());
    shard = *parsed;
  }
  auto share = run::plan_frames(scene.output, requested, shard);
  if (!share) return fail_bad_input(share.message());

  const bool want_mp4 = (args.mp4 || has_format(scene.output, scene::OutputFormat::mp4)) && !args.no_mp4;
  if (want_mp4 && args.shard.empty() && !find_program("ffmpeg"))  // before hours of rendering
    return fail_runtime("the scene asks for mp4 but ffmpeg is not on PATH; install ffmpeg, or pass --no-mp4");

  RecordPlan plan;
  plan.dir = args.output;
  plan.exr = args.exr || has_format(scene.output, scene::OutputFormat::exr);
  plan.aov = args.aov;
  std::error_code error;
  std::filesystem::create_directories(plan.dir, error);
  if (error) return fail_runtime(plan.dir.string() + ": cannot create the output folder: " + error.message());
  // The folder must belong to this scene and size before any of its files is trusted.
  auto scene_text = scene::to_json(scene);
  if (!scene_text) return fail_bad_input(scene_text.message());
  const RecordManifest manifest{proxies::content_hash(std::span(reinterpret_cast<const std::uint8_t*>(scene_text->data()),
                                                                scene_text->size())),
                                scene.output.width, scene.output.height, PROXYGI_VERSION};
  auto found = read_manifest(plan.dir);
  if (!found && !args.overwrite) return fail_bad_input(found.message() + " (use another folder or --overwrite)");
  if (!args.overwrite) {
    if (found && *found) {
      if (const std::string why = manifest_mismatch(**found, manifest); !why.empty())
        return fail_bad_input(plan.dir.string() + ": " + why + "; record into another folder, or pass --overwrite to replace its frames");
    } else if (has_frame_files(plan.dir)) {
      return fail_bad_input(plan.dir.string() + " holds frames but no record.json, so they may belong to another scene; record into "
                            "another folder, or pass --overwrite to replace them");
    }
  }
  if (args.overwrite || !found || !*found || found->value().version != manifest.version)
    if (Status s = write_manifest(plan.dir, manifest); !s) return fail_runtime(s.message());
  int stale = remove_stale_temporaries(plan.dir);
  if (plan.aov) stale += remove_stale_temporaries(plan.dir / "aov");
  if (stale > 0 && !quiet()) std::fprintf(stderr, "record: removed %d temporary file%s left by an interrupted run\n", stale, stale > 1 ? "s" : "");
  for (int frame : *share) {
    if (!args.overwrite && frame_done(plan.dir, frame, plan.exr, plan.aov, args.verify)) ++plan.skipped;
    else plan.frames.push_back(frame);
  }

  // --quiet: no progress, no summary, no info lines; warnings and errors still print.
  std::FILE* progress_stream = stderr;
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> null_stream(nullptr, &std::fclose);
  if (quiet()) {
    null_stream.reset(std::fopen("/dev/null", "w"));
    if (null_stream) progress_stream = null_stream.get();
  }
  std::signal(SIGINT, on_interrupt);
  std::signal(SIGTERM, on_interrupt);
  std::optional<RecordProgress> progress;
  if (plan.frames.empty()) {
    progress.emplace(0, plan.skipped, progress_stream);  // resume of a finished run: no device needed
  } else {
    for (const scene::Character& character : scene.characters)
      if (scene::is_builtin_mannequin(character.model) && !std::filesystem::exists(assets_dir() / "mannequin.glb", error))
        return fail_runtime((assets_dir() / "mannequin.glb").string() +
                            " is missing: create it with `proxygi mannequin -o <assets>/mannequin.glb` or point "
                            "$PROXYGI_ASSETS at a folder holding it");
    // The world first: a missing or malformed model, clip or rig is bad input (exit 2), named by
    // the scene and field, before any device is opened.
    auto world = world::World::load(scene, {.assets_dir = assets_dir(), .write_rig_cache = true, .refit = args.refit});
    if (!world) return fail_bad_input((args.scene.scene.empty() ? std::string("default") : args.scene.scene) + ": " + world.message());
    auto context = gpu::Context::create({.device_request = args.device});
    if (!context) return fail_runtime(context.message());
    auto renderer = gpu::SceneRenderer::create(**context, std::shared_ptr<const world::World>(std::move(*world)), scene.render,
                                               std::uint32_t(scene.output.width), std::uint32_t(scene.output.height));
    if (!renderer) return fail_runtime(renderer.message());
    if (!quiet() && (*renderer)->static_transfer().level != settings::StaticTransfer::l0)
      std::fprintf(stderr, "record: %s\n", gpu::describe((*renderer)->static_transfer()).c_str());
    // render.quality: the settings chosen for the first frame's shot, and why.
    if (const quality::QualityChoice& choice = (*renderer)->quality(); !quiet() && choice.automatic) {
      std::fprintf(stderr, "record: %s (shadow_eta resolves to %.3g)\n", quality::describe(choice).c_str(),
                   (*renderer)->frame().shadow_eta());
      for (const std::string& reason : choice.reasons) std::fprintf(stderr, "record:   %s\n", reason.c_str());
    }
    progress.emplace(int(plan.frames.size()), plan.skipped, progress_stream);
    const Status rendered = plan.aov ? render_with_aovs(**renderer, plan, *progress)
                                     : render_in_flight(**renderer, plan, *progress);
    if (!rendered) {
      progress->finish();
      return fail_runtime(rendered.message());
    }
  }
  progress->finish();
  if (g_interrupted) return fail_runtime("interrupted; finished frames are kept, run the same command to resume");

  if (!want_mp4) return kExitOk;
  if (!args.shard.empty()) {
    if (!quiet()) std::fprintf(stderr, "record: shards do not encode video; when all shards are done, run again without --shard\n");
    return kExitOk;
  }
  return encode_when_complete(plan, requested.value_or(run::scene_frame_range(scene.output)), scene.output.fps,
                              !plan.frames.empty());
}

}  // namespace

void add_record_command(CLI::App& app, CommandRunner& runner) {
  auto args = std::make_shared<RecordArgs>();
  CLI::App* command = app.add_subcommand(
      "record",
      "Render a scene headless to DIR/frame_%05d.png (+ .exr, + video.mp4). Resumable: frames whose files "
      "exist are skipped; files are written atomically.");
  add_scene_options(*command, args->scene, true);
  command->add_option("-o,--output", args->output, "Output folder (created if missing)")->required();
  command->add_option("--frames", args->frames,
                      "A:B, first and last frame (inclusive) within the scene's output range (default: all)");
  command->add_option("--shard", args->shard,
                      "I/N: render only frames f of the range with (f - A) mod N == I (0-based I < N), A the "
                      "range's first frame; N processes fill one folder with the files of a single run");
  command->add_flag("--exr", args->exr, "Also write linear float DIR/frame_%05d.exr");
  auto* mp4 = command->add_flag("--mp4", args->mp4,
                                "Encode DIR/video.mp4 with ffmpeg once every frame exists (also when the scene's "
                                "formats include mp4); shards never encode");
  command->add_flag("--no-mp4", args->no_mp4, "Do not encode video even if the scene asks for it")->excludes(mp4);
  command->add_flag("--aov", args->aov,
                    "Render one frame at a time and write DIR/aov/frame_%05d_{receivers,occlusion_dc,direct,"
                    "indirect,upsampled}.exr and _proxies.png");
  command->add_option("--width", args->width, "Override the scene's output width")->check(CLI::Range(settings::kMinImageSize, settings::kMaxImageSize));
  command->add_option("--height", args->height, "Override the scene's output height")->check(CLI::Range(settings::kMinImageSize, settings::kMaxImageSize));
  command->add_flag("--overwrite", args->overwrite,
                    "Render every frame again, also into a folder recorded from another scene or size");
  command->add_flag("--refit", args->refit,
                    "Fit every proxy rig again and write it, also a rig file the scene names (else used as it is)");
  add_quiet_flag(*command);
  command->add_flag("--verify", args->verify, "Decode the frames already in the folder; render again those that do not decode");
  add_device_option(*command, args->device);
  command->callback([args, &runner] { runner = [args] { return run_record(*args); }; });
}

}  // namespace proxygi::app
