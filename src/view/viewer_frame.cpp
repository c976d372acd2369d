// One frame of the viewer: events, clock, world state, settings in place, adaptive internal
// resolution, the frame into the target image, the UI over it, screenshot, present.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <thread>

#include <imgui.h>
#include <backends/imgui_impl_vulkan.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "base/log.h"
#include "shaders/shared/layouts.h"
#include "view/viewer.h"

namespace proxygi::view {
namespace {

// The viewer's views are the composite's debug views, in the same order.
static_assert(int(View::receivers) == int(gpu_layout::kDebugViewReceivers) && int(View::direct) == int(gpu_layout::kDebugViewDirect) &&
              int(View::occlusion) == int(gpu_layout::kDebugViewOcclusion) && int(View::heat_map) == int(gpu_layout::kDebugViewHeatMap) &&
              kViewCount == int(gpu_layout::kDebugViewCount));

constexpr double kScales[] = {1.0, 0.75, 0.5, 0.375, 0.25};  // internal / display resolution
constexpr int kAdaptWindow = 16;                              // frames measured per decision
// The HUD's pass times without trusted timestamps: a fenced frame of its own this often.
constexpr double kPassTimingPeriodS = 5.0;

const char* present_name(VkPresentModeKHR mode) {
  switch (mode) {
    case VK_PRESENT_MODE_FIFO_KHR: return "FIFO (vsync)";
    case VK_PRESENT_MODE_MAILBOX_KHR: return "mailbox";
    case VK_PRESENT_MODE_IMMEDIATE_KHR: return "immediate";
    default: return "other";
  }
}

}  // namespace

const char* frame_part_name(FramePart part) {
  switch (part) {
    case FramePart::events: return "events";
    case FramePart::acquire: return "acquire";
    case FramePart::render: return "render";
    case FramePart::pass_timing: return "pass_timing";
    case FramePart::ui_build: return "ui_build";
    case FramePart::ui_submit: return "ui_submit";
    case FramePart::screenshot: return "screenshot";
    case FramePart::present: return "present";
    case FramePart::count: break;
  }
  return "?";
}

void FrameParts::commit(bool counted) {
  for (std::size_t p = 0; p < std::size_t(FramePart::count); ++p) {
    if (counted) sum_ms[p] += pending[p];
    pending[p] = 0.0;
  }
  frames += counted ? 1 : 0;
}

// Poses the world at the core's time; the scene camera goes to the core (for the free camera's
// start), and the free camera replaces it when on. The renderer draws this state as it is.
void Viewer::evaluate_world() {
  if (Status s = world_->evaluate(core_->state().playback.time_s, std::nullopt, state_); !s) {
    core_->state().message = s.message();
    return;
  }
  core_->set_scene_camera(state_.camera);
  if (auto free = core_->camera_override()) state_.camera = *free;
  glm::vec3 low(1e30f), high(-1e30f);
  for (const render::Sphere& sphere : state_.spheres)
    low = glm::min(low, sphere.center - sphere.radius), high = glm::max(high, sphere.center + sphere.radius);
  for (const auto& instance : state_.instances)
    for (const glm::mat4& node : instance.pose.world) low = glm::min(low, glm::vec3(node[3])), high = glm::max(high, glm::vec3(node[3]));
  if (low.x <= high.x) core_->set_bounds(0.5f * (low + high), std::max(0.5f * glm::length(high - low), 0.05f));
}

void Viewer::adapt_resolution(double frame_ms) {
  if (!adaptive_) {
    scale_ = 1.0;
    return;
  }
  adaptive_ms_ += frame_ms;
  if (++adaptive_frames_ < kAdaptWindow) return;
  const double mean = adaptive_ms_ / adaptive_frames_, budget = 1000.0 / options_.min_fps;
  adaptive_frames_ = 0, adaptive_ms_ = 0.0;
  const auto* current = std::find(std::begin(kScales), std::end(kScales), scale_);
  if (mean > budget && current + 1 != std::end(kScales)) scale_ = *(current + 1);
  // Up only with room to spare: the next scale up costs about (s'/s)² more.
  else if (mean < 0.45 * budget && current != std::begin(kScales)) scale_ = *(current - 1);
}

// The CPU half before anything is submitted: settings and internal size in place, the world
// evaluated (the UI's overlays draw this state, and the renderer renders it).
Status Viewer::prepare_frame(std::uint32_t display_width, std::uint32_t display_height) {
  if (!renderer_) return {};
  const std::uint32_t width = std::max(16u, std::uint32_t(std::lround(display_width * scale_)));
  const std::uint32_t height = std::max(16u, std::uint32_t(std::lround(display_height * scale_)));
  if (core_->state().settings != applied_settings_ || width != internal_width_ || height != internal_height_) {
    if (Status s = finish_all(); !s) return s;
    if (Status s = renderer_->apply_settings(core_->state().settings, width, height); !s) {
      core_->state().message = "settings: " + s.message();
      core_->state().settings = applied_settings_;
    } else {
      applied_settings_ = core_->state().settings;
      internal_width_ = width, internal_height_ = height;
    }
  }
  evaluate_world();
  return requalify(height);
}

// render.quality: a new choice when the camera moved since the last one (the shot changed); the
// renderer rebuilds only when the chosen settings differ.
Status Viewer::requalify(std::uint32_t height) {
  const settings::RenderSettings& requested = core_->state().settings;
  if (requested.quality == settings::kQualityManual) {
    quality_camera_.reset();
    return {};
  }
  const scene::CameraState& camera = state_.camera;
  if (quality_camera_ && quality_camera_->eye == camera.eye && quality_camera_->target == camera.target &&
      quality_camera_->fov_y_degrees == camera.fov_y_degrees)
    return {};
  auto choice = renderer_->choose_quality(requested, state_.time_s, camera, height);
  if (!choice) {
    core_->state().message = "quality: " + choice.message();
    return {};
  }
  if (choice->settings != renderer_->frame().settings())
    if (Status s = finish_all(); !s) return s;
  if (Status s = renderer_->apply_choice(*choice, state_.time_s, camera, internal_width_, internal_height_); !s)
    core_->state().message = "quality: " + s.message();
  quality_camera_ = camera;
  return {};
}

Status Viewer::render_into(const TargetImage& target, FrameEnd end) {
  if (!renderer_) return end == FrameEnd::readback ? Status{} : clear_target(*context_, target);
  gpu::FrameRequest request;
  request.state = &state_;
  request.frame = core_->state().playback.frame();
  request.debug_view = std::uint32_t(core_->state().view);
  request.output = end == FrameEnd::readback
                       ? gpu::FrameOutput::readback(true)  // as run::time_pipelined_frames
                       : gpu::FrameOutput::into({target.image, target.format, target.width, target.height,
                                                 VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL});
  request.output.float_targets = false;  // the viewer shows the 8-bit frame only
  const bool hud = ui_with_ && core_->state().toggles.hud && !script_;
  const auto since_timing = std::chrono::steady_clock::now() - last_pass_timing_;
  if (hud && timestamps_trusted_ && (want_pass_timing_ || since_timing >= std::chrono::duration<double>(options_.pass_timing_period_s))) {
    want_pass_timing_ = false;
    last_pass_timing_ = std::chrono::steady_clock::now();
    request.pass_timestamps = true;  // read in finish_oldest, no wait of its own
  }
  // Frames in flight: the next frame is prepared on the CPU while the device still renders the
  // previous one; only when every ring slot is busy does the loop wait for the oldest.
  while (in_flight_.size() >= kFramesInFlight)
    if (Status s = finish_oldest(); !s) return s;
  auto ticket = renderer_->begin(request);
  if (!ticket) return ticket.error();
  in_flight_.push_back(*ticket);
  if (!first_frame_logged_) {
    if (Status s = finish_all(); !s) return s;  // measured to the frame's completion
    first_frame_logged_ = true;
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - options_.started).count();
    char line[64];
    std::snprintf(line, sizeof line, " after %.2f s", seconds);
    log_info("view: first frame of " + name_ + line +
             (world_->proxy_count() == 0 && loader_.busy() ? " (without proxies: rigs are being fitted)" : ""));
  }
  rendered_last_ = true;
  if (world_->proxy_count() == 0 && loader_.busy() && ++frames_without_proxies_ >= options_.hold_rigs_frames &&
      !rig_hold_open_) {
    rig_hold_open_ = true;
    rig_hold_.set_value();
  }
  // Until a fenced timing has shown the device's timestamps plausible (and after they were
  // refused once), the HUD times a frame of its own, fenced.
  if (hud && !timestamps_trusted_ &&
      (want_pass_timing_ || std::chrono::steady_clock::now() - last_pass_timing_ > std::chrono::duration<double>(kPassTimingPeriodS))) {
    want_pass_timing_ = false;
    last_pass_timing_ = std::chrono::steady_clock::now();
    parts_.lap(FramePart::render);
    if (Status s = finish_all(); !s) return s;  // pass timing needs an idle ring
    if (auto timings = renderer_->time_passes(core_->state().playback.frame(), gpu::PassClock::timestamps_if_valid)) {
      char label[256];
      if (timings->timestamps)
        std::snprintf(label, sizeof label, "GPU timestamps, one fenced submit (%.2f ms)", timings->frame_fenced_ms);
      else
        std::snprintf(label, sizeof label, "fenced CPU timings, one submit each (%s)", timings->note.c_str());
      show_pass_timings(*timings, label);
      timestamps_trusted_ = timings->timestamps;
    }
    parts_.lap(FramePart::pass_timing);
  }
  return {};
}

void Viewer::show_pass_timings(const gpu::PassTimings& timings, const std::string& clock) {
  passes_.clear();
  pass_clock_ = clock;
  passes_.push_back({"prepare (CPU)", timings.cpu_prepare_ms});
  for (std::size_t p = 0; p < std::size_t(gpu::FramePass::count); ++p)
    if (timings.milliseconds[p] > 0.0) passes_.push_back({gpu::frame_pass_name(gpu::FramePass(p)), timings.milliseconds[p]});
  ++pass_timings_shown_;
}

Status Viewer::finish_oldest() {
  const gpu::FrameTicket ticket = in_flight_.front();
  in_flight_.pop_front();
  auto finished = renderer_->finish(ticket);
  if (!finished) return finished.error();
  if (finished->passes) {
    if (finished->passes->timestamps) {
      show_pass_timings(*finished->passes, "GPU timestamps in a frame shown");
      ++in_frame_pass_timings_;
    } else {
      timestamps_trusted_ = false;  // back to fenced timings, which say why
      want_pass_timing_ = true;
    }
  }
  return {};
}

Status Viewer::finish_all() {
  while (!in_flight_.empty())
    if (Status s = finish_oldest(); !s) return s;
  return {};
}

HudInfo Viewer::hud_info() const {
  HudInfo hud;
  hud.device = context_->report().name;
  hud.driver = context_->report().driver;
  hud.display_width = display_width_, hud.display_height = display_height_;
  hud.internal_width = internal_width_, hud.internal_height = internal_height_;
  hud.present = swapchain_ ? present_name(swapchain_->present_mode()) : "offscreen";
  hud.swapchain_recreations = swapchain_ ? swapchain_->recreations() : 0;
  hud.passes = passes_;
  hud.pass_clock = pass_clock_;
  hud.loading = loader_.progress();
  if (renderer_) {
    hud.proxies = world_->proxy_count();
    hud.receivers = renderer_->config().receiver_count();
    hud.shadow_eta = renderer_->frame().shadow_eta();
    if (renderer_->quality().automatic) {
      hud.quality = quality::describe(renderer_->quality());
      hud.quality_reasons = renderer_->quality().reasons;
    }
    for (const auto& model : world_->models())
      for (const auto& mesh : model->character.meshes)
        for (const auto& primitive : mesh.primitives) hud.triangles += primitive.indices.size() / 3;
  }
  hud.title = name_;
  return hud;
}

// This frame's UI (ImGui's draw lists for a target of this size) and how it reaches the frame.
void Viewer::build_ui(std::uint32_t width, std::uint32_t height) {
  const bool with_ui = options_.show_ui && core_ && core_->state().toggles.ui && !ui_suppressed_ &&
                       !(!screenshots_.empty() && !screenshots_.front().with_ui);
  ImGuiIO& io = ImGui::GetIO();
  if (window_) {
    window_->new_imgui_frame(width, height, ui_dt_s_);
  } else {
    io.DisplaySize = {float(width), float(height)};
    io.DeltaTime = float(step_s_);
  }
  ImGui_ImplVulkan_NewFrame();
  ImGui::NewFrame();
  // Pointer moves and held buttons are input for the overlay too (hover highlights, drags).
  bool pointer = io.MousePos.x != last_mouse_.x || io.MousePos.y != last_mouse_.y || io.MouseWheel != 0.0f ||
                 io.MouseWheelH != 0.0f || io.InputQueueCharacters.Size > 0;
  for (bool down : io.MouseDown) pointer = pointer || down;
  last_mouse_ = {io.MousePos.x, io.MousePos.y};
  ui_input_ = ui_input_ || pointer;
  UiRequests requests;
  if (with_ui) {
    const HudInfo hud = hud_info();
    UiContext ui{*core_, hud, times_, world_.get(), renderer_ ? &state_ : nullptr, &scene_, &adaptive_, &save_path_, &open_path_};
    requests = draw_ui(ui);
  }
  ImGui::Render();
  UiDraw how = UiDraw::direct;
  ui_clock_s_ += double(io.DeltaTime);
  if (with_ui && options_.ui_cache) {
    draw_signature(*ImGui::GetDrawData(), ImGui::GetBackgroundDrawList(), draw_signature_);
    OverlayChange change;
    change.cached = ui_pass_->overlay_cached(width, height);
    change.exact = !screenshots_.empty();
    change.scene_changed = draw_signature_.scene != overlay_signature_.scene;
    change.panels_changed = draw_signature_.panels != overlay_signature_.panels;
    change.input = ui_input_;
    change.since_draw_s = ui_clock_s_ - overlay_drawn_at_s_;
    if (redraw_due(change)) {
      how = UiDraw::redraw_overlay;
      std::swap(overlay_signature_, draw_signature_);
      overlay_drawn_at_s_ = ui_clock_s_;
      ++overlay_draws_;
    } else {
      how = UiDraw::reuse_overlay;
      ++overlay_reuses_;
      screenshots_reusing_ += change.exact ? 1 : 0;
    }
  } else if (with_ui) {
    ++ui_direct_draws_;
  }
  ui_with_ = with_ui, ui_how_ = how, ui_requests_ = requests;
  parts_.lap(FramePart::ui_build);
}

// The UI built by build_ui over the frame in `target`, then the screenshot when one is due.
Status Viewer::submit_ui(const TargetImage& target, VkSemaphore signal, VkImageLayout final_layout) {
  const UiRequests requests = ui_requests_;
  if (Status s = ui_pass_->submit(target, ui_with_ ? ImGui::GetDrawData() : nullptr, ui_how_, signal); !s) return s;
  ui_input_ = false;
  parts_.lap(FramePart::ui_submit);
  if (!screenshots_.empty()) {
    if (Status s = ui_pass_->wait(); !s) return s;
    auto rgba = read_target(*context_, target, final_layout);
    if (!rgba) return rgba.error();
    if (Status s = write_screenshot(*rgba, target.width, target.height, screenshots_.front().path); !s)
      core_->state().message = s.message();
    screenshots_.pop_front();
    parts_.lap(FramePart::screenshot);
  }
  if (requests.screenshot) screenshots_.push_back(ScreenshotEvent{"", true});
  if (requests.time_passes) want_pass_timing_ = true;
  if (requests.open) loader_.open(*requests.open, world_ ? &world_->scene() : nullptr);
  if (requests.save)
    if (Status s = save_scene(*requests.save); !s) core_->state().message = s.message();
  if (requests.reload) loader_.load(scene_, name_);
  return {};
}

Status Viewer::frame() {
  const auto now = std::chrono::steady_clock::now();
  const double wall_dt = std::min(std::chrono::duration<double>(now - last_frame_).count(), 0.25);
  const double frame_ms = std::chrono::duration<double, std::milli>(now - last_frame_).count();
  last_frame_ = now;
  ui_dt_s_ = frame_ms / 1000.0;
  // Only frames the renderer drew count (not the placeholder frames while the first scene loads).
  if (rendered_last_) {
    times_.add(frame_ms), steady_times_.add(frame_ms), adapt_resolution(frame_ms);
    if (blocks_) blocks_->add(frame_ms);
  }
  parts_.commit(rendered_last_);
  parts_.start();
  rendered_last_ = false;

  std::vector<Event> events = window_ ? window_->poll() : std::vector<Event>{};
  if (auto loaded = loader_.poll())
    if (Status s = adopt(std::move(*loaded)); !s) return s;
  if (core_)
    step_s_ = script_ && script_->script().step_s ? *script_->script().step_s : 1.0 / core_->state().playback.fps;
  if (script_) {
    // The script's clock stands still while a scene loads. Frame k shows script time k·step,
    // after the events due by then: the clock advances first, then its events apply.
    if (loader_.busy()) {
      for (const Event& event : events) dispatch(event);
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
      return {};
    }
    if (!screenshots_.empty() || script_->has_due(script_clock_s_)) {
      // A screenshot takes its frame, and the events after it at the same time apply next.
    } else if (script_started_) {
      core_->advance(step_s_);
      script_clock_s_ += step_s_;
    }
    script_started_ = true;
    if (screenshots_.empty())
      for (Event& event : script_->due(script_clock_s_)) events.push_back(std::move(event));
  } else if (core_) {
    core_->advance(wall_dt);
  }
  ui_input_ = ui_input_ || !events.empty();  // kept until a frame draws the UI
  for (const Event& event : events) dispatch(event);
  if (core_)
    for (const Event& event : core_->take_requests()) dispatch(event);
  parts_.lap(FramePart::events);

  const FrameEnd end = blocks_ ? blocks_->next() : window_ ? FrameEnd::window : FrameEnd::offscreen;
  ui_suppressed_ = blocks_ && end != FrameEnd::window;
  if (end != FrameEnd::window && end != FrameEnd::window_no_ui) return measured_frame(end);

  int width = 0, height = 0;
  window_->framebuffer_size(width, height);
  if (width == 0 || height == 0) {  // minimized: no swapchain images to draw into
    if (Status s = present_pending(); !s) return s;
    glfwWaitEventsTimeout(0.02);
    return {};
  }
  if (swapchain_stale_ || std::uint32_t(width) != swapchain_->width() || std::uint32_t(height) != swapchain_->height()) {
    if (Status s = present_pending(); !s) return s;
    ui_pass_->forget_framebuffers();
    if (Status s = swapchain_->recreate(std::uint32_t(width), std::uint32_t(height)); !s) return s;
    swapchain_stale_ = false;
  }
  display_width_ = swapchain_->width(), display_height_ = swapchain_->height();
  // This frame's image is asked for now and the previous frame presented only after this
  // frame's CPU work: on a software swapchain vkQueuePresentKHR waits for the device to finish
  // that frame, so the work here overlaps it. Nothing of this frame is submitted yet (the
  // present's own submission would wait for it).
  auto started = swapchain_->start_acquire();
  if (!started) return started.error();
  if (!*started) {  // out of date: rebuild next frame
    if (Status s = present_pending(); !s) return s;
    swapchain_stale_ = true;
    return {};
  }
  parts_.lap(FramePart::acquire);
  if (Status s = prepare_frame(display_width_, display_height_); !s) return s;
  parts_.lap(FramePart::render);
  build_ui(display_width_, display_height_);
  if (Status s = present_pending(); !s) return s;
  if (swapchain_stale_) return {};  // rebuilt next frame
  auto acquired = swapchain_->acquire();
  if (!acquired) return acquired.error();
  if (!*acquired) {  // out of date: rebuild next frame
    swapchain_stale_ = true;
    return {};
  }
  const std::uint32_t index = (*acquired)->index;
  const TargetImage& target = swapchain_->image(index);
  parts_.lap(FramePart::acquire);
  if (Status s = render_into(target, FrameEnd::window); !s) return s;
  parts_.lap(FramePart::render);
  if (Status s = submit_ui(target, swapchain_->render_done(index), VK_IMAGE_LAYOUT_PRESENT_SRC_KHR); !s) return s;
  pending_present_ = PendingPresent{index, (*acquired)->stale};
  return {};
}

// A frame that is not presented: the offscreen presenter's (or, with measure blocks in a window,
// an image of the swapchain's size and format), or read back as `bench frame` does (no UI).
Status Viewer::measured_frame(FrameEnd end) {
  std::uint32_t width = display_width_, height = display_height_;
  if (window_) {
    if (Status s = present_pending(); !s) return s;  // the window block's last frame
    int w = 0, h = 0;
    window_->framebuffer_size(w, h);
    if (w == 0 || h == 0) return {};
    width = std::uint32_t(w), height = std::uint32_t(h);
  }
  const gpu::Image* image = window_ ? nullptr : &*offscreen_;
  if (window_ && end == FrameEnd::offscreen) {
    if (!measure_image_ || measure_image_->width() != width || measure_image_->height() != height) {
      if (Status s = finish_all(); !s) return s;
      if (Status s = ui_pass_->wait(); !s) return s;
      auto made = gpu::Image::create(*context_, width, height, swapchain_->format(),
                                     VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT |
                                         VK_IMAGE_USAGE_TRANSFER_SRC_BIT);
      if (!made) return made.error();
      ui_pass_->forget_framebuffers();
      measure_image_ = std::move(*made);
    }
    image = &*measure_image_;
  }
  const TargetImage target = image ? TargetImage{image->handle(), image->view(), image->format(), image->width(), image->height()}
                                   : TargetImage{VK_NULL_HANDLE, VK_NULL_HANDLE, VK_FORMAT_UNDEFINED, width, height};
  if (Status s = prepare_frame(target.width, target.height); !s) return s;
  parts_.lap(FramePart::render);
  if (end == FrameEnd::readback) {
    ui_with_ = false;
    if (Status s = render_into(target, end); !s) return s;
    parts_.lap(FramePart::render);
    return {};
  }
  build_ui(target.width, target.height);
  if (Status s = render_into(target, end); !s) return s;
  parts_.lap(FramePart::render);
  // The window's UI pass ends in the swapchain's layout, also on the measure image.
  return submit_ui(target, VK_NULL_HANDLE, window_ ? VK_IMAGE_LAYOUT_PRESENT_SRC_KHR : VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);
}

Status Viewer::present_pending() {
  if (!pending_present_) return {};
  const PendingPresent pending = *pending_present_;
  pending_present_.reset();
  auto presented = swapchain_->present(pending.index, swapchain_->render_done(pending.index));
  if (!presented) return presented.error();
  parts_.lap(FramePart::present);
  if (!*presented || pending.stale) swapchain_stale_ = true;
  return {};
}

}  // namespace proxygi::view
