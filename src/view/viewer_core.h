#pragma once
// ViewerCore: the viewer without a window. Input events (input.h) change a ViewerState —
// playback clock, free or scene camera, toggles, render settings — and the state says what to
// render next (scene time, camera override, settings). The window presenter, the offscreen
// presenter and scripts all drive this one object, so a script tests what a person does.
//
//   ViewerCore core(scene);
//   core.handle(KeyEvent{Key::space});          // play
//   core.advance(1.0 / 60.0);                   // wall (or fixed) time step
//   renderer.render({.time_s = core.state().playback.time_s, .camera = core.camera_override()});
//
// Events the core cannot carry out itself (screenshots, opening files, resizing, quitting) are
// queued for the application: take_requests().
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "scene/camera.h"
#include "scene/scene.h"
#include "settings/render_settings.h"
#include "view/input.h"

namespace proxygi::view {

enum class LoopMode { loop, once, ping_pong };
std::string_view loop_mode_name(LoopMode mode);

// The playback clock on the scene's frame grid (the frames `record` writes).
struct Playback {
  double time_s = 0.0;
  bool playing = false;
  double speed = 1.0;   // scene seconds per wall second, 1/16..16
  int direction = 1;    // +1 forward, -1 reverse
  LoopMode loop = LoopMode::loop;
  bool fixed_step = false;  // advance one frame (1/fps) per displayed frame, whatever the wall time
  double fps = 24.0;
  int first_frame = 0, last_frame = 95;

  double start_s() const { return first_frame / fps; }
  double end_s() const { return last_frame / fps; }
  int frame() const;  // the nearest frame of the grid
};

// The free camera: orbits `target` at `distance`, azimuth like the scene's orbit camera
// (0: on the +Z side of the target, 90: +X side), elevation above the horizontal plane.
struct FreeCamera {
  glm::vec3 target{0.0f, 1.0f, 0.0f};
  float distance = 5.0f;
  float azimuth_degrees = 0.0f;
  float elevation_degrees = 15.0f;
  float fov_y_degrees = 45.0f;
  float near_m = 0.05f, far_m = 200.0f;

  scene::CameraState state() const;
  static FreeCamera from(const scene::CameraState& camera);
};

// What the frame shows (V cycles): the final frame or one of its inputs (the composite pass's
// gpu_layout::kDebugView* in the same order: shaders/shared/layouts.h says what each holds).
enum class View { final, albedo, normals, irradiance, receivers, direct, indirect, occlusion, heat_map };
inline constexpr int kViewCount = 9;
std::string_view view_name(View view);

struct Toggles {
  bool ui = true;       // F10: the whole UI
  bool hud = true;      // H
  bool help = false;    // F1
  bool bones = false;   // B
  bool proxies = false; // O
  bool grid = false;    // G
  bool wireframe = false;  // W: the characters' triangle edges (x-ray overlay)
  bool shells = false;     // each proxy's shadow sphere of influence (η·r) with its sphere
  std::string selected_bone;  // its spheres are highlighted (empty: none)
};

struct ViewerState {
  Playback playback;
  bool free_camera = false;  // false: the scene's own camera at the current time
  FreeCamera camera;
  Toggles toggles;
  settings::RenderSettings settings;
  View view = View::final;
  std::string message;  // the last error (a file that failed to open, a bad setting), shown until dismissed
  std::string notice;   // the last notice (screenshot written, scene saved)
};

class ViewerCore {
 public:
  explicit ViewerCore(const scene::Scene& scene);

  // A newly opened scene: its frame range, fps and settings; playback and toggles are kept.
  void reset_for_scene(const scene::Scene& scene);

  void handle(const Event& event);
  // Advances the clock by a wall-time step (or one frame with fixed_step) while playing.
  void advance(double wall_dt_s);

  // The scene camera at the current time, given by the application each frame, so that the
  // free camera starts where the scene camera is when the user first drags.
  void set_scene_camera(const scene::CameraState& camera) { scene_camera_ = camera; }
  // The bounding sphere of what is on screen (for frame all).
  void set_bounds(const glm::vec3& center, float radius) { bounds_center_ = center, bounds_radius_ = radius; }

  std::optional<scene::CameraState> camera_override() const;
  scene::CameraState camera() const;  // what is rendered

  const ViewerState& state() const { return state_; }
  ViewerState& state() { return state_; }  // the UI edits it directly (sliders, checkboxes)

  // Events for the application (screenshot, open, resize, quit), oldest first.
  std::vector<Event> take_requests();

  // Playback operations, also used by the UI's buttons and timeline.
  void step_frames(int frames);  // pauses
  void seek(double time_s);      // clamped to the range
  void frame_all();

 private:
  void handle_key(const KeyEvent& key);
  void handle_drag(const DragEvent& drag);
  void ensure_free_camera();

  ViewerState state_;
  scene::CameraState scene_camera_;
  glm::vec3 bounds_center_{0.0f, 1.0f, 0.0f};
  float bounds_radius_ = 1.0f;
  std::vector<Event> requests_;
};

}  // namespace proxygi::view
