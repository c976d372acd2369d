#include "regress/scenario.h"

#include <algorithm>
#include <cmath>
#include <set>

#include <nlohmann/json.hpp>

#include "base/atomic_file.h"
#include "scene/json_reader.h"
#include "scene/scene_defaults.h"
#include "scene/scene_parse.h"
#include "scene/scene_validate.h"
#include "settings/fields.h"

namespace proxygi::regress {
namespace {

using nlohmann::json;
using scene::detail::fail;
using scene::detail::ObjectReader;
namespace detail = scene::detail;

constexpr std::pair<std::string_view, CheckType> kCheckTypes[] = {{"image", CheckType::image},
                                                                   {"tracks", CheckType::tracks},
                                                                   {"temporal", CheckType::temporal},
                                                                   {"differential", CheckType::differential},
                                                                   {"budget", CheckType::budget}};
constexpr std::pair<std::string_view, Region> kRegions[] = {
    {"all", Region::all}, {"ground", Region::ground}, {"character", Region::character}};
constexpr std::pair<std::string_view, Aov> kAovs[] = {
    {"final", Aov::final_frame}, {"irradiance", Aov::irradiance}, {"albedo", Aov::albedo}};
constexpr std::pair<std::string_view, DifferentialKind> kKinds[] = {
    {"settings", DifferentialKind::settings}, {"repeat", DifferentialKind::repeat}, {"shard", DifferentialKind::shard}};

void at_least(double value, double minimum, const std::string& path) {
  if (!(value >= minimum)) fail(path, "must be >= " + std::to_string(minimum) + " (got " + std::to_string(value) + ")");
}

Overrides read_overrides(const json& value, const std::string& path) {
  if (!value.is_object()) fail(path, "expected an object of \"render.<field>\" / \"output.<field>\" keys");
  Overrides out;
  for (const auto& [key, v] : value.items()) {
    const std::string where = detail::join_path(path, key);
    if (key.rfind("render.", 0) == 0) {
      const settings::Field* field = settings::find_field(std::string_view(key).substr(7));
      if (field == nullptr) fail(where, "unknown render setting");
      if (field->kind == settings::FieldKind::choice || (settings::accepts_names(*field) && v.is_string())) {
        double named = 0.0;  // a choice's name, "auto" or a named value ("balanced")
        if (auto why = settings::value_from_name(*field, detail::read_string(v, where), named)) fail(where, *why);
        out[key] = named;
      } else if (!field->object_key.empty() && v.is_object()) {  // {"target_relative_mse": 0.015}
        const std::string inner(field->object_key);
        if (v.size() != 1 || !v.contains(inner)) fail(where, "expected {\"" + inner + "\": number}");
        const double number = detail::read_double(v[inner], detail::join_path(where, inner));
        if (auto why = settings::check_number(*field, number)) fail(detail::join_path(where, inner), *why);
        out[key] = number;
      } else if (field->kind == settings::FieldKind::boolean) {
        out[key] = detail::read_bool(v, where) ? 1.0 : 0.0;
      } else {
        const double number = detail::read_double(v, where);
        if (auto why = settings::check_number(*field, number)) fail(where, *why);
        out[key] = number;
      }
    } else if (key == "output.width" || key == "output.height" || key == "output.frames.first" ||
               key == "output.frames.count") {
      out[key] = detail::read_int(v, where);
    } else if (key == "output.fps") {
      out[key] = detail::read_double(v, where);
    } else {
      fail(where, "unknown override (render.<field>, output.width, output.height, output.fps, output.frames.first, "
                  "output.frames.count)");
    }
  }
  return out;
}

std::vector<int> read_frames(const json& value, const std::string& path) {
  const json& array = detail::expect_array(value, path);
  std::vector<int> frames;
  for (std::size_t i = 0; i < array.size(); ++i) {
    const int frame = detail::read_int(array[i], detail::index_path(path, i));
    if (frame < 0) fail(detail::index_path(path, i), "frames are >= 0");
    frames.push_back(frame);
  }
  if (frames.empty()) fail(path, "needs at least one frame");
  return frames;
}

Check read_check(const json& value, const std::string& path) {
  ObjectReader r(value, path);
  Check c;
  c.name = detail::read_string(r.require("name"), r.field("name"));
  if (c.name.empty() || !std::all_of(c.name.begin(), c.name.end(), [](char ch) {
        return std::isalnum(static_cast<unsigned char>(ch)) || ch == '_' || ch == '-';
      }))
    fail(r.field("name"), "use letters, digits, _ and - (got \"" + c.name + "\")");
  c.type = detail::parse_enum(r.require("type"), r.field("type"), kCheckTypes);
  if (const json* frames = r.get("frames")) c.frames = read_frames(*frames, r.field("frames"));
  const bool imagey = c.type == CheckType::image || c.type == CheckType::temporal || c.type == CheckType::differential;
  if (imagey) {
    c.region = r.enumeration("region", c.region, kRegions);
    c.image.pixel_threshold = r.integer("pixel_threshold", c.type == CheckType::differential ? 0 : c.image.pixel_threshold);
    at_least(c.image.pixel_threshold, 0, r.field("pixel_threshold"));
    c.image.max_failing_fraction =
        r.number_double("max_failing_fraction", c.type == CheckType::differential ? 0.0 : c.image.max_failing_fraction);
    at_least(c.image.max_failing_fraction, 0, r.field("max_failing_fraction"));
  }
  if (c.type == CheckType::image) {
    c.aov = r.enumeration("aov", c.aov, kAovs);
    if (const json* v = r.get("flip_mean")) c.image.flip_mean = detail::read_double(*v, r.field("flip_mean"));
    if (const json* v = r.get("flip_percentile")) {
      ObjectReader p(*v, r.field("flip_percentile"));
      c.image.flip_percentile = detail::read_double(p.require("p"), p.field("p"));
      c.image.flip_percentile_max = detail::read_double(p.require("max"), p.field("max"));
      if (!(*c.image.flip_percentile > 0.0 && *c.image.flip_percentile <= 1.0)) fail(p.field("p"), "must be in (0, 1]");
      p.finish();
    }
    c.image.shift_radius = r.integer("shift_radius", 0);
    if (c.image.shift_radius < 0 || c.image.shift_radius > 8) fail(r.field("shift_radius"), "must be in 0..8");
    c.fallback_scale = r.number_double("fallback_scale", c.fallback_scale);
    at_least(c.fallback_scale, 1.0, r.field("fallback_scale"));
  } else if (c.type == CheckType::tracks) {
    c.joints = r.boolean("joints", c.joints);
    c.vertices = r.integer("vertices", c.vertices);
    at_least(c.vertices, 0, r.field("vertices"));
    c.seed = std::uint32_t(r.integer("seed", int(c.seed)));
    c.proxies = r.boolean("proxies", c.proxies);
    c.tracks.joint_mm = r.number_double("joint_mm", c.tracks.joint_mm);
    c.tracks.rotation_distance_m = r.number_double("rotation_distance_m", c.tracks.rotation_distance_m);
    c.tracks.vertex_mm = r.number_double("vertex_mm", c.tracks.vertex_mm);
    c.tracks.proxy_mm = r.number_double("proxy_mm", c.tracks.proxy_mm);
    for (const char* key : {"joint_mm", "rotation_distance_m", "vertex_mm", "proxy_mm"}) {
      if (const json* v = r.get(key)) at_least(v->get<double>(), 0.0, r.field(key));
    }
  } else if (c.type == CheckType::temporal) {
    c.temporal_tolerance = r.number_double("tolerance", c.temporal_tolerance);
    at_least(c.temporal_tolerance, 0.0, r.field("tolerance"));
  } else if (c.type == CheckType::differential) {
    c.kind = r.enumeration("kind", c.kind, kKinds);
    if (c.kind == DifferentialKind::settings) {
      c.a = read_overrides(r.require("a"), r.field("a"));
      c.b = read_overrides(r.require("b"), r.field("b"));
    }
  } else if (c.type == CheckType::budget) {
    const json& budgets = r.require("devices");
    if (!budgets.is_object() || budgets.empty()) fail(r.field("devices"), "expected an object {\"device pattern\": ms}");
    for (const auto& [pattern, ms] : budgets.items()) {
      const double limit = detail::read_double(ms, detail::join_path(r.field("devices"), pattern));
      if (!(limit > 0)) fail(detail::join_path(r.field("devices"), pattern), "must be > 0 ms");
      c.budgets.emplace_back(pattern, limit);
    }
    c.runs = r.integer("runs", c.runs);
    if (c.runs < 1 || c.runs > 31) fail(r.field("runs"), "must be in 1..31");
    c.timed_frames = r.integer("timed_frames", c.timed_frames);
    if (c.timed_frames < 1) fail(r.field("timed_frames"), "must be >= 1");
  }
  r.finish();
  return c;
}

scene::Scene read_scene_field(const json& value, const std::filesystem::path& file, const std::string& path) {
  if (value.is_string()) {
    const std::string text = value.get<std::string>();
    if (text == "builtin:default") return scene::default_scene();
    if (text == "builtin:crowd") return scene::crowd_scene();
    auto loaded = scene::load_scene(file.parent_path() / text);
    if (!loaded) fail(path, loaded.message());
    return *loaded;
  }
  if (!value.is_object()) fail(path, "expected a scene file path, builtin:default, builtin:crowd or an inline scene");
  auto parsed = scene::parse_scene(value.dump(), file);
  if (!parsed) fail(path, "inline scene: " + parsed.message());
  return *parsed;
}

}  // namespace

bool Scenario::requirements_met() const {
  std::error_code error;
  return std::all_of(requires_paths.begin(), requires_paths.end(),
                     [&](const auto& path) { return std::filesystem::exists(path, error); });
}

std::string_view check_type_name(CheckType type) {
  for (const auto& [name, t] : kCheckTypes)
    if (t == type) return name;
  return "?";
}

Status apply_overrides(scene::Scene& scene, const Overrides& overrides) {
  for (const auto& [key, value] : overrides) {
    if (key.rfind("render.", 0) == 0) {
      const settings::Field* field = settings::find_field(std::string_view(key).substr(7));
      if (field == nullptr) return make_error(key + ": unknown render setting");
      if (auto why = settings::check_value(*field, value)) return make_error(key + ": " + *why);
      field->set(scene.render, value);
    } else if (key == "output.width") {
      scene.output.width = int(value);
    } else if (key == "output.height") {
      scene.output.height = int(value);
    } else if (key == "output.fps") {
      scene.output.fps = value;
    } else if (key == "output.frames.first") {
      scene.output.first_frame = int(value);
    } else if (key == "output.frames.count") {
      scene.output.frame_count = int(value);
    } else {
      return make_error(key + ": unknown override");
    }
  }
  return scene::validate_scene(scene);
}

Result<Scenario> parse_scenario(std::string_view json_text, const std::filesystem::path& file,
                                const std::filesystem::path& /*assets_dir*/) {
  const std::string where = file.generic_string();
  Scenario scenario;
  scenario.name = file.stem().string();
  scenario.file = file;
  try {
    const json document = json::parse(json_text.begin(), json_text.end());
    ObjectReader r(document, "");
    const int version = detail::read_int(r.require("scenario_version"), "scenario_version");
    if (version != kScenarioVersion)
      fail("scenario_version", "unsupported version " + std::to_string(version) + " (this build reads " +
                                   std::to_string(kScenarioVersion) + ")");
    r.string("description", "");
    if (const json* needs = r.get("requires")) {
      const json& list = detail::expect_array(*needs, "requires");
      for (std::size_t i = 0; i < list.size(); ++i)
        scenario.requires_paths.push_back(file.parent_path() / detail::read_string(list[i], detail::index_path("requires", i)));
    }
    scenario.scene = read_scene_field(r.require("scene"), file, "scene");
    if (const json* o = r.get("overrides")) {
      if (Status s = apply_overrides(scenario.scene, read_overrides(*o, "overrides")); !s) fail("overrides", s.message());
    }
    const int first = scenario.scene.output.first_frame;
    const int last = scene::last_frame(scenario.scene.output);
    scenario.checkpoints = r.get("checkpoints") ? read_frames(*r.get("checkpoints"), "checkpoints") : std::vector<int>{first};
    const json& checks = detail::expect_array(r.require("checks"), "checks");
    std::set<std::string> names;
    for (std::size_t i = 0; i < checks.size(); ++i) {
      const std::string path = detail::index_path("checks", i);
      Check check = read_check(checks[i], path);
      if (!names.insert(check.name).second) fail(path + ".name", "duplicate check name \"" + check.name + "\"");
      if (check.frames.empty()) check.frames = scenario.checkpoints;
      for (int frame : check.frames)
        if (frame < first || frame > last)
          fail(path + ".frames", "frame " + std::to_string(frame) + " outside the scene's range " + std::to_string(first) +
                                     ".." + std::to_string(last));
      if (check.type == CheckType::temporal && check.frames.size() < 2)
        fail(path + ".frames", "a temporal check needs at least two frames");
      scenario.checks.push_back(std::move(check));
    }
    if (scenario.checks.empty()) fail("checks", "needs at least one check");
    r.finish();
  } catch (const detail::FieldError& e) {
    return make_error(where + ": " + (e.path.empty() ? "" : e.path + ": ") + e.message);
  } catch (const json::exception& e) {
    return make_error(where + ": invalid JSON: " + e.what());
  }
  return scenario;
}

Result<Scenario> load_scenario(const std::filesystem::path& file, const std::filesystem::path& assets_dir) {
  auto bytes = read_file(file, scene::kMaxSceneFileBytes);
  if (!bytes) return bytes.error();
  return parse_scenario(std::string_view(reinterpret_cast<const char*>(bytes->data()), bytes->size()), file, assets_dir);
}

Result<std::vector<Scenario>> load_scenarios(const std::vector<std::filesystem::path>& inputs,
                                             const std::filesystem::path& assets_dir) {
  std::vector<std::filesystem::path> files;
  for (const auto& input : inputs) {
    std::error_code error;
    if (std::filesystem::is_directory(input, error)) {
      for (const auto& entry : std::filesystem::directory_iterator(input)) {
        if (entry.path().extension() != ".json") continue;
        auto bytes = read_file(entry.path(), scene::kMaxSceneFileBytes);
        if (!bytes) return bytes.error();
        const std::string_view text(reinterpret_cast<const char*>(bytes->data()), bytes->size());
        if (text.find("\"scenario_version\"") != std::string_view::npos) files.push_back(entry.path());
      }
    } else if (std::filesystem::exists(input, error)) {
      files.push_back(input);
    } else {
      return make_error(input.string() + ": no such scenario file or folder");
    }
  }
  std::sort(files.begin(), files.end(), [](const auto& a, const auto& b) { return a.stem() < b.stem(); });
  std::vector<Scenario> scenarios;
  std::set<std::string> names;
  for (const auto& file : files) {
    auto scenario = load_scenario(file, assets_dir);
    if (!scenario) return scenario.error();
    if (!names.insert(scenario->name).second) return make_error(file.string() + ": a second scenario named " + scenario->name);
    scenarios.push_back(std::move(*scenario));
  }
  if (scenarios.empty()) return make_error("no scenario files found");
  return scenarios;
}

}  // namespace proxygi::regress
