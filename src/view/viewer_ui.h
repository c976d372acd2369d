#pragma once
// What Dear ImGui draws over the frame (between ImGui::NewFrame and ImGui::Render): the HUD,
// the playback bar with its timeline, the live settings panel (one widget per row of
// settings::fields(), so a new setting appears without touching the viewer), the scene panel
// (clips, environment: these reload the world), the key map (F1), and the overlays — proxy
// spheres coloured by bone, the skeleton and a ground grid — projected with the frame's camera
// onto ImGui's background draw list.
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "scene/scene.h"
#include "view/viewer_core.h"
#include "world/world.h"

namespace proxygi::view {

// Frame times of the last 128 frames (milliseconds).
class FrameTimes {
 public:
  static constexpr std::size_t kCount = 128;
  void add(double ms);
  std::size_t size() const { return count_; }
  double mean() const;
  double min() const;
  double max() const;
  // Oldest first, for the plot.
  std::vector<float> ordered() const;

 private:
  std::array<double, kCount> ms_{};
  std::size_t next_ = 0, count_ = 0;
};

// Every frame time after the first `warmup` (the state file's steady figures, comparable with
// run::time_pipelined_frames, which times frames after warming up as many).
class SteadyTimes {
 public:
  explicit SteadyTimes(int warmup) : warmup_(warmup) {}
  void add(double ms);
  int frames() const { return frames_; }
  double mean() const { return frames_ ? sum_ / frames_ : 0.0; }
  double min() const { return frames_ ? min_ : 0.0; }
  double max() const { return frames_ ? max_ : 0.0; }

 private:
  int warmup_ = 0, skipped_ = 0, frames_ = 0;
  double sum_ = 0.0, min_ = 0.0, max_ = 0.0;
};

struct PassTime {
  std::string name;
  double ms = 0.0;
};

struct HudInfo {
  std::string device, driver;
  std::size_t proxies = 0, triangles = 0;
  std::uint64_t receivers = 0;
  float shadow_eta = 0.0f;  // η of shadows in use (the setting, or from the lighting when auto)
  std::string quality;                       // render.quality's choice (quality::describe), empty when manual
  std::vector<std::string> quality_reasons;  // and why, one line per setting
  std::uint32_t display_width = 0, display_height = 0, internal_width = 0, internal_height = 0;
  std::string present;  // "FIFO", "offscreen", ...
  int swapchain_recreations = 0;
  std::vector<PassTime> passes;  // per-pass times of one frame (pass names of `bench frame`)
  std::string pass_clock;        // how: GPU timestamps or fenced CPU timings (and why)
  std::string loading;           // progress line of a background load, empty when idle
  std::string title;
};

// What the UI asks of the application this frame.
struct UiRequests {
  std::optional<std::string> open;
  std::optional<std::string> save;
  bool reload = false;       // the scene (clips, environment) was edited: load it again
  bool time_passes = false;  // measure per-pass times now
  bool screenshot = false;
};

struct UiContext {
  ViewerCore& core;
  const HudInfo& hud;
  const FrameTimes& times;
  const world::World* world = nullptr;
  const world::WorldState* state = nullptr;  // the frame shown (overlays)
  scene::Scene* scene = nullptr;             // editable copy (clips, environment)
  bool* adaptive = nullptr;
  std::string* save_path = nullptr;
  std::string* open_path = nullptr;
};

UiRequests draw_ui(UiContext& ui);

}  // namespace proxygi::view
