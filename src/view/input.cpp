#include "view/input.h"

#include <array>
#include <utility>

namespace proxygi::view {
namespace {

constexpr std::array<std::pair<std::string_view, Key>, 24> kKeyNames = {{
    {"space", Key::space}, {"left", Key::left}, {"right", Key::right}, {"up", Key::up}, {"down", Key::down},
    {"home", Key::home}, {"end", Key::end}, {"f", Key::f}, {"c", Key::c}, {"minus", Key::minus},
    {"equal", Key::equal}, {"backspace", Key::backspace}, {"l", Key::l}, {"p", Key::p}, {"b", Key::b},
    {"o", Key::o}, {"w", Key::w}, {"g", Key::g}, {"h", Key::h}, {"v", Key::v}, {"f1", Key::f1},
    {"f10", Key::f10}, {"f12", Key::f12}, {"escape", Key::escape},
}};

}  // namespace

std::optional<Key> key_from_name(std::string_view name) {
  for (const auto& [key_name, key] : kKeyNames)
    if (key_name == name) return key;
  return std::nullopt;
}

std::string_view key_name(Key key) {
  for (const auto& [name, k] : kKeyNames)
    if (k == key) return name;
  return "?";
}

std::optional<MouseButton> button_from_name(std::string_view name) {
  if (name == "left") return MouseButton::left;
  if (name == "middle") return MouseButton::middle;
  if (name == "right") return MouseButton::right;
  return std::nullopt;
}

}  // namespace proxygi::view
