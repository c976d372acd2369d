#pragma once
// Viewer: the state of one run of the viewer application (viewer_app.h is its entry point).
// Split over viewer.cpp (set-up, the loop, events, loading), viewer_frame.cpp (one frame:
// world state, adaptive resolution, UI build, the previous frame's present, render, UI pass,
// screenshot) and viewer_files.cpp
// (scene saving, screenshots, the state file for tests).
#include <chrono>
#include <deque>
#include <future>
#include <memory>
#include <optional>
#include <string>

#include "gpu/context.h"
#include "gpu/resources.h"
#include "gpu/scene_renderer.h"
#include "run/frame_loop.h"
#include "view/measure_blocks.h"
#include "view/scene_loader.h"
#include "view/swapchain.h"
#include "view/ui_pass.h"
#include "view/viewer_app.h"
#include "view/viewer_core.h"
#include "view/viewer_ui.h"
#include "view/window.h"

struct ImGuiContext;

namespace proxygi::view {

// Ring slots of the scene renderer: one frame prepared while the previous one renders.
inline constexpr std::size_t kFramesInFlight = 2;

// Where a frame's wall time goes (the state file's "frame_parts_ms", for scripts/viewer-measure.sh):
// the loop's steady-clock time between laps, summed per part over the frames the renderer drew.
enum class FramePart { events, acquire, render, pass_timing, ui_build, ui_submit, screenshot, present, count };
const char* frame_part_name(FramePart part);
struct FrameParts {
  void start() { last = std::chrono::steady_clock::now(); }
  void lap(FramePart part) {
    const auto now = std::chrono::steady_clock::now();
    pending[std::size_t(part)] += std::chrono::duration<double, std::milli>(now - last).count();
    last = now;
  }
  void commit(bool counted);  // adds this frame's laps to the sums when counted, then clears them
  std::chrono::steady_clock::time_point last;
  double pending[std::size_t(FramePart::count)] = {};
  double sum_ms[std::size_t(FramePart::count)] = {};
  int frames = 0;
};

class Viewer {
 public:
  explicit Viewer(const ViewerOptions& options);
  ~Viewer();
  Status init();
  Status run();

 private:
  // viewer.cpp
  void dispatch(const Event& event);
  Status adopt(Result<LoadedScene> loaded);
  Status make_renderer();
  // viewer_frame.cpp
  Status frame();
  Status prepare_frame(std::uint32_t display_width, std::uint32_t display_height);
  Status requalify(std::uint32_t height);  // render.quality: a new choice when the camera moved
  // The frame into `target`, or read back as `bench frame` does (FrameEnd::readback: no target).
  Status render_into(const TargetImage& target, FrameEnd end);
  Status measured_frame(FrameEnd end);  // a measure-blocks frame that is not presented
  Status finish_oldest();  // waits for the oldest frame in flight
  Status finish_all();
  void show_pass_timings(const gpu::PassTimings& timings, const std::string& clock);  // the HUD's
  void evaluate_world();
  void adapt_resolution(double frame_ms);
  void build_ui(std::uint32_t width, std::uint32_t height);
  Status submit_ui(const TargetImage& target, VkSemaphore signal, VkImageLayout final_layout);
  Status present_pending();  // the swapchain image of the previous frame, if any
  HudInfo hud_info() const;
  // viewer_files.cpp
  Status save_scene(const std::string& path);
  Status write_screenshot(const std::vector<std::uint8_t>& rgba, std::uint32_t width, std::uint32_t height,
                          const std::string& path);
  Status write_state() const;

  ViewerOptions options_;
  std::unique_ptr<Window> window_;
  std::unique_ptr<gpu::Context> context_;
  std::unique_ptr<Swapchain> swapchain_;
  bool swapchain_stale_ = false;
  struct PendingPresent {
    std::uint32_t index = 0;
    bool stale = false;  // acquired suboptimal: rebuild after presenting
  };
  std::optional<PendingPresent> pending_present_;  // drawn, presented at the next frame
  bool ui_with_ = false;  // build_ui → submit_ui
  UiDraw ui_how_ = UiDraw::direct;
  UiRequests ui_requests_;
  std::optional<gpu::Image> offscreen_;
  ImGuiContext* imgui_ = nullptr;
  std::unique_ptr<UiPass> ui_pass_;
  std::promise<void> rig_hold_;  // ViewerOptions::hold_rigs_frames (before loader_, which waits on it)
  SceneLoader loader_;

  std::string name_;  // what is shown
  std::shared_ptr<const world::World> world_;
  std::unique_ptr<gpu::SceneRenderer> renderer_;
  std::deque<gpu::FrameTicket> in_flight_;  // begun, not yet finished (oldest first)
  scene::Scene scene_;  // editable copy of the world's scene (clips, environment)
  std::optional<ViewerCore> core_;
  world::WorldState state_;
  settings::RenderSettings applied_settings_;
  // render.quality: the camera the renderer's choice was last made for (a new choice per shot).
  std::optional<scene::CameraState> quality_camera_;
  std::uint32_t internal_width_ = 0, internal_height_ = 0;
  std::uint32_t display_width_ = 0, display_height_ = 0;

  std::optional<ScriptPlayer> script_;
  double script_clock_s_ = 0.0;
  bool script_started_ = false;
  double step_s_ = 1.0 / 24.0;
  std::deque<ScreenshotEvent> screenshots_;  // one per frame, oldest first
  int screenshot_count_ = 0;
  bool quit_ = false;
  bool adaptive_ = true;
  double scale_ = 1.0;
  int adaptive_frames_ = 0;
  double adaptive_ms_ = 0.0;
  int frames_ = 0;           // frames the renderer drew
  int previews_ = 0;         // scenes shown without rigs while they were fitted
  int frames_without_proxies_ = 0;  // frames drawn with a preview world
  bool rig_hold_open_ = true;
  bool rendered_last_ = false;
  bool first_frame_logged_ = false;
  std::chrono::steady_clock::time_point last_frame_;
  double ui_dt_s_ = 0.0;  // wall time since the previous frame (ImGui's step)
  std::chrono::steady_clock::time_point last_pass_timing_;
  bool want_pass_timing_ = true;
  // A fenced time_passes found the device's timestamps plausible: later pass times come from
  // timestamps in the frames shown (FrameRequest::pass_timestamps), without a frame of their own.
  bool timestamps_trusted_ = false;
  int pass_timings_shown_ = 0, in_frame_pass_timings_ = 0;  // state file
  std::vector<PassTime> passes_;
  std::string pass_clock_;  // how passes_ were measured (HUD)
  FrameTimes times_;  // the HUD's: the last 128 frames
  SteadyTimes steady_times_{run::kWarmupFrames};  // the state file's: every frame after the warm-up
  std::optional<MeasureBlocks> blocks_;            // ViewerOptions::measure_block_frames
  std::optional<gpu::Image> measure_image_;        // the window's offscreen blocks draw here
  bool ui_suppressed_ = false;                     // this frame ends without the UI (measure blocks)
  FrameParts parts_;
  bool ui_input_ = false;
  glm::vec2 last_mouse_{-1e30f, -1e30f};  // ImGui's pointer at the previous frame  // an input event arrived this frame (the overlay shows it at once)
  DrawSignature overlay_signature_;  // of the overlay drawn last
  DrawSignature draw_signature_;     // scratch: this frame's
  double ui_clock_s_ = 0.0;           // sum of ImGui's steps (wall time; a script's fixed step)
  double overlay_drawn_at_s_ = 0.0;  // ui_clock_s_ when the overlay was drawn
  int overlay_draws_ = 0, overlay_reuses_ = 0, ui_direct_draws_ = 0;  // frames with the UI, by how
  int screenshots_reusing_ = 0;  // screenshots with the UI that blended an overlay drawn earlier
  std::string save_path_ = "viewer_scene.json";
  std::string open_path_;
};

}  // namespace proxygi::view
