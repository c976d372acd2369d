#include "view/window.h"

#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <backends/imgui_impl_glfw.h>

#include <cfloat>
#include <cstring>

#include "gpu/vulkan_check.h"

namespace proxygi::view {
namespace {

std::string glfw_error() {
  const char* description = nullptr;
  glfwGetError(&description);
  return description ? description : "unknown GLFW error";
}

std::optional<Key> key_of(int key) {
  switch (key) {
    case GLFW_KEY_SPACE: return Key::space;
    case GLFW_KEY_LEFT: return Key::left;
    case GLFW_KEY_RIGHT: return Key::right;
    case GLFW_KEY_UP: return Key::up;
    case GLFW_KEY_DOWN: return Key::down;
    case GLFW_KEY_HOME: return Key::home;
    case GLFW_KEY_END: return Key::end;
    case GLFW_KEY_F: return Key::f;
    case GLFW_KEY_C: return Key::c;
    case GLFW_KEY_MINUS: case GLFW_KEY_KP_SUBTRACT: return Key::minus;
    case GLFW_KEY_EQUAL: case GLFW_KEY_KP_ADD: return Key::equal;
    case GLFW_KEY_BACKSPACE: return Key::backspace;
    case GLFW_KEY_L: return Key::l;
    case GLFW_KEY_P: return Key::p;
    case GLFW_KEY_B: return Key::b;
    case GLFW_KEY_O: return Key::o;
    case GLFW_KEY_W: return Key::w;
    case GLFW_KEY_G: return Key::g;
    case GLFW_KEY_H: return Key::h;
    case GLFW_KEY_V: return Key::v;
    case GLFW_KEY_F1: return Key::f1;
    case GLFW_KEY_F10: return Key::f10;
    case GLFW_KEY_F12: return Key::f12;
    case GLFW_KEY_ESCAPE: return Key::escape;
    default: return std::nullopt;
  }
}

Modifiers modifiers_of(int mods) { return {(mods & GLFW_MOD_SHIFT) != 0, (mods & GLFW_MOD_CONTROL) != 0}; }

Window* self(GLFWwindow* window) { return static_cast<Window*>(glfwGetWindowUserPointer(window)); }

}  // namespace

Result<std::unique_ptr<Window>> Window::create(int width, int height, const std::string& title) {
  if (!glfwInit()) return make_error("cannot open a window: " + glfw_error());
  if (!glfwVulkanSupported()) return make_error("GLFW finds no Vulkan loader");
  glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);
  std::unique_ptr<Window> window(new Window());
  window->window_ = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
  if (!window->window_) return make_error("cannot open a window: " + glfw_error());
  glfwSetWindowUserPointer(window->window_, window.get());
  glfwSetKeyCallback(window->window_, on_key);
  glfwSetMouseButtonCallback(window->window_, on_mouse_button);
  glfwSetCursorPosCallback(window->window_, on_cursor);
  glfwSetScrollCallback(window->window_, on_scroll);
  glfwSetDropCallback(window->window_, on_drop);
  glfwSetCursorEnterCallback(window->window_, on_enter);
  glfwSetWindowFocusCallback(window->window_, on_focus);
  glfwSetWindowSizeCallback(window->window_, on_size);
  glfwSetFramebufferSizeCallback(window->window_, on_framebuffer_size);
  glfwGetWindowSize(window->window_, &window->window_width_, &window->window_height_);
  glfwGetFramebufferSize(window->window_, &window->framebuffer_width_, &window->framebuffer_height_);
  glfwGetCursorPos(window->window_, &window->cursor_x_, &window->cursor_y_);
  window->focused_ = glfwGetWindowAttrib(window->window_, GLFW_FOCUSED) != 0;
  window->inside_ = window->cursor_x_ >= 0 && window->cursor_y_ >= 0 && window->cursor_x_ < window->window_width_ &&
                    window->cursor_y_ < window->window_height_;
  return window;
}

Window::~Window() {
  if (imgui_) ImGui_ImplGlfw_Shutdown();
  for (GLFWcursor* cursor : cursors_)
    if (cursor) glfwDestroyCursor(cursor);
  if (window_) glfwDestroyWindow(window_);
  glfwTerminate();
}

std::vector<std::string> Window::required_instance_extensions() {
  std::uint32_t count = 0;
  const char** names = glfwGetRequiredInstanceExtensions(&count);
  std::vector<std::string> extensions;
  for (std::uint32_t i = 0; i < count; ++i) extensions.emplace_back(names[i]);
  return extensions;
}

Result<VkSurfaceKHR> Window::create_surface(VkInstance instance) const {
  VkSurfaceKHR surface = VK_NULL_HANDLE;
  PROXYGI_VK_TRY(glfwCreateWindowSurface(instance, window_, nullptr, &surface));
  return surface;
}

void Window::init_imgui() {
  ImGui_ImplGlfw_InitForVulkan(window_, true);  // chains to the callbacks above
  imgui_ = true;
  // GLFW 3.3's standard shapes; ImGui's others fall back to the arrow, as in its backend.
  cursors_[ImGuiMouseCursor_Arrow] = glfwCreateStandardCursor(GLFW_ARROW_CURSOR);
  cursors_[ImGuiMouseCursor_TextInput] = glfwCreateStandardCursor(GLFW_IBEAM_CURSOR);
  cursors_[ImGuiMouseCursor_ResizeNS] = glfwCreateStandardCursor(GLFW_VRESIZE_CURSOR);
  cursors_[ImGuiMouseCursor_ResizeEW] = glfwCreateStandardCursor(GLFW_HRESIZE_CURSOR);
  cursors_[ImGuiMouseCursor_Hand] = glfwCreateStandardCursor(GLFW_HAND_CURSOR);
}

void Window::new_imgui_frame(std::uint32_t width, std::uint32_t height, double dt_s) {
  static_assert(ImGuiMouseCursor_COUNT <= int(sizeof(cursors_) / sizeof(cursors_[0])));
  ImGuiIO& io = ImGui::GetIO();
  io.DisplaySize = {float(window_width_ > 0 ? window_width_ : int(width)), float(window_height_ > 0 ? window_height_ : int(height))};
  io.DisplayFramebufferScale = {float(width) / io.DisplaySize.x, float(height) / io.DisplaySize.y};
  io.DeltaTime = dt_s > 0.0 ? float(dt_s) : 1.0f / 60.0f;
  for (int i = 0; i < 5; ++i) {  // GLFW keeps the buttons' state: no server request
    io.MouseDown[i] = just_pressed_[i] || glfwGetMouseButton(window_, i) == GLFW_PRESS;
    just_pressed_[i] = false;
  }
  // Outside the window the last position inside stands while it has the focus (X sends motion
  // outside only during a drag), as the backend's pointer query would give it then.
  io.MousePos = inside_ || focused_ ? ImVec2(float(cursor_x_), float(cursor_y_)) : ImVec2(-FLT_MAX, -FLT_MAX);
  std::memset(io.NavInputs, 0, sizeof(io.NavInputs));  // no gamepad navigation
  if (io.ConfigFlags & ImGuiConfigFlags_NoMouseCursorChange) return;
  const int shape = ImGui::GetMouseCursor();
  if (shape == cursor_shape_) return;  // set only on a change: each set is a request to the server
  cursor_shape_ = shape;
  if (shape == ImGuiMouseCursor_None || io.MouseDrawCursor) {
    glfwSetInputMode(window_, GLFW_CURSOR, GLFW_CURSOR_HIDDEN);
  } else {
    glfwSetCursor(window_, cursors_[shape] ? cursors_[shape] : cursors_[ImGuiMouseCursor_Arrow]);
    glfwSetInputMode(window_, GLFW_CURSOR, GLFW_CURSOR_NORMAL);
  }
}

std::vector<Event> Window::poll() {
  glfwPollEvents();
  std::vector<Event> events;
  events.swap(events_);
  return events;
}

bool Window::should_close() const { return glfwWindowShouldClose(window_); }
void Window::framebuffer_size(int& width, int& height) const {
  width = framebuffer_width_, height = framebuffer_height_;
}
void Window::set_title(const std::string& title) { glfwSetWindowTitle(window_, title.c_str()); }

void Window::resize(int width, int height) {
  if (width == 0 && height == 0) glfwIconifyWindow(window_);
  else if (width < 0) glfwRestoreWindow(window_);
  else glfwSetWindowSize(window_, width, height);
}

void Window::move(int x, int y) { glfwSetWindowPos(window_, x, y); }
void Window::position(int& x, int& y) const { glfwGetWindowPos(window_, &x, &y); }
int Window::monitor_count() {
  int count = 0;
  glfwGetMonitors(&count);
  return count;
}

void Window::on_key(GLFWwindow* window, int key, int, int action, int mods) {
  if (action == GLFW_RELEASE) return;
  Window* me = self(window);
  if (me->imgui_ && ImGui::GetIO().WantTextInput) return;  // a text field has the keyboard
  if (auto mapped = key_of(key)) me->events_.push_back(KeyEvent{*mapped, modifiers_of(mods)});
}

void Window::on_mouse_button(GLFWwindow* window, int button, int action, int) {
  Window* me = self(window);
  if (action == GLFW_PRESS && button >= 0 && button < 5) me->just_pressed_[button] = true;
  if (action == GLFW_PRESS) {
    if (me->imgui_ && ImGui::GetIO().WantCaptureMouse) return;
    if (me->dragging_ < 0) me->dragging_ = button;
    glfwGetCursorPos(window, &me->last_x_, &me->last_y_);
  } else if (button == me->dragging_) {
    me->dragging_ = -1;
  }
}

void Window::on_cursor(GLFWwindow* window, double x, double y) {
  Window* me = self(window);
  me->cursor_x_ = x, me->cursor_y_ = y;
  if (me->dragging_ < 0) return;
  const float dx = float(x - me->last_x_), dy = float(y - me->last_y_);
  me->last_x_ = x, me->last_y_ = y;
  MouseButton button = MouseButton::left;
  if (me->dragging_ == GLFW_MOUSE_BUTTON_RIGHT) button = MouseButton::right;
  else if (me->dragging_ == GLFW_MOUSE_BUTTON_MIDDLE) button = MouseButton::middle;
  const bool shift = glfwGetKey(window, GLFW_KEY_LEFT_SHIFT) == GLFW_PRESS || glfwGetKey(window, GLFW_KEY_RIGHT_SHIFT) == GLFW_PRESS;
  const bool ctrl = glfwGetKey(window, GLFW_KEY_LEFT_CONTROL) == GLFW_PRESS || glfwGetKey(window, GLFW_KEY_RIGHT_CONTROL) == GLFW_PRESS;
  me->events_.push_back(DragEvent{button, dx, dy, {shift, ctrl}});
}

void Window::on_scroll(GLFWwindow* window, double, double dy) {
  Window* me = self(window);
  if (me->imgui_ && ImGui::GetIO().WantCaptureMouse) return;
  me->events_.push_back(ScrollEvent{float(dy)});
}

void Window::on_enter(GLFWwindow* window, int entered) { self(window)->inside_ = entered != 0; }
void Window::on_focus(GLFWwindow* window, int focused) { self(window)->focused_ = focused != 0; }
void Window::on_size(GLFWwindow* window, int width, int height) {
  self(window)->window_width_ = width, self(window)->window_height_ = height;
}

void Window::on_framebuffer_size(GLFWwindow* window, int width, int height) {
  self(window)->framebuffer_width_ = width, self(window)->framebuffer_height_ = height;
}

void Window::on_drop(GLFWwindow* window, int count, const char** paths) {
  Window* me = self(window);
  for (int i = 0; i < count; ++i) me->events_.push_back(OpenFileEvent{paths[i]});
}

}  // namespace proxygi::view
