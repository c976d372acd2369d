#include "view/viewer_core.h"

#include <algorithm>
#include <cmath>

#include "run/frame_plan.h"
#include "settings/fields.h"

namespace proxygi::view {
namespace {

constexpr float kOrbitDegreesPerPixel = 0.3f;
constexpr float kPanPerPixel = 0.0015f;  // of the distance: the target follows the cursor roughly
constexpr float kZoomPerWheelStep = 0.9f;
constexpr double kMinSpeed = 1.0 / 16.0, kMaxSpeed = 16.0;

}  // namespace

std::string_view loop_mode_name(LoopMode mode) {
  switch (mode) {
    case LoopMode::loop: return "loop";
    case LoopMode::once: return "once";
    case LoopMode::ping_pong: return "ping-pong";
  }
  return "?";
}

std::string_view view_name(View view) {
  switch (view) {
    case View::final: return "final";
    case View::albedo: return "albedo";
    case View::normals: return "normals";
    case View::irradiance: return "irradiance (direct + indirect)";
    case View::receivers: return "receivers at 1/k";
    case View::direct: return "direct only";
    case View::indirect: return "indirect only";
    case View::occlusion: return "occlusion (visible fraction)";
    case View::heat_map: return "proxies per tile (heat map)";
  }
  return "?";
}

int Playback::frame() const {
  return std::clamp(int(std::lround(time_s * fps)), first_frame, last_frame);
}

scene::CameraState FreeCamera::state() const {
  const float azimuth = glm::radians(azimuth_degrees), elevation = glm::radians(elevation_degrees);
  const glm::vec3 offset{std::cos(elevation) * std::sin(azimuth), std::sin(elevation),
                         std::cos(elevation) * std::cos(azimuth)};
  scene::CameraState camera;
  camera.target = target;
  camera.eye = target + distance * offset;
  camera.up = {0.0f, 1.0f, 0.0f};
  camera.fov_y_degrees = fov_y_degrees;
  camera.near_m = near_m;
  camera.far_m = far_m;
  return camera;
}

FreeCamera FreeCamera::from(const scene::CameraState& camera) {
  FreeCamera free;
  const glm::vec3 offset = camera.eye - camera.target;
  free.target = camera.target;
  free.distance = std::max(glm::length(offset), 1e-3f);
  free.elevation_degrees = glm::degrees(std::asin(std::clamp(offset.y / free.distance, -1.0f, 1.0f)));
  free.azimuth_degrees = glm::degrees(std::atan2(offset.x, offset.z));
  free.fov_y_degrees = camera.fov_y_degrees;
  free.near_m = camera.near_m;
  free.far_m = camera.far_m;
  return free;
}

ViewerCore::ViewerCore(const scene::Scene& scene) {
  reset_for_scene(scene);
  state_.playback.time_s = state_.playback.start_s();
}

void ViewerCore::reset_for_scene(const scene::Scene& scene) {
  const run::FrameRange range = run::scene_frame_range(scene.output);
  Playback& playback = state_.playback;
  playback.fps = scene.output.fps;
  playback.first_frame = range.first;
  playback.last_frame = range.last;
  playback.time_s = std::clamp(playback.time_s, playback.start_s(), playback.end_s());
  state_.settings = scene.render;
  state_.free_camera = false;
}

void ViewerCore::seek(double time_s) {
  state_.playback.time_s = std::clamp(time_s, state_.playback.start_s(), state_.playback.end_s());
}

void ViewerCore::step_frames(int frames) {
  Playback& playback = state_.playback;
  playback.playing = false;
  const int frame = std::clamp(playback.frame() + frames, playback.first_frame, playback.last_frame);
  playback.time_s = frame / playback.fps;
}

void ViewerCore::advance(double wall_dt_s) {
  Playback& playback = state_.playback;
  if (!playback.playing) return;
  const double dt = playback.fixed_step ? 1.0 / playback.fps : wall_dt_s * playback.speed;
  double t = playback.time_s + playback.direction * dt;
  const double start = playback.start_s(), end = playback.end_s(), length = end - start;
  if (t > end || t < start) {
    switch (playback.loop) {
      case LoopMode::loop:
        t = length > 0.0 ? start + std::fmod(std::fmod(t - start, length) + length, length) : start;
        break;
      case LoopMode::once:
        t = std::clamp(t, start, end);
        playback.playing = false;
        break;
      case LoopMode::ping_pong:
        t = t > end ? end - (t - end) : start + (start - t);
        t = std::clamp(t, start, end);
        playback.direction = -playback.direction;
        break;
    }
  }
  playback.time_s = t;
}

void ViewerCore::ensure_free_camera() {
  if (state_.free_camera) return;
  state_.camera = FreeCamera::from(scene_camera_);
  state_.free_camera = true;
}

void ViewerCore::frame_all() {
  ensure_free_camera();
  FreeCamera& camera = state_.camera;
  camera.target = bounds_center_;
  const float half_fov = glm::radians(camera.fov_y_degrees) * 0.5f;
  camera.distance = std::max(bounds_radius_ / std::sin(half_fov) * 1.1f, camera.near_m * 4.0f);
}

std::optional<scene::CameraState> ViewerCore::camera_override() const {
  if (!state_.free_camera) return std::nullopt;
  return state_.camera.state();
}

scene::CameraState ViewerCore::camera() const { return state_.free_camera ? state_.camera.state() : scene_camera_; }

std::vector<Event> ViewerCore::take_requests() {
  std::vector<Event> requests;
  requests.swap(requests_);
  return requests;
}

void ViewerCore::handle_key(const KeyEvent& event) {
  Playback& playback = state_.playback;
  Toggles& toggles = state_.toggles;
  const bool shift = event.mods.shift, ctrl = event.mods.ctrl;
  switch (event.key) {
    case Key::space:
      if (shift && ctrl) playback.direction = -playback.direction;
      else playback.playing = !playback.playing;
      break;
    case Key::left:
      if (shift) playback.playing = false, playback.time_s = playback.start_s();
      else step_frames(-1);
      break;
    case Key::right:
      if (shift) playback.playing = false, playback.time_s = playback.end_s();
      else step_frames(1);
      break;
    case Key::down: step_frames(-10); break;
    case Key::up: step_frames(10); break;
    case Key::home:
    case Key::f: frame_all(); break;
    case Key::end: playback.playing = false, playback.time_s = playback.end_s(); break;
    case Key::c:
      if (state_.free_camera) state_.free_camera = false;
      else ensure_free_camera();
      break;
    case Key::minus: playback.speed = std::max(kMinSpeed, playback.speed * 0.5); break;
    case Key::equal: playback.speed = std::min(kMaxSpeed, playback.speed * 2.0); break;
    case Key::backspace: playback.speed = 1.0, playback.direction = 1; break;
    case Key::l: playback.loop = playback.loop == LoopMode::loop ? LoopMode::once : LoopMode::loop; break;
    case Key::p: playback.loop = playback.loop == LoopMode::ping_pong ? LoopMode::loop : LoopMode::ping_pong; break;
    case Key::b: toggles.bones = !toggles.bones; break;
    case Key::o: toggles.proxies = !toggles.proxies; break;
    case Key::w: toggles.wireframe = !toggles.wireframe; break;
    case Key::g: toggles.grid = !toggles.grid; break;
    case Key::h: toggles.hud = !toggles.hud; break;
    case Key::v: state_.view = View((int(state_.view) + (shift ? kViewCount - 1 : 1)) % kViewCount); break;
    case Key::f1: toggles.help = !toggles.help; break;
    case Key::f10: toggles.ui = !toggles.ui; break;
    case Key::f12: requests_.push_back(ScreenshotEvent{"", !ctrl}); break;
    case Key::escape: requests_.push_back(QuitEvent{}); break;
  }
}

void ViewerCore::handle_drag(const DragEvent& drag) {
  const bool pan = drag.button == MouseButton::right || (drag.mods.shift && drag.button != MouseButton::right);
  const bool zoom = drag.button == MouseButton::middle && drag.mods.ctrl;
  ensure_free_camera();
  FreeCamera& camera = state_.camera;
  if (zoom) {
    camera.distance = std::max(camera.distance * std::exp(drag.dy * 0.01f), 1e-2f);
  } else if (pan) {
    const scene::CameraState view = camera.state();
    const glm::vec3 forward = glm::normalize(view.target - view.eye);
    const glm::vec3 right = glm::normalize(glm::cross(forward, view.up));
    const glm::vec3 up = glm::cross(right, forward);
    camera.target += (-right * drag.dx + up * drag.dy) * (camera.distance * kPanPerPixel);
  } else {
    camera.azimuth_degrees -= drag.dx * kOrbitDegreesPerPixel;
    camera.elevation_degrees = std::clamp(camera.elevation_degrees + drag.dy * kOrbitDegreesPerPixel, -89.0f, 89.0f);
  }
}

void ViewerCore::handle(const Event& event) {
  if (const auto* key = std::get_if<KeyEvent>(&event)) return handle_key(*key);
  if (const auto* drag = std::get_if<DragEvent>(&event)) return handle_drag(*drag);
  if (const auto* scroll = std::get_if<ScrollEvent>(&event)) {
    ensure_free_camera();
    state_.camera.distance = std::max(state_.camera.distance * std::pow(kZoomPerWheelStep, scroll->dy), 1e-2f);
    return;
  }
  if (const auto* set = std::get_if<SetSettingEvent>(&event)) {
    const settings::Field* field = settings::find_field(set->key);
    if (!field) {
      state_.message = "unknown setting " + set->key;
      return;
    }
    if (auto why = settings::check_value(*field, set->value)) {
      state_.message = set->key + ": " + *why;
      return;
    }
    field->set(state_.settings, set->value);
    return;
  }
  requests_.push_back(event);  // open, screenshot, resize, quit: the application's
}

}  // namespace proxygi::view
