#include "scene/scene_write.h"

#include <algorithm>
#include <charconv>
#include <string>
#include <system_error>

#include <nlohmann/json.hpp>

#include "base/atomic_file.h"
#include "scene/scene_names.h"
#include "settings/fields.h"
#include "scene/scene_validate.h"

namespace proxygi::scene {
namespace {

using ojson = nlohmann::ordered_json;

// The double whose shortest decimal form is the float's shortest decimal form, so the file
// shows 0.1 rather than 0.10000000149011612 and still reads back to the same float.
ojson number(float value) {
  char buffer[64];
  const auto written = std::to_chars(buffer, buffer + sizeof(buffer), value);
  double shortest = static_cast<double>(value);
  std::from_chars(buffer, written.ptr, shortest);
  return shortest;
}

ojson number(double value) { return value; }

ojson vec(const glm::vec3& v) { return ojson::array({number(v.x), number(v.y), number(v.z)}); }

ojson transform_json(const Transform& t) {
  ojson j = ojson::object();
  j["translation"] = vec(t.translation);
  if (t.rotation.form == Rotation::Form::euler_degrees) {
    j["rotation_degrees"] = vec(t.rotation.euler_degrees);
  } else {
    const glm::quat& q = t.rotation.quaternion;
    j["rotation_quaternion"] = ojson::array({number(q.x), number(q.y), number(q.z), number(q.w)});
  }
  const bool uniform = t.scale.x == t.scale.y && t.scale.y == t.scale.z;
  j["scale"] = uniform ? number(t.scale.x) : vec(t.scale);
  return j;
}

ojson clip_json(const ClipRef& clip) {
  if (const auto* name = std::get_if<std::string>(&clip)) return *name;
  return std::get<int>(clip);
}

ojson segment_json(const ClipSegment& s) {
  ojson j = ojson::object();
  j["clip"] = clip_json(s.clip);
  j["start"] = s.start_s;
  if (s.duration_s) j["duration"] = *s.duration_s;
  if (s.repeat) j["repeat"] = *s.repeat;
  j["speed"] = number(s.speed);
  j["clip_offset"] = number(s.clip_offset_s);
  j["mode"] = std::string(names::name_of(names::kSegmentMode, s.mode));
  j["crossfade"] = number(s.crossfade_s);
  return j;
}

ojson character_json(const Character& c) {
  ojson j = ojson::object();
  j["model"] = c.model;
  if (!c.timeline.empty()) {
    j["timeline"] = ojson::array();
    for (const ClipSegment& s : c.timeline) j["timeline"].push_back(segment_json(s));
  } else {
    j["clip"] = clip_json(c.clip);
    j["speed"] = number(c.speed);
    j["time_offset"] = number(c.time_offset_s);
  }
  j["transform"] = transform_json(c.transform);
  if (c.proxies) j["proxies"] = *c.proxies;
  if (c.proxy_tolerance) j["proxy_tolerance"] = number(*c.proxy_tolerance);
  if (c.proxy_max_spheres) j["proxy_max_spheres"] = *c.proxy_max_spheres;
  if (c.path) {
    j["path"] = {{"start", vec(c.path->start)},
                 {"end", vec(c.path->end)},
                 {"speed", number(c.path->speed)},
                 {"repeat", std::string(names::name_of(names::kRepeat, c.path->repeat))}};
  }
  return j;
}

ojson environment_json(const Environment& e) {
  ojson j = ojson::object();
  j["type"] = std::string(names::name_of(names::kEnvironmentType, e.type));
  j["intensity"] = number(e.intensity);
  j["rotation_degrees"] = number(e.rotation_degrees);
  if (e.type == Environment::Type::map) {
    j["path"] = e.map_path;
    return j;
  }
  j["sun"] = {{"elevation_degrees", number(e.sun.elevation_degrees)},
              {"azimuth_degrees", number(e.sun.azimuth_degrees)},
              {"angular_radius_degrees", number(e.sun.angular_radius_degrees)},
              {"color", vec(e.sun.color)},
              {"irradiance", number(e.sun.irradiance)}};
  j["sky"] = {{"zenith_color", vec(e.sky.zenith_color)},
              {"horizon_color", vec(e.sky.horizon_color)},
              {"below_horizon_color", vec(e.sky.below_horizon_color)},
              {"radiance", number(e.sky.radiance)}};
  return j;
}

ojson camera_json(const Camera& camera) {
  ojson j = ojson::object();
  j["type"] = std::string(names::kCameraType[camera.kind.index()]);
  if (const auto* f = std::get_if<FixedCamera>(&camera.kind)) {
    j["position"] = vec(f->position);
    j["target"] = vec(f->target);
    j["up"] = vec(f->up);
    j["fov_degrees"] = number(f->fov_degrees);
  } else if (const auto* o = std::get_if<OrbitCamera>(&camera.kind)) {
    j["target"] = vec(o->target);
    j["distance"] = number(o->distance);
    j["elevation_degrees"] = number(o->elevation_degrees);
    j["start_azimuth_degrees"] = number(o->start_azimuth_degrees);
    j["degrees_per_second"] = number(o->degrees_per_second);
    j["fov_degrees"] = number(o->fov_degrees);
  } else if (const auto* w = std::get_if<FollowCamera>(&camera.kind)) {
    j["character"] = w->character;
    j["offset"] = vec(w->offset);
    j["look_at_height"] = number(w->look_at_height);
    j["smoothing"] = number(w->smoothing_s);
    j["fov_degrees"] = number(w->fov_degrees);
  } else {
    const auto& k = std::get<KeyframedCamera>(camera.kind);
    ojson keys = ojson::array();
    for (const CameraKey& key : k.keys) {
      keys.push_back({{"time", number(key.time_s)},
                      {"position", vec(key.position)},
                      {"target", vec(key.target)},
                      {"fov_degrees", number(key.fov_degrees)}});
    }
    j["keys"] = keys;
    j["interpolation"] = std::string(names::name_of(names::kInterpolation, k.interpolation));
    j["up"] = vec(k.up);
  }
  j["near"] = number(camera.near_m);
  j["far"] = number(camera.far_m);
  return j;
}

ojson render_json(const settings::RenderSettings& r) {
  ojson j = ojson::object();
  for (const settings::Field& field : settings::fields()) {
    const double value = field.get(r);
    const std::string key(field.key);
    switch (field.kind) {
      case settings::FieldKind::boolean: j[key] = value != 0.0; break;
      case settings::FieldKind::integer: j[key] = int(value); break;
      case settings::FieldKind::real:
        if (auto name = settings::value_name(field, value)) j[key] = std::string(*name);
        else if (!field.object_key.empty()) j[key][std::string(field.object_key)] = number(float(value));
        else j[key] = number(float(value));
        break;
      case settings::FieldKind::choice: j[key] = std::string(settings::choice_name(field, int(value))); break;
    }
  }
  return j;
}

ojson output_json(const Output& o) {
  ojson formats = ojson::array();
  for (OutputFormat f : o.formats) formats.push_back(std::string(names::name_of(names::kOutputFormat, f)));
  return {{"width", o.width},
          {"height", o.height},
          {"fps", number(o.fps)},
          {"frames", {{"first", o.first_frame}, {"count", o.frame_count}}},
          {"formats", formats}};
}

// Like ordered_json::dump(2), but arrays of scalars stay on one line ("[0.0, 1.0, 0.0]") so
// vectors and colors read as one value.
void print(const ojson& j, int indent, std::string& out) {
  const std::string pad(static_cast<std::size_t>(indent) + 2, ' ');
  if (j.is_object()) {
    if (j.empty()) {
      out += "{}";
      return;
    }
    out += "{\n";
    bool first = true;
    for (const auto& [key, value] : j.items()) {
      if (!first) out += ",\n";
      first = false;
      out += pad + ojson(key).dump() + ": ";
      print(value, indent + 2, out);
    }
    out += "\n" + std::string(static_cast<std::size_t>(indent), ' ') + "}";
  } else if (j.is_array()) {
    const bool scalars = std::none_of(j.begin(), j.end(), [](const ojson& e) { return e.is_structured(); });
    if (j.empty() || scalars) {
      out += "[";
      for (std::size_t i = 0; i < j.size(); ++i) out += (i == 0 ? "" : ", ") + j[i].dump();
      out += "]";
      return;
    }
    out += "[\n";
    for (std::size_t i = 0; i < j.size(); ++i) {
      out += (i == 0 ? "" : ",\n") + pad;
      print(j[i], indent + 2, out);
    }
    out += "\n" + std::string(static_cast<std::size_t>(indent), ' ') + "]";
  } else {
    out += j.dump();
  }
}

}  // namespace

Result<std::string> to_json(const Scene& scene) {
  if (Status valid = validate_scene(scene); !valid) return make_error("to_json: " + valid.message());
  ojson j = ojson::object();
  // Version 1 unless a character has a timeline, so version-1 scenes write back unchanged.
  const bool timelines = std::any_of(scene.characters.begin(), scene.characters.end(),
                                     [](const Character& c) { return !c.timeline.empty(); });
  j["schema_version"] = timelines ? kSchemaVersion : kMinSchemaVersion;
  j["description"] = scene.description;
  j["characters"] = ojson::array();
  for (const Character& c : scene.characters) j["characters"].push_back(character_json(c));
  j["environment"] = environment_json(scene.environment);
  j["ground"] = {{"enabled", scene.ground.enabled},
                 {"size", number(scene.ground.size)},
                 {"albedo", vec(scene.ground.albedo)}};
  j["static_meshes"] = ojson::array();
  for (const StaticMesh& m : scene.static_meshes) {
    ojson mesh = {{"model", m.model}, {"transform", transform_json(m.transform)}};
    if (m.albedo) mesh["albedo"] = vec(*m.albedo);
    j["static_meshes"].push_back(mesh);
  }
  j["camera"] = camera_json(scene.camera);
  j["render"] = render_json(scene.render);
  j["output"] = output_json(scene.output);
  std::string text;
  try {
    print(j, 0, text);
  } catch (const nlohmann::json::exception&) {  // dump() refuses strings that are not UTF-8
    return make_error("to_json: a string (description, model or path) is not valid UTF-8");
  }
  return text + "\n";
}

Status save_scene(const Scene& scene, const std::filesystem::path& path) {
  Result<std::string> text = to_json(scene);
  if (!text) return make_error(path.generic_string() + ": " + text.message());
  return write_file_atomically(path, std::string_view(*text));
}

}  // namespace proxygi::scene
