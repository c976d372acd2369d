// What the viewer writes: scene files of what is on screen (for `record` and `regress`),
// screenshots through the application's PNG writer, and the state file tests read.
#include <cstdio>
#include <fstream>

#include <nlohmann/json.hpp>

#include "scene/scene_write.h"
#include "base/log.h"
#include "settings/fields.h"
#include "view/viewer.h"

namespace proxygi::view {
namespace {

// Paths written relative to the shown scene's folder, made absolute so the saved file opens
// from wherever it is written.
std::string absolute_path(const scene::Scene& scene, const std::string& path) {
  if (path.empty() || scene::is_builtin_mannequin(path)) return path;
  return std::filesystem::absolute(scene::resolve_scene_path(scene, path)).lexically_normal().string();
}

}  // namespace

Status Viewer::save_scene(const std::string& path) {
  if (!world_ || !core_) return make_error("save scene: nothing is shown yet");
  scene::Scene out = scene_;
  for (scene::Character& character : out.characters) {
    character.model = absolute_path(scene_, character.model);
    if (character.proxies) character.proxies = absolute_path(scene_, *character.proxies);
  }
  for (scene::StaticMesh& mesh : out.static_meshes) mesh.model = absolute_path(scene_, mesh.model);
  if (out.environment.type == scene::Environment::Type::map)
    out.environment.map_path = absolute_path(scene_, out.environment.map_path);
  out.base_dir.clear();
  out.render = core_->state().settings;
  // The camera as seen: the free camera becomes a fixed one; a scene camera is kept as it is.
  if (core_->state().free_camera) {
    const scene::CameraState camera = core_->camera();
    scene::FixedCamera fixed;
    fixed.position = camera.eye;
    fixed.target = camera.target;
    fixed.up = camera.up;
    fixed.fov_degrees = camera.fov_y_degrees;
    out.camera.kind = fixed;
  }
  // The range starts at the frame on screen, so `record` renders it first.
  const Playback& playback = core_->state().playback;
  out.output.first_frame = playback.frame();
  out.output.frame_count = playback.last_frame - playback.frame() + 1;
  out.output.width = int(display_width_);
  out.output.height = int(display_height_);
  if (Status s = scene::save_scene(out, path); !s) return s;
  core_->state().notice = "saved " + path;
  return {};
}

Status Viewer::write_screenshot(const std::vector<std::uint8_t>& rgba, std::uint32_t width, std::uint32_t height,
                                const std::string& path) {
  std::filesystem::path file = path;
  if (file.empty()) {
    char name[64];
    std::snprintf(name, sizeof name, "frame_%05d_%d.png", core_ ? core_->state().playback.frame() : 0,
                  screenshot_count_);
    file = options_.screenshot_dir / name;
  }
  ++screenshot_count_;
  std::error_code error;
  if (file.has_parent_path()) std::filesystem::create_directories(file.parent_path(), error);
  if (!options_.write_png) return make_error("screenshot: no PNG writer");
  if (Status s = options_.write_png(file, rgba, int(width), int(height)); !s) return s;
  if (core_) core_->state().notice = "screenshot " + file.string();
  log_info("view: wrote " + file.string());
  return {};
}

Status Viewer::write_state() const {
  if (options_.state_out.empty() || !core_) return {};
  const ViewerState& state = core_->state();
  const scene::CameraState camera = core_->camera();
  nlohmann::json json;
  json["scene"] = name_;
  json["time_s"] = state.playback.time_s;
  json["frame"] = state.playback.frame();
  json["playing"] = state.playback.playing;
  json["speed"] = state.playback.speed;
  json["direction"] = state.playback.direction;
  json["loop"] = std::string(loop_mode_name(state.playback.loop));
  json["free_camera"] = state.free_camera;
  json["camera"] = {{"eye", {camera.eye.x, camera.eye.y, camera.eye.z}},
                    {"target", {camera.target.x, camera.target.y, camera.target.z}}};
  for (const settings::Field& field : settings::fields()) json["settings"][std::string(field.key)] = field.get(state.settings);
  json["view"] = std::string(view_name(state.view));
  json["message"] = state.message;
  json["notice"] = state.notice;
  json["frames"] = frames_;
  json["proxies"] = world_ ? world_->proxy_count() : 0;
  json["previews"] = previews_;
  json["ui_overlay_draws"] = overlay_draws_;    // frames that rasterized ImGui into the overlay
  json["ui_overlay_reuses"] = overlay_reuses_;  // frames that blended the overlay as it was
  json["ui_direct_draws"] = ui_direct_draws_;   // frames that rasterized ImGui onto the frame
  json["ui_screenshots_reusing_overlay"] = screenshots_reusing_;
  json["frames_without_proxies"] = frames_without_proxies_;
  json["fps_mean"] = times_.mean() > 0.0 ? 1000.0 / times_.mean() : 0.0;
  json["frame_ms"] = {{"mean", times_.mean()}, {"min", times_.min()}, {"max", times_.max()}};  // last 128 frames
  json["frame_ms_steady"] = {{"mean", steady_times_.mean()}, {"min", steady_times_.min()}, {"max", steady_times_.max()},
                             {"frames", steady_times_.frames()}, {"warmup_frames", run::kWarmupFrames}};
  if (blocks_) {  // --measure-blocks: each kind's block means, block k of every kind neighbours
    nlohmann::json blocks = {{"block_frames", blocks_->block_frames()}, {"warmup_frames", MeasureBlocks::kWarmupFrames}};
    for (std::size_t e = 0; e < std::size_t(FrameEnd::count); ++e)
      blocks[frame_end_name(FrameEnd(e))] = blocks_->block_means(FrameEnd(e));
    json["measure_blocks_ms"] = blocks;
  }
  json["pass_timings_shown"] = pass_timings_shown_;        // HUD pass-time updates
  json["in_frame_pass_timings"] = in_frame_pass_timings_;  // of them, from timestamps in a frame shown
  nlohmann::json parts = nlohmann::json::object();
  for (std::size_t p = 0; p < std::size_t(FramePart::count); ++p)
    parts[frame_part_name(FramePart(p))] = parts_.frames ? parts_.sum_ms[p] / parts_.frames : 0.0;
  json["frame_parts_ms"] = parts;  // mean wall time per loop part (FramePart)
  json["display"] = {display_width_, display_height_};
  json["internal"] = {internal_width_, internal_height_};
  json["swapchain_recreations"] = swapchain_ ? swapchain_->recreations() : 0;
  if (window_) {
    int x = 0, y = 0;
    window_->position(x, y);
    json["window_position"] = {x, y};
    json["monitors"] = Window::monitor_count();
  }
  json["validation_messages"] = context_ ? context_->validation_message_count() : 0;
  json["toggles"] = {{"ui", state.toggles.ui}, {"hud", state.toggles.hud}, {"help", state.toggles.help},
                     {"bones", state.toggles.bones}, {"proxies", state.toggles.proxies}, {"grid", state.toggles.grid},
                     {"wireframe", state.toggles.wireframe}};
  // render.quality: the settings the renderer chose for the current shot, and why.
  if (renderer_ && renderer_->quality().automatic) {
    const quality::QualityChoice& choice = renderer_->quality();
    const settings::RenderSettings& chosen = choice.settings;
    json["quality"] = {{"choice", quality::describe(choice)},
                       {"target_relative_mse", choice.target},
                       {"predicted_relative_mse", choice.predicted},
                       {"met", choice.met},
                       {"sh_order", chosen.sh_order},
                       {"receiver_scale", chosen.receiver_scale},
                       {"upsampling", std::string(settings::name_of(chosen.upsampling))},
                       {"shadow_eta", renderer_->frame().shadow_eta()},
                       {"proxy_lod", std::string(settings::name_of(chosen.proxy_lod))},
                       {"reasons", choice.reasons}};
  } else {
    json["quality"] = "manual";
  }
  json["environment"] = scene_.environment.type == scene::Environment::Type::map ? scene_.environment.map_path : std::string("sky");
  std::ofstream out(options_.state_out);
  if (!out) return make_error(options_.state_out.string() + ": cannot write the viewer state");
  out << json.dump(2) << "\n";
  return {};
}

}  // namespace proxygi::view
