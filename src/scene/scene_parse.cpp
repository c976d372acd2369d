#include "scene/scene_parse.h"

#include <set>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "base/atomic_file.h"
#include "base/log.h"
#include "scene/json_reader.h"
#include "settings/fields.h"
#include "scene/scene_names.h"
#include "scene/scene_validate.h"

namespace proxygi::scene {
namespace {

using nlohmann::json;
using detail::fail;
using detail::ObjectReader;

Transform read_transform(const json& value, const std::string& path) {
  ObjectReader r(value, path);
  Transform t;
  t.translation = r.vec3("translation", t.translation);
  const json* euler = r.get("rotation_degrees");
  const json* quat = r.get("rotation_quaternion");
  if (euler != nullptr && quat != nullptr) {
    fail(r.field("rotation_quaternion"), "give rotation_degrees or rotation_quaternion, not both");
  }
  if (euler != nullptr) {
    t.rotation.form = Rotation::Form::euler_degrees;
    t.rotation.euler_degrees = detail::read_vec3(*euler, r.field("rotation_degrees"));
  } else if (quat != nullptr) {
    const glm::vec4 xyzw = detail::read_vec4(*quat, r.field("rotation_quaternion"));
    t.rotation.form = Rotation::Form::quaternion;
    t.rotation.quaternion = glm::quat(xyzw.w, xyzw.x, xyzw.y, xyzw.z);
  }
  if (const json* scale = r.get("scale")) {
    if (scale->is_number()) {
      t.scale = glm::vec3(detail::read_float(*scale, r.field("scale")));
    } else if (scale->is_array()) {
      t.scale = detail::read_vec3(*scale, r.field("scale"));
    } else {
      fail(r.field("scale"), "expected a number or an array of 3 numbers");
    }
  }
  r.finish();
  return t;
}

WalkPath read_walk_path(const json& value, const std::string& path) {
  ObjectReader r(value, path);
  WalkPath p;
  p.start = detail::read_vec3(r.require("start"), r.field("start"));
  p.end = detail::read_vec3(r.require("end"), r.field("end"));
  p.speed = r.number("speed", p.speed);
  p.repeat = r.enumeration("repeat", p.repeat, names::kRepeat);
  r.finish();
  return p;
}

ClipRef read_clip(const json& clip, const std::string& path) {
  if (clip.is_string()) return clip.get<std::string>();
  if (clip.is_number_integer()) return detail::read_int(clip, path);
  fail(path, "expected a string or an integer");
}

ClipSegment read_segment(const json& value, const std::string& path) {
  ObjectReader r(value, path);
  ClipSegment s;
  s.clip = read_clip(r.require("clip"), r.field("clip"));
  s.start_s = detail::read_double(r.require("start"), r.field("start"));
  const json* duration = r.get("duration");
  const json* repeat = r.get("repeat");
  if (duration != nullptr && repeat != nullptr) fail(r.field("repeat"), "give duration or repeat, not both");
  if (duration == nullptr && repeat == nullptr) fail(r.field("duration"), "give duration (seconds) or repeat (passes)");
  if (duration != nullptr) s.duration_s = detail::read_double(*duration, r.field("duration"));
  if (repeat != nullptr) s.repeat = detail::read_int(*repeat, r.field("repeat"));
  s.speed = r.number("speed", s.speed);
  s.clip_offset_s = r.number("clip_offset", s.clip_offset_s);
  s.mode = r.enumeration("mode", s.mode, names::kSegmentMode);
  s.crossfade_s = r.number("crossfade", s.crossfade_s);
  r.finish();
  return s;
}

Character read_character(const json& value, const std::string& path, int version) {
  ObjectReader r(value, path);
  Character c;
  c.model = detail::read_string(r.require("model"), r.field("model"));
  if (const json* timeline = r.get("timeline")) {
    const std::string timeline_path = r.field("timeline");
    if (version < 2) fail(timeline_path, "needs schema_version 2 (this file is version " + std::to_string(version) + ")");
    for (const char* key : {"clip", "speed", "time_offset"})
      if (r.has(key)) fail(r.field(key), "not allowed with a timeline (give it per segment)");
    detail::expect_array(*timeline, timeline_path);
    if (timeline->empty()) fail(timeline_path, "needs at least one segment");
    for (std::size_t i = 0; i < timeline->size(); ++i)
      c.timeline.push_back(read_segment((*timeline)[i], detail::index_path(timeline_path, i)));
  }
  if (const json* clip = r.get("clip")) c.clip = read_clip(*clip, r.field("clip"));
  c.speed = r.number("speed", c.speed);
  c.time_offset_s = r.number("time_offset", c.time_offset_s);
  if (const json* t = r.get("transform")) c.transform = read_transform(*t, r.field("transform"));
  if (const json* p = r.get("proxies")) c.proxies = detail::read_string(*p, r.field("proxies"));
  if (r.has("proxy_tolerance")) c.proxy_tolerance = r.number("proxy_tolerance", 0.0f);
  if (r.has("proxy_max_spheres")) c.proxy_max_spheres = r.integer("proxy_max_spheres", 0);
  if (const json* p = r.get("path")) c.path = read_walk_path(*p, r.field("path"));
  r.finish();
  return c;
}

Environment read_environment(const json& value, const std::string& path) {
  ObjectReader r(value, path);
  Environment e;
  e.type = r.enumeration("type", e.type, names::kEnvironmentType);
  e.intensity = r.number("intensity", e.intensity);
  e.rotation_degrees = r.number("rotation_degrees", e.rotation_degrees);
  if (e.type == Environment::Type::map) {
    for (const char* key : {"sun", "sky"}) {
      if (r.has(key)) fail(r.field(key), "only allowed when environment.type is \"sky\"");
    }
    e.map_path = detail::read_string(r.require("path"), r.field("path"));
  } else {
    if (r.has("path")) fail(r.field("path"), "only allowed when environment.type is \"map\"");
    if (const json* sun = r.get("sun")) {
      ObjectReader s(*sun, r.field("sun"));
      e.sun.elevation_degrees = s.number("elevation_degrees", e.sun.elevation_degrees);
      e.sun.azimuth_degrees = s.number("azimuth_degrees", e.sun.azimuth_degrees);
      e.sun.angular_radius_degrees = s.number("angular_radius_degrees", e.sun.angular_radius_degrees);
      e.sun.color = s.vec3("color", e.sun.color);
      e.sun.irradiance = s.number("irradiance", e.sun.irradiance);
      s.finish();
    }
    if (const json* sky = r.get("sky")) {
      ObjectReader s(*sky, r.field("sky"));
      e.sky.zenith_color = s.vec3("zenith_color", e.sky.zenith_color);
      e.sky.horizon_color = s.vec3("horizon_color", e.sky.horizon_color);
      e.sky.below_horizon_color = s.vec3("below_horizon_color", e.sky.below_horizon_color);
      e.sky.radiance = s.number("radiance", e.sky.radiance);
      s.finish();
    }
  }
  r.finish();
  return e;
}

Ground read_ground(const json& value, const std::string& path, const Ground& defaults) {
  ObjectReader r(value, path);
  Ground g = defaults;
  g.enabled = r.boolean("enabled", g.enabled);
  g.size = r.number("size", g.size);
  g.albedo = r.vec3("albedo", g.albedo);
  r.finish();
  return g;
}

StaticMesh read_static_mesh(const json& value, const std::string& path) {
  ObjectReader r(value, path);
  StaticMesh m;
  m.model = detail::read_string(r.require("model"), r.field("model"));
  if (const json* t = r.get("transform")) m.transform = read_transform(*t, r.field("transform"));
  if (const json* a = r.get("albedo")) m.albedo = detail::read_vec3(*a, r.field("albedo"));
  r.finish();
  return m;
}

CameraKey read_camera_key(const json& value, const std::string& path) {
  ObjectReader r(value, path);
  CameraKey k;
  k.time_s = detail::read_float(r.require("time"), r.field("time"));
  k.position = detail::read_vec3(r.require("position"), r.field("position"));
  k.target = detail::read_vec3(r.require("target"), r.field("target"));
  k.fov_degrees = r.number("fov_degrees", k.fov_degrees);
  r.finish();
  return k;
}

Camera read_camera(const json& value, const std::string& path, float default_far_m) {
  ObjectReader r(value, path);
  Camera c;
  c.far_m = default_far_m;
  // No "type": a fixed camera (README, "Scene files").
  const std::string type = r.has("type") ? detail::read_string(*r.get("type"), r.field("type")) : std::string("fixed");
  c.near_m = r.number("near", c.near_m);
  c.far_m = r.number("far", c.far_m);
  if (type == "fixed") {
    FixedCamera f;
    f.position = r.vec3("position", f.position);
    f.target = r.vec3("target", f.target);
    f.up = r.vec3("up", f.up);
    f.fov_degrees = r.number("fov_degrees", f.fov_degrees);
    c.kind = f;
  } else if (type == "orbit") {
    OrbitCamera o;
    o.target = r.vec3("target", o.target);
    o.distance = r.number("distance", o.distance);
    o.elevation_degrees = r.number("elevation_degrees", o.elevation_degrees);
    o.start_azimuth_degrees = r.number("start_azimuth_degrees", o.start_azimuth_degrees);
    o.degrees_per_second = r.number("degrees_per_second", o.degrees_per_second);
    o.fov_degrees = r.number("fov_degrees", o.fov_degrees);
    c.kind = o;
  } else if (type == "follow") {
    FollowCamera f;
    f.character = r.integer("character", f.character);
    f.offset = r.vec3("offset", f.offset);
    f.look_at_height = r.number("look_at_height", f.look_at_height);
    f.smoothing_s = r.number("smoothing", f.smoothing_s);
    f.fov_degrees = r.number("fov_degrees", f.fov_degrees);
    c.kind = f;
  } else if (type == "keyframed") {
    KeyframedCamera k;
    const std::string keys_path = r.field("keys");
    const json& keys = detail::expect_array(r.require("keys"), keys_path);
    for (std::size_t i = 0; i < keys.size(); ++i) {
      k.keys.push_back(read_camera_key(keys[i], detail::index_path(keys_path, i)));
    }
    k.interpolation = r.enumeration("interpolation", k.interpolation, names::kInterpolation);
    k.up = r.vec3("up", k.up);
    c.kind = k;
  } else {
    fail(r.field("type"), "unknown value \"" + type +
                              "\" (expected one of: fixed, orbit, follow, keyframed)");
  }
  r.finish();
  return c;
}

// Every field of the settings table (settings/fields.h), by its kind; unknown keys are refused.
settings::RenderSettings read_render(const json& value, const std::string& path) {
  ObjectReader r(value, path);
  settings::RenderSettings s;
  // The boolean of earlier files still loads (true = proxy, false = none), alone only.
  if (const json* old = r.get("indirect")) {
    const bool on = detail::read_bool(*old, r.field("indirect"));
    if (r.has("indirect_method"))
      fail(r.field("indirect"), "give only \"indirect_method\" (\"indirect\" is its older boolean form)");
    s.indirect_method = on ? settings::IndirectMethod::proxy : settings::IndirectMethod::none;
    log_warning(r.field("indirect") + ": the boolean form of \"indirect_method\", read as \"" +
                (on ? "proxy" : "none") + "\"; write \"indirect_method\" instead");
  }
  for (const settings::Field& field : settings::fields()) {
    const json* v = r.get(field.key);
    if (v == nullptr) continue;
    const std::string where = r.field(field.key);
    switch (field.kind) {
      case settings::FieldKind::boolean: field.set(s, detail::read_bool(*v, where) ? 1.0 : 0.0); break;
      case settings::FieldKind::integer: field.set(s, double(detail::read_int(*v, where))); break;
      case settings::FieldKind::real: {
        if (settings::accepts_names(field) && v->is_string()) {  // "auto", "manual", "balanced", ...
          double named = 0.0;
          if (auto why = settings::value_from_name(field, detail::read_string(*v, where), named)) fail(where, *why);
          field.set(s, named);
          break;
        }
        if (!field.object_key.empty() && v->is_object()) {  // {"target_relative_mse": 0.015}
          ObjectReader o(*v, where);
          const std::string key(field.object_key);
          const double number = double(detail::read_float(o.require(key), o.field(key)));
          if (auto why = settings::check_number(field, number)) fail(o.field(key), *why);
          o.finish();
          field.set(s, number);
          break;
        }
        const double number = double(detail::read_float(*v, where));
        if (settings::value_name(field, number) && settings::check_number(field, number))
          fail(where, *settings::check_number(field, number));
        field.set(s, number);
        break;
      }
      case settings::FieldKind::choice: {
        const std::string text = detail::read_string(*v, where);
        const auto chosen = settings::choice_value(field, text);
        if (!chosen) {
          std::string known;
          for (const settings::Choice& choice : field.choices) {
            if (!known.empty()) known += ", ";
            known += choice.name;
          }
          fail(where, "unknown value \"" + text + "\" (expected one of: " + known + ")");
        }
        field.set(s, double(*chosen));
        break;
      }
    }
  }
  r.finish();
  return s;
}

Output read_output(const json& value, const std::string& path) {
  ObjectReader r(value, path);
  Output o;
  o.width = r.integer("width", o.width);
  o.height = r.integer("height", o.height);
  o.fps = r.number_double("fps", o.fps);
  if (const json* frames = r.get("frames")) {
    ObjectReader f(*frames, r.field("frames"));
    o.first_frame = f.integer("first", o.first_frame);
    const json* last = f.get("last");
    const json* count = f.get("count");
    if (last != nullptr && count != nullptr) fail(f.field("count"), "give last or count, not both");
    if (last != nullptr) {
      const int last_frame = detail::read_int(*last, f.field("last"));
      if (last_frame < o.first_frame) {
        fail(f.field("last"), "must be >= first (" + std::to_string(o.first_frame) + ")");
      }
      o.frame_count = last_frame - o.first_frame + 1;
    } else if (count != nullptr) {
      o.frame_count = detail::read_int(*count, f.field("count"));
    }
    f.finish();
  }
  if (const json* formats = r.get("formats")) {
    const std::string formats_path = r.field("formats");
    detail::expect_array(*formats, formats_path);
    o.formats.clear();
    for (std::size_t i = 0; i < formats->size(); ++i) {
      o.formats.push_back(
          detail::parse_enum((*formats)[i], detail::index_path(formats_path, i), names::kOutputFormat));
    }
  }
  r.finish();
  return o;
}

Scene read_scene(const json& document) {
  ObjectReader r(document, "");
  const json& version = r.require("schema_version");
  if (!version.is_number_integer()) fail("schema_version", "expected an integer");
  const bool in_range = version.is_number_unsigned()
                            ? version.get<std::uint64_t>() >= std::uint64_t(kMinSchemaVersion) &&
                                  version.get<std::uint64_t>() <= std::uint64_t(kSchemaVersion)
                            : version.get<std::int64_t>() >= kMinSchemaVersion && version.get<std::int64_t>() <= kSchemaVersion;
  if (!in_range) {
    fail("schema_version", "unsupported version " + version.dump() + " (this build reads versions " +
                               std::to_string(kMinSchemaVersion) + " to " + std::to_string(kSchemaVersion) + ")");
  }
  const int schema = int(version.get<std::int64_t>());
  Scene scene;
  scene.description = r.string("description", scene.description);
  if (const json* characters = r.get("characters")) {
    detail::expect_array(*characters, "characters");
    for (std::size_t i = 0; i < characters->size(); ++i) {
      scene.characters.push_back(read_character((*characters)[i], detail::index_path("characters", i), schema));
    }
  }
  if (const json* e = r.get("environment")) scene.environment = read_environment(*e, "environment");
  // Without ground.size the ground reaches the horizon, as in the built-in scenes, and without
  // camera.far the far plane lies beyond its edge; a file that sizes its ground keeps the far
  // plane of Camera's default.
  const json* ground = r.get("ground");
  const bool sized_ground = ground != nullptr && ground->is_object() && ground->contains("size");
  scene.ground.size = kHorizonGroundSize;
  if (ground) scene.ground = read_ground(*ground, "ground", scene.ground);
  scene.camera.far_m = sized_ground ? Camera{}.far_m : kHorizonFarM;
  if (const json* meshes = r.get("static_meshes")) {
    detail::expect_array(*meshes, "static_meshes");
    for (std::size_t i = 0; i < meshes->size(); ++i) {
      scene.static_meshes.push_back(read_static_mesh((*meshes)[i], detail::index_path("static_meshes", i)));
    }
  }
  if (const json* c = r.get("camera")) scene.camera = read_camera(*c, "camera", scene.camera.far_m);
  if (const json* s = r.get("render")) scene.render = read_render(*s, "render");
  if (const json* o = r.get("output")) scene.output = read_output(*o, "output");
  r.finish();
  return scene;
}

// Parses JSON refusing duplicate keys (nlohmann would keep the last one silently).
json parse_json_strict(std::string_view text) {
  struct Frame {
    bool is_object = false;
    std::string path;
    std::set<std::string> keys;
    std::string key;        // objects: the key being read
    std::size_t index = 0;  // arrays: the element being read
  };
  std::vector<Frame> stack;
  auto child_path = [&stack]() -> std::string {
    if (stack.empty()) return "";
    const Frame& top = stack.back();
    return top.is_object ? detail::join_path(top.path, top.key) : detail::index_path(top.path, top.index);
  };
  auto element_done = [&stack]() {
    if (!stack.empty() && !stack.back().is_object) ++stack.back().index;
  };
  const json::parser_callback_t callback = [&](int, json::parse_event_t event, json& parsed) {
    switch (event) {
      case json::parse_event_t::object_start:
      case json::parse_event_t::array_start:
        stack.push_back(Frame{event == json::parse_event_t::object_start, child_path(), {}, {}, 0});
        break;
      case json::parse_event_t::key: {
        Frame& top = stack.back();
        top.key = parsed.get<std::string>();
        if (!top.keys.insert(top.key).second) fail(child_path(), "duplicate key");
        break;
      }
      case json::parse_event_t::object_end:
      case json::parse_event_t::array_end:
        stack.pop_back();
        element_done();
        break;
      case json::parse_event_t::value:
        element_done();
        break;
    }
    return true;
  };
  return json::parse(text.begin(), text.end(), callback);
}

}  // namespace

Result<Scene> parse_scene(std::string_view json_text, const std::filesystem::path& scene_file) {
  const std::string file = scene_file.generic_string();
  Scene scene;
  try {
    scene = read_scene(parse_json_strict(json_text));
  } catch (const detail::FieldError& e) {
    return make_error(file + ": " + (e.path.empty() ? "" : e.path + ": ") + e.message);
  } catch (const json::exception& e) {
    // e.what() is "[json.exception.parse_error.101] parse error at line 3, column 5: ...".
    std::string what = e.what();
    if (const auto end = what.find("] "); end != std::string::npos) what = what.substr(end + 2);
    return make_error(file + ": invalid JSON: " + what);
  }
  scene.base_dir = scene_file.parent_path();
  if (Status valid = validate_scene(scene); !valid) return make_error(file + ": " + valid.message());
  return scene;
}

Result<Scene> load_scene(const std::filesystem::path& scene_file) {
  Result<std::vector<std::uint8_t>> bytes = read_file(scene_file, kMaxSceneFileBytes);
  if (!bytes) return bytes.error();
  const std::string_view text(reinterpret_cast<const char*>(bytes->data()), bytes->size());
  return parse_scene(text, scene_file);
}

}  // namespace proxygi::scene
