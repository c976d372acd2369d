#pragma once
// The viewer's GLFW window (X11 on Debian's GLFW 3.3): no client API (Vulkan draws into it),
// callbacks turned into viewer events (input.h), and files dropped on it turned into
// OpenFileEvents. Dear ImGui's GLFW backend is installed after these callbacks and chains to
// them; events go to the viewer only when ImGui does not want them (a text field for keys,
// a UI window under the cursor for the mouse).
//
// new_imgui_frame() replaces the backend's ImGui_ImplGlfw_NewFrame: that one asks the X server
// for the window size (twice), the focus and the pointer every frame, four round trips that
// cost about 1 ms a frame under Xvfb on a busy CPU; here they come from GLFW's callbacks, and
// so does the framebuffer size the viewer asks for each frame.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "base/result.h"
#include "view/input.h"

struct GLFWwindow;
struct GLFWcursor;

namespace proxygi::view {

class Window {
 public:
  // Fails (with GLFW's message) when there is no display.
  static Result<std::unique_ptr<Window>> create(int width, int height, const std::string& title);
  ~Window();
  Window(const Window&) = delete;
  Window& operator=(const Window&) = delete;

  static std::vector<std::string> required_instance_extensions();
  Result<VkSurfaceKHR> create_surface(VkInstance instance) const;
  void init_imgui();  // ImGui's GLFW backend (the ImGui context must exist)
  // ImGui's per-frame input for a target of `width` × `height` pixels (the framebuffer):
  // display size, time step, mouse position and buttons, and the mouse cursor ImGui asks for.
  void new_imgui_frame(std::uint32_t width, std::uint32_t height, double dt_s);

  // Polls GLFW and returns the events since the last call.
  std::vector<Event> poll();
  bool should_close() const;
  // As of the last poll (GLFW's size events; no server request).
  void framebuffer_size(int& width, int& height) const;
  void set_title(const std::string& title);
  void resize(int width, int height);  // ResizeEvent: 0 × 0 minimizes, negative restores
  void move(int x, int y);             // MoveEvent
  // Where the window is (asks the server: for the state file, not per frame) and the monitors
  // GLFW reports.
  void position(int& x, int& y) const;
  static int monitor_count();
  GLFWwindow* handle() const { return window_; }

 private:
  Window() = default;
  static void on_key(GLFWwindow* window, int key, int scancode, int action, int mods);
  static void on_mouse_button(GLFWwindow* window, int button, int action, int mods);
  static void on_cursor(GLFWwindow* window, double x, double y);
  static void on_scroll(GLFWwindow* window, double dx, double dy);
  static void on_drop(GLFWwindow* window, int count, const char** paths);
  static void on_enter(GLFWwindow* window, int entered);
  static void on_focus(GLFWwindow* window, int focused);
  static void on_size(GLFWwindow* window, int width, int height);
  static void on_framebuffer_size(GLFWwindow* window, int width, int height);

  GLFWwindow* window_ = nullptr;
  bool imgui_ = false;
  std::vector<Event> events_;
  int dragging_ = -1;  // GLFW button held since a press the viewer took, -1: none
  double last_x_ = 0.0, last_y_ = 0.0;
  // What ImGui's frame needs, kept from the callbacks (window coordinates).
  double cursor_x_ = 0.0, cursor_y_ = 0.0;
  bool inside_ = false, focused_ = false;
  int window_width_ = 0, window_height_ = 0;
  int framebuffer_width_ = 0, framebuffer_height_ = 0;
  bool just_pressed_[5] = {};  // a press and release within one frame still counts as held
  int cursor_shape_ = -1;      // the ImGuiMouseCursor last set
  GLFWcursor* cursors_[9] = {};  // by ImGuiMouseCursor (Arrow .. NotAllowed)
};

}  // namespace proxygi::view
