#pragma once
// The viewer's input events, independent of any window system: the window presenter turns GLFW
// callbacks into these, scripts (script.h) spell them by name, and the core (viewer_core.h)
// handles both the same way. Key bindings follow ../shared/notes/viewer-regression.md §1.
#include <optional>
#include <string>
#include <string_view>
#include <variant>

namespace proxygi::view {

enum class Key {
  space, left, right, up, down, home, end, f, c, minus, equal, backspace,
  l, p, b, o, w, g, h, v, f1, f10, f12, escape,
};

struct Modifiers {
  bool shift = false;
  bool ctrl = false;
};

struct KeyEvent {
  Key key = Key::space;
  Modifiers mods;
};

enum class MouseButton { left, middle, right };

// A drag step: the cursor moved by (dx, dy) pixels with `button` held (y grows downwards).
struct DragEvent {
  MouseButton button = MouseButton::left;
  float dx = 0.0f, dy = 0.0f;
  Modifiers mods;
};

// Wheel: positive dy zooms in.
struct ScrollEvent {
  float dy = 0.0f;
};

struct SetSettingEvent {
  std::string key;  // a settings::fields() key
  double value = 0.0;
};

struct OpenFileEvent {
  std::string path;  // scene .json, .glb/.gltf, "default", "crowd"
};

struct ScreenshotEvent {
  std::string path;     // empty: screenshots/frame_NNNNN.png
  bool with_ui = true;  // false: the frame as record renders it
};

struct ResizeEvent {
  int width = 0, height = 0;  // 0 × 0: minimize; negative: restore
};

// Moves the window's top-left corner to (x, y) in desktop coordinates (across screens or
// monitors: the swapchain follows the framebuffer size wherever the window lands).
struct MoveEvent {
  int x = 0, y = 0;
};

// Writes the viewer's state as a scene file `record` runs (see viewer_app.h).
struct SaveSceneEvent {
  std::string path;
};

struct QuitEvent {};

using Event = std::variant<KeyEvent, DragEvent, ScrollEvent, SetSettingEvent, OpenFileEvent, ScreenshotEvent,
                           ResizeEvent, MoveEvent, SaveSceneEvent, QuitEvent>;

// "space", "left", "f12", ...: the names scripts use.
std::optional<Key> key_from_name(std::string_view name);
std::string_view key_name(Key key);
std::optional<MouseButton> button_from_name(std::string_view name);

}  // namespace proxygi::view
