#include "view/script.h"

#include <algorithm>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "settings/fields.h"

namespace proxygi::view {
namespace {

using nlohmann::json;

Modifiers modifiers_of(const json& object) {
  return {object.value("shift", false), object.value("ctrl", false)};
}

// A setting value: a number, a boolean, a choice's name, "auto", a named value ("balanced") or,
// for a field with an object form, {"target_relative_mse": 0.015} (settings::value_from_name).
Result<double> setting_value(const std::string& key, const json& value) {
  const settings::Field* field = settings::find_field(key);
  if (!field) return make_error("unknown setting \"" + key + "\"");
  if (value.is_boolean()) return value.get<bool>() ? 1.0 : 0.0;
  if (value.is_number()) {
    const double number = value.get<double>();
    if (auto why = settings::check_number(*field, number)) return make_error(key + ": " + *why);
    return number;
  }
  if (value.is_string()) {
    double named = 0.0;
    if (auto why = settings::value_from_name(*field, value.get<std::string>(), named)) return make_error(key + ": " + *why);
    return named;
  }
  if (value.is_object() && !field->object_key.empty()) {  // {"target_relative_mse": 0.015}
    const std::string inner(field->object_key);
    if (value.size() != 1 || !value.contains(inner) || !value[inner].is_number())
      return make_error(key + ": expected {\"" + inner + "\": number}");
    const double number = value[inner].get<double>();
    if (auto why = settings::check_number(*field, number)) return make_error(key + "." + inner + ": " + *why);
    return number;
  }
  return make_error(key + ": expected a number, a boolean, a choice name or \"auto\"");
}

Status parse_event(const json& item, std::vector<TimedEvent>& out) {
  if (!item.is_object()) return make_error("expected an object");
  if (!item.contains("t") || !item["t"].is_number()) return make_error("t: expected a number of seconds");
  const double t = item["t"].get<double>();
  if (t < 0.0) return make_error("t: must be >= 0");
  auto add = [&](Event event) { out.push_back({t, std::move(event)}); };
  if (item.contains("key")) {
    const auto name = item["key"].is_string() ? item["key"].get<std::string>() : std::string();
    const auto key = key_from_name(name);
    if (!key) return make_error("key: unknown key \"" + name + "\"");
    add(KeyEvent{*key, modifiers_of(item)});
  } else if (item.contains("drag")) {
    const json& drag = item["drag"];
    const auto button = button_from_name(drag.value("button", std::string("left")));
    if (!button) return make_error("drag.button: expected left, middle or right");
    add(DragEvent{*button, drag.value("dx", 0.0f), drag.value("dy", 0.0f), modifiers_of(drag)});
  } else if (item.contains("scroll")) {
    if (!item["scroll"].is_number()) return make_error("scroll: expected a number");
    add(ScrollEvent{item["scroll"].get<float>()});
  } else if (item.contains("set")) {
    if (!item["set"].is_object()) return make_error("set: expected an object of settings");
    for (const auto& [key, value] : item["set"].items()) {
      auto number = setting_value(key, value);
      if (!number) return make_error("set." + key + ": " + number.message());
      add(SetSettingEvent{key, *number});
    }
  } else if (item.contains("screenshot")) {
    if (!item["screenshot"].is_string()) return make_error("screenshot: expected a file path");
    add(ScreenshotEvent{item["screenshot"].get<std::string>(), item.value("ui", true)});
  } else if (item.contains("open")) {
    if (!item["open"].is_string()) return make_error("open: expected a file path or name");
    add(OpenFileEvent{item["open"].get<std::string>()});
  } else if (item.contains("save")) {
    if (!item["save"].is_string()) return make_error("save: expected a scene file path");
    add(SaveSceneEvent{item["save"].get<std::string>()});
  } else if (item.contains("resize")) {
    const json& size = item["resize"];
    if (!size.is_array() || size.size() != 2 || !size[0].is_number_integer() || !size[1].is_number_integer() ||
        size[0].get<int>() < 1 || size[1].get<int>() < 1)
      return make_error("resize: expected [width, height] in pixels");
    add(ResizeEvent{size[0].get<int>(), size[1].get<int>()});
  } else if (item.contains("move")) {
    const json& at = item["move"];
    if (!at.is_array() || at.size() != 2 || !at[0].is_number_integer() || !at[1].is_number_integer())
      return make_error("move: expected [x, y], the window's top-left in desktop pixels");
    add(MoveEvent{at[0].get<int>(), at[1].get<int>()});
  } else if (item.contains("minimize")) {
    add(ResizeEvent{0, 0});
  } else if (item.contains("restore")) {
    add(ResizeEvent{-1, -1});
  } else if (item.contains("quit")) {
    if (item["quit"] != true) return make_error("quit: expected true");
    add(QuitEvent{});
  } else {
    return make_error("expected one of key, drag, scroll, set, screenshot, open, save, resize, move, minimize, restore, quit");
  }
  return {};
}

}  // namespace

Result<Script> parse_script(std::string_view json_text) {
  json root = json::parse(json_text, nullptr, false);
  if (root.is_discarded() || !root.is_object()) return make_error("script: not a JSON object");
  Script script;
  if (root.contains("step_s")) {
    if (!root["step_s"].is_number() || root["step_s"].get<double>() <= 0.0)
      return make_error("script: step_s: expected seconds > 0");
    script.step_s = root["step_s"].get<double>();
  }
  if (!root.contains("events") || !root["events"].is_array()) return make_error("script: events: expected an array");
  for (std::size_t i = 0; i < root["events"].size(); ++i)
    if (Status s = parse_event(root["events"][i], script.events); !s)
      return make_error("script: events[" + std::to_string(i) + "]." + s.message());
  std::stable_sort(script.events.begin(), script.events.end(),
                   [](const TimedEvent& a, const TimedEvent& b) { return a.time_s < b.time_s; });
  return script;
}

Result<Script> load_script(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) return make_error(file.string() + ": cannot open the script");
  std::stringstream text;
  text << in.rdbuf();
  auto script = parse_script(text.str());
  if (!script) return make_error(file.string() + ": " + script.message());
  return script;
}

std::vector<Event> ScriptPlayer::due(double now_s) {
  std::vector<Event> events;
  // A small tolerance: event times written as frame multiples land on the frame they name.
  while (has_due(now_s)) {
    events.push_back(script_.events[next_++].event);
    if (std::holds_alternative<ScreenshotEvent>(events.back())) break;
  }
  return events;
}

bool ScriptPlayer::has_due(double now_s) const {
  return next_ < script_.events.size() && script_.events[next_].time_s <= now_s + 1e-9;
}

}  // namespace proxygi::view
