#pragma once
// The viewer application: a window (GLFW + Vulkan swapchain) or an offscreen image, the viewer
// core (viewer_core.h), the scene renderer, Dear ImGui over the frame, and files opened in the
// background. One loop serves people, scripts and tests:
//
//   per frame: events (window, script) → core → settings applied in place (apply_settings) →
//   world evaluated at the core's time with its camera → UI built → (window) the previous
//   frame presented, an image acquired → frame rendered into the target image (at a lower
//   internal resolution when adaptive) → UI pass (a cached overlay, overlay_cache.h) → screenshot.
//
// Loading never blocks the loop: open_scene and world::World::load (import, rig fit or cache)
// run on a thread; the previous scene keeps playing, and a failure is shown in the window
// (the previous scene stays). Scripts freeze their clock while a load runs, so they are
// deterministic.
#include <chrono>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>

#include "base/result.h"
#include "view/scene_loader.h"
#include "view/script.h"

namespace proxygi::view {

// Writes RGBA8 sRGB bytes (row 0 on top) as a PNG; the application passes the recorder's writer.
using PngWriter = std::function<Status(const std::filesystem::path&, std::span<const std::uint8_t>, int, int)>;

struct ViewerOptions {
  std::string open;                  // what to open first (scene_open.h); empty: default
  std::filesystem::path assets_dir;  // the bundled assets
  std::string device;                // --device
  bool offscreen = false;            // render into an image, no window
  int width = 1280, height = 720;    // window / offscreen size
  bool vsync = true;                 // FIFO; false: mailbox or immediate
  bool validation = false;           // validation layer on; any message fails the run
  bool adaptive_resolution = true;   // lower internal resolution below min_fps
  double min_fps = 15.0;
  bool show_ui = true;
  // Blend a cached UI overlay, redrawn when the UI changes (overlay_cache.h); false: ImGui
  // rasterized onto every frame.
  bool ui_cache = true;
  bool play = false;                 // start playing
  // The HUD's pass times come from GPU timestamps in a frame shown, this often (seconds), once a
  // fenced timing found the device's timestamps plausible; else a fenced frame every 5 s.
  double pass_timing_period_s = 1.0;
  std::optional<Script> script;      // drive the viewer from a script (fixed time step)
  int max_frames = 0;                // stop after this many rendered frames (0: no limit)
  // Measurement (measure_blocks.h): blocks of this many frames cycle through window, offscreen
  // and readback endings; their block means go to the state file. 0: off.
  int measure_block_frames = 0;
  std::filesystem::path state_out;   // write the final viewer state here as JSON (tests)
  std::filesystem::path screenshot_dir = "screenshots";  // F12
  PngWriter write_png;
  std::chrono::steady_clock::time_point started = std::chrono::steady_clock::now();
  LoaderOptions loader;              // the preview while rigs are fitted (scene_loader.h)
  // Tests: the first open's rig step waits until this many frames were drawn without proxies
  // (a fit that is slow on demand); 0: no wait. Ignored with a script (it waits for the rigs).
  int hold_rigs_frames = 0;
  // Quit at the first frame drawn with proxies after the scene was shown without them.
  bool quit_when_rigged = false;
};

// Runs until quit (window closed, Esc, script end, max_frames, quit_when_rigged). Errors: no device, no window
// (without --offscreen), a failing first scene, validation messages with validation on.
Status run_viewer(const ViewerOptions& options);

}  // namespace proxygi::view
