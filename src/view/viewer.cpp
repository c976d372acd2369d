#include "view/viewer.h"

#include <cstdio>
#include <thread>

#include <imgui.h>

#include "base/log.h"

namespace proxygi::view {

Status run_viewer(const ViewerOptions& options) {
  Viewer viewer(options);
  if (Status s = viewer.init(); !s) return s;
  return viewer.run();
}

namespace {

LoaderOptions loader_options(const ViewerOptions& options, std::promise<void>& hold) {
  LoaderOptions loader = options.loader;
  if (options.hold_rigs_frames > 0) {
    loader.preview_after_s = 0.0;
    loader.rig_gate = hold.get_future().share();
  }
  return loader;
}

}  // namespace

Viewer::Viewer(const ViewerOptions& options)
    : options_(options), loader_(options.assets_dir, loader_options(options, rig_hold_)) {
  adaptive_ = options.adaptive_resolution && !options.script;  // scripts are exact: no adaptation
  if (options.script) script_.emplace(*options.script);
  rig_hold_open_ = options.hold_rigs_frames <= 0;
}

Viewer::~Viewer() {
  if (!rig_hold_open_) rig_hold_.set_value();  // the loader's worker may wait on it
  if (context_) vkDeviceWaitIdle(context_->device());
  if (renderer_) (void)finish_all();
  renderer_.reset();
  ui_pass_.reset();
  swapchain_.reset();
  offscreen_.reset();
  window_.reset();  // ImGui's GLFW backend goes with the window
  if (imgui_) ImGui::DestroyContext(imgui_);
}

Status Viewer::init() {
  gpu::ContextOptions context_options{.device_request = options_.device,
                                      .validation = options_.validation ? gpu::Validation::on
                                                                        : gpu::Validation::build_default};
  display_width_ = std::uint32_t(options_.width);
  display_height_ = std::uint32_t(options_.height);
  if (!options_.offscreen) {
    auto window = Window::create(options_.width, options_.height, "proxygi — " + (options_.open.empty() ? std::string("default") : options_.open));
    if (!window) return make_error(window.message() + " (use --offscreen without a display)");
    window_ = std::move(*window);
    context_options.instance_extensions = Window::required_instance_extensions();
    context_options.device_extensions = {VK_KHR_SWAPCHAIN_EXTENSION_NAME};
    context_options.create_surface = [this](VkInstance instance) { return window_->create_surface(instance); };
  }
  auto context = gpu::Context::create(context_options);
  if (!context) return context.error();
  context_ = std::move(*context);

  imgui_ = ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini in the working directory
  ImGui::StyleColorsDark();
  VkFormat format = VK_FORMAT_R8G8B8A8_UNORM;
  std::uint32_t image_count = 2;
  if (window_) {
    int width = 0, height = 0;
    window_->framebuffer_size(width, height);
    auto swapchain = Swapchain::create(*context_, std::uint32_t(std::max(width, 1)), std::uint32_t(std::max(height, 1)),
                                       options_.vsync);
    if (!swapchain) return swapchain.error();
    swapchain_ = std::move(*swapchain);
    format = swapchain_->format();
    image_count = swapchain_->image_count();
    window_->init_imgui();
  } else {
    auto image = gpu::Image::create(*context_, display_width_, display_height_, format,
                                    VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT |
                                        VK_IMAGE_USAGE_TRANSFER_SRC_BIT);
    if (!image) return image.error();
    offscreen_ = std::move(*image);
  }
  auto ui_pass = UiPass::create(*context_, format,
                                window_ ? VK_IMAGE_LAYOUT_PRESENT_SRC_KHR : VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                                image_count);
  if (!ui_pass) return ui_pass.error();
  ui_pass_ = std::move(*ui_pass);

  if (options_.measure_block_frames > 0) {
    if (options_.measure_block_frames <= MeasureBlocks::kWarmupFrames)
      return make_error("measure blocks need more than " + std::to_string(MeasureBlocks::kWarmupFrames) + " frames each");
    blocks_.emplace(options_.measure_block_frames, window_ != nullptr);
  }
  loader_.open(options_.open, nullptr);
  if (script_) {
    if (!rig_hold_open_) {  // a script waits for the rigs: no hold
      rig_hold_open_ = true;
      rig_hold_.set_value();
    }
    // Nothing to show until the scene is there (rigs included); a failing first scene is an error.
    if (Status s = adopt(*loader_.wait()); !s) return s;
  }
  last_frame_ = last_pass_timing_ = std::chrono::steady_clock::now();
  return {};
}

Status Viewer::make_renderer() {
  if (renderer_)
    if (Status s = finish_all(); !s) return s;
  in_flight_.clear();
  renderer_.reset();
  auto renderer = gpu::SceneRenderer::create(*context_, world_, core_->state().settings, internal_width_,
                                             internal_height_, std::uint32_t(kFramesInFlight));
  if (!renderer) return renderer.error();
  renderer_ = std::move(*renderer);
  applied_settings_ = core_->state().settings;
  quality_camera_.reset();  // a new renderer chose for its scene camera: choose again for the shown one
  return {};
}

// A finished load: the new world replaces the shown one, or its error is shown and the
// previous scene stays. Without a previous scene the error ends the run.
Status Viewer::adopt(Result<LoadedScene> loaded) {
  const bool keep = loaded && loaded->keep_state;
  if (!loaded) {
    log_info("view: " + loaded.message());
    if (!world_) return loaded.error();
    core_->state().message = loaded.message();
    return {};
  }
  std::shared_ptr<const world::World> previous = world_;
  world_ = loaded->world;
  scene_ = world_->scene();
  if (!core_) {
    core_.emplace(scene_);
    core_->state().playback.playing = options_.play;
  }
  else if (!keep) core_->reset_for_scene(scene_);
  if (internal_width_ == 0) internal_width_ = display_width_, internal_height_ = display_height_;
  if (Status s = make_renderer(); !s) {
    core_->state().message = loaded->name + ": " + s.message();
    world_ = previous;
    if (!world_) return s;
    scene_ = world_->scene();
    return make_renderer();
  }
  name_ = loaded->name.empty() ? "default" : loaded->name;
  if (!keep) core_->state().message.clear();
  if (window_) window_->set_title("proxygi — " + name_);
  log_info("view: showing " + name_ + (loaded->preview ? " (without proxies while its rigs are fitted)" : ""));
  if (loaded->preview) {
    ++previews_;
  } else if (previews_ > 0 && keep) {
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - options_.started).count();
    char line[64];
    std::snprintf(line, sizeof line, " on after %.2f s", seconds);
    log_info("view: proxies of " + name_ + line);
  }
  return {};
}

void Viewer::dispatch(const Event& event) {
  if (std::holds_alternative<QuitEvent>(event)) {
    quit_ = true;
  } else if (const auto* open = std::get_if<OpenFileEvent>(&event)) {
    loader_.open(open->path, world_ ? &world_->scene() : nullptr);
  } else if (const auto* shot = std::get_if<ScreenshotEvent>(&event)) {
    screenshots_.push_back(*shot);
  } else if (const auto* save = std::get_if<SaveSceneEvent>(&event)) {
    if (Status s = save_scene(save->path); !s) core_->state().message = s.message();
  } else if (const auto* move = std::get_if<MoveEvent>(&event)) {
    if (window_) window_->move(move->x, move->y);
  } else if (const auto* resize = std::get_if<ResizeEvent>(&event)) {
    if (window_) {
      window_->resize(resize->width, resize->height);
    } else if (resize->width > 0) {
      vkDeviceWaitIdle(context_->device());
      auto image = gpu::Image::create(*context_, std::uint32_t(resize->width), std::uint32_t(resize->height),
                                      VK_FORMAT_R8G8B8A8_UNORM,
                                      VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT |
                                          VK_IMAGE_USAGE_TRANSFER_SRC_BIT);
      if (!image) {
        core_->state().message = image.message();
        return;
      }
      ui_pass_->forget_framebuffers();
      offscreen_ = std::move(*image);
      display_width_ = std::uint32_t(resize->width), display_height_ = std::uint32_t(resize->height);
    }
  } else if (core_) {
    core_->handle(event);
  }
}

Status Viewer::run() {
  while (!quit_) {
    if (window_ && window_->should_close()) break;
    if (Status s = frame(); !s) return s;
    if (rendered_last_) ++frames_;
    if (options_.max_frames > 0 && frames_ >= options_.max_frames) break;
    if (script_ && script_->finished() && !loader_.busy() && screenshots_.empty()) break;
    if (options_.quit_when_rigged && rendered_last_ && previews_ > 0 && !loader_.busy() && world_->proxy_count() > 0) break;
  }
  if (swapchain_)
    if (Status s = present_pending(); !s) return s;
  if (context_) vkDeviceWaitIdle(context_->device());
  if (Status s = write_state(); !s) return s;
  if (options_.validation && context_->validation_message_count() > 0)
    return make_error(std::to_string(context_->validation_message_count()) + " validation messages (see stderr)");
  return {};
}

}  // namespace proxygi::view
