// proxygi view [SCENE.json | MODEL.glb | MODEL.gltf | mannequin | default | crowd] [--offscreen] [--script FILE.json]
//              [--width W --height H] [--no-vsync] [--no-adaptive] [--no-ui] [--no-ui-cache] [--play] [--validation]
//              [--max-frames N] [--state-out FILE.json] [--measure-blocks N] [--device NAME|INDEX]
// The interactive viewer (src/view): a window with the frame, its HUD and live settings, or an
// offscreen image driven by a script. Screenshots go through the recorder's PNG writer.
#include <chrono>
#include <memory>

#include "apps/commands.h"
#include "settings/limits.h"
#include "image/image.h"
#include "view/measure_blocks.h"
#include "view/viewer_app.h"

namespace proxygi::app {
namespace {

struct ViewArgs {
  std::string open;
  std::string script;
  bool offscreen = false;
  int width = 1280, height = 720;
  bool no_vsync = false, no_adaptive = false, no_ui = false, no_ui_cache = false, validation = false, play = false;
  int max_frames = 0;
  int measure_blocks = 0;
  std::string state_out;
  std::string device;
};

int run_view(const ViewArgs& args, std::chrono::steady_clock::time_point started) {
  view::ViewerOptions options;
  options.open = args.open;
  options.assets_dir = assets_dir();
  options.device = args.device;
  options.offscreen = args.offscreen;
  options.width = args.width;
  options.height = args.height;
  options.vsync = !args.no_vsync;
  options.validation = args.validation;
  options.adaptive_resolution = !args.no_adaptive;
  options.show_ui = !args.no_ui;
  options.ui_cache = !args.no_ui_cache;
  options.play = args.play;
  options.max_frames = args.max_frames;
  options.measure_block_frames = args.measure_blocks;
  options.state_out = args.state_out;
  options.write_png = image::write_png_rgba8;  // the recorder's writer: the bytes as they are
  options.started = started;
  if (!args.script.empty()) {
    auto script = view::load_script(args.script);
    if (!script) return fail_bad_input(script.message());
    options.script = std::move(*script);
  }
  if (args.offscreen && !options.script && options.max_frames == 0)
    return fail_bad_input("view --offscreen needs --script FILE.json or --max-frames N (nothing would end it)");
  if (Status s = view::run_viewer(options); !s) return fail_runtime(s.message());
  return kExitOk;
}

}  // namespace

void add_view_command(CLI::App& app, CommandRunner& runner) {
  auto args = std::make_shared<ViewArgs>();
  const auto started = std::chrono::steady_clock::now();
  CLI::App* command = app.add_subcommand(
      "view", "Interactive viewer: play, scrub and orbit a scene or model with live settings (F1: keys)");
  command->add_option("scene", args->open, "scene .json, model .glb/.gltf or 'mannequin' (on record's stage), 'default' or 'crowd' (default: default)");
  command->add_option("--script", args->script, "run time-stamped events from FILE.json on a fixed time step");
  command->add_flag("--offscreen", args->offscreen, "render into an image instead of a window (no display needed)");
  command->add_option("--width", args->width, "window / image width")->check(CLI::Range(settings::kMinImageSize, settings::kMaxImageSize));
  command->add_option("--height", args->height, "window / image height")->check(CLI::Range(settings::kMinImageSize, settings::kMaxImageSize));
  command->add_flag("--no-vsync", args->no_vsync, "present with mailbox or immediate instead of FIFO");
  command->add_flag("--no-adaptive", args->no_adaptive, "never lower the internal resolution");
  command->add_flag("--no-ui", args->no_ui, "hide the UI (as F10)");
  command->add_flag("--no-ui-cache", args->no_ui_cache, "rasterize the UI onto every frame instead of blending a cached overlay");
  command->add_flag("--play", args->play, "start playing (as Space)");
  command->add_flag("--validation", args->validation, "Vulkan validation on; any message fails the run");
  command->add_option("--max-frames", args->max_frames, "quit after N frames")->check(CLI::NonNegativeNumber);
  command->add_option("--state-out", args->state_out, "write the final viewer state as JSON (tests)");
  command->add_option("--measure-blocks", args->measure_blocks,
                      "measurement: blocks of N frames cycle through window (UI, present), window without UI, "
                      "offscreen (no UI) and readback (as bench frame) endings; block means in the --state-out file")
      ->check(CLI::Range(view::MeasureBlocks::kWarmupFrames + 1, 100000));
  add_quiet_flag(*command);
  add_device_option(*command, args->device);
  command->callback([args, started, &runner] { runner = [args, started] { return run_view(*args, started); }; });
}

}  // namespace proxygi::app
