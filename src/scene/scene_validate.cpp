#include "scene/scene_validate.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>

#include "scene/json_reader.h"
#include "settings/fields.h"
#include "settings/limits.h"
#include "scene/scene_names.h"

namespace proxygi::scene {
namespace {

using detail::fail;
using detail::index_path;
using detail::join_path;

std::string show(double value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

std::string show(const glm::vec3& v) {
  std::ostringstream out;  // not string concatenation: GCC 12 -Wrestrict false positive
  out << "[" << v.x << ", " << v.y << ", " << v.z << "]";
  return out.str();
}

void finite(float value, const std::string& path) {
  if (!std::isfinite(value)) fail(path, "must be a finite number");
}

void finite(const glm::vec3& v, const std::string& path) {
  for (int i = 0; i < 3; ++i) finite(v[i], index_path(path, static_cast<std::size_t>(i)));
}

void positive(float value, const std::string& path) {
  finite(value, path);
  if (!(value > 0.0f)) fail(path, "must be > 0 (got " + show(value) + ")");
}

void non_negative(float value, const std::string& path) {
  finite(value, path);
  if (!(value >= 0.0f)) fail(path, "must be >= 0 (got " + show(value) + ")");
}

void in_range(double value, double low, double high, const std::string& path) {
  if (!std::isfinite(value)) fail(path, "must be a finite number");
  if (value < low || value > high) {
    fail(path, "must be in [" + show(low) + ", " + show(high) + "] (got " + show(value) + ")");
  }
}

void color(const glm::vec3& c, const std::string& path) {
  finite(c, path);
  for (int i = 0; i < 3; ++i) {
    if (c[i] < 0.0f) fail(index_path(path, static_cast<std::size_t>(i)), "must be >= 0 (got " + show(c[i]) + ")");
  }
}

void albedo(const glm::vec3& a, const std::string& path) {
  for (int i = 0; i < 3; ++i) in_range(a[i], 0.0, 1.0, index_path(path, static_cast<std::size_t>(i)));
}

void non_empty(const std::string& text, const std::string& path) {
  if (text.empty()) fail(path, "must not be empty");
}

void fov(float degrees, const std::string& path) { in_range(degrees, 1.0, 179.0, path); }

// eye and target differ, and up is not parallel to the view direction.
void view(const glm::vec3& eye, const glm::vec3& target, const glm::vec3& up,
          const std::string& target_path, const std::string& up_path) {
  const glm::vec3 forward = target - eye;
  if (!(glm::length(forward) > 1e-6f)) fail(target_path, "must differ from the camera position");
  if (!(glm::length(up) > 1e-6f)) fail(up_path, "must not be zero");
  const float sine = glm::length(glm::cross(glm::normalize(forward), glm::normalize(up)));
  if (!(sine > 1e-3f)) fail(up_path, "must not be parallel to the view direction");
}

void validate_transform(const Transform& t, const std::string& path) {
  finite(t.translation, join_path(path, "translation"));
  if (t.rotation.form == Rotation::Form::euler_degrees) {
    finite(t.rotation.euler_degrees, join_path(path, "rotation_degrees"));
  } else {
    const glm::quat& q = t.rotation.quaternion;
    const std::string qpath = join_path(path, "rotation_quaternion");
    for (float c : {q.x, q.y, q.z, q.w}) finite(c, qpath);
    const float length = std::sqrt(q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w);
    if (std::fabs(length - 1.0f) > 1e-3f) fail(qpath, "must have unit length (got " + show(length) + ")");
  }
  for (int i = 0; i < 3; ++i) positive(t.scale[i], join_path(path, "scale"));
}

// What the file alone can say about a timeline; World::load checks repeat-count lengths against
// the clips (world/timeline.h), since those need the clip durations.
void validate_timeline(const std::vector<ClipSegment>& timeline, const std::string& path) {
  for (std::size_t i = 0; i < timeline.size(); ++i) {
    const ClipSegment& s = timeline[i];
    const std::string p = index_path(path, i);
    if (const auto* name = std::get_if<std::string>(&s.clip)) non_empty(*name, join_path(p, "clip"));
    else if (std::get<int>(s.clip) < 0) fail(join_path(p, "clip"), "clip index must be >= 0 (got " + std::to_string(std::get<int>(s.clip)) + ")");
    if (!std::isfinite(s.start_s) || s.start_s < 0.0) fail(join_path(p, "start"), "must be >= 0 (got " + show(s.start_s) + ")");
    if (s.duration_s && !(std::isfinite(*s.duration_s) && *s.duration_s > 0.0))
      fail(join_path(p, "duration"), "must be > 0 (got " + show(*s.duration_s) + ")");
    if (s.repeat && *s.repeat < 1) fail(join_path(p, "repeat"), "must be >= 1 (got " + std::to_string(*s.repeat) + ")");
    positive(s.speed, join_path(p, "speed"));
    if (!std::isfinite(s.clip_offset_s) || s.clip_offset_s < 0.0f) fail(join_path(p, "clip_offset"), "must be >= 0 (got " + show(s.clip_offset_s) + ")");
    if (!std::isfinite(s.crossfade_s) || s.crossfade_s < 0.0f) fail(join_path(p, "crossfade"), "must be >= 0 (got " + show(s.crossfade_s) + ")");
    if (i + 1 == timeline.size() && s.crossfade_s > 0.0f) fail(join_path(p, "crossfade"), "the last segment has nothing to fade into");
    if (i == 0) continue;
    const ClipSegment& previous = timeline[i - 1];
    if (s.start_s < previous.start_s)
      fail(join_path(p, "start"), "segments must be ordered by start (" + show(s.start_s) + " < " + show(previous.start_s) + ")");
    if (previous.duration_s && previous.start_s + *previous.duration_s > s.start_s + 1e-9)
      fail(join_path(p, "start"), "overlaps " + index_path(path, i - 1) + " (which ends at " +
                                      show(previous.start_s + *previous.duration_s) + ", this starts at " + show(s.start_s) + ")");
    if (s.duration_s && previous.crossfade_s > *s.duration_s)
      fail(join_path(index_path(path, i - 1), "crossfade"), "longer than the next segment (" + show(*s.duration_s) + " s)");
  }
}

void validate_character(const Character& c, const std::string& path) {
  validate_timeline(c.timeline, join_path(path, "timeline"));
  non_empty(c.model, join_path(path, "model"));
  if (const auto* name = std::get_if<std::string>(&c.clip)) {
    non_empty(*name, join_path(path, "clip"));
  } else if (std::get<int>(c.clip) < 0) {
    fail(join_path(path, "clip"), "clip index must be >= 0 (got " + std::to_string(std::get<int>(c.clip)) + ")");
  }
  finite(c.speed, join_path(path, "speed"));
  finite(c.time_offset_s, join_path(path, "time_offset"));
  validate_transform(c.transform, join_path(path, "transform"));
  if (c.proxies) non_empty(*c.proxies, join_path(path, "proxies"));
  if (c.proxy_tolerance && !(*c.proxy_tolerance > 0.0f && *c.proxy_tolerance <= 1.0f))
    fail(join_path(path, "proxy_tolerance"), "must be in (0, 1] (got " + show(*c.proxy_tolerance) + ")");
  if (c.proxy_max_spheres && (*c.proxy_max_spheres < 1 || *c.proxy_max_spheres > settings::kMaxProxySpheres))
    fail(join_path(path, "proxy_max_spheres"),
         "must be in [1, " + std::to_string(settings::kMaxProxySpheres) + "] (got " + std::to_string(*c.proxy_max_spheres) + ")");
  if (c.path) {
    const std::string p = join_path(path, "path");
    finite(c.path->start, join_path(p, "start"));
    finite(c.path->end, join_path(p, "end"));
    if (!(glm::length(c.path->end - c.path->start) > 1e-4f)) {
      fail(join_path(p, "end"), "must differ from start " + show(c.path->start));
    }
    positive(c.path->speed, join_path(p, "speed"));
  }
}

bool has_suffix_ignoring_case(const std::string& text, std::string_view suffix) {
  if (text.size() < suffix.size()) return false;
  return std::equal(suffix.begin(), suffix.end(), text.end() - static_cast<std::ptrdiff_t>(suffix.size()),
                    [](char s, char t) { return s == std::tolower(static_cast<unsigned char>(t)); });
}

void validate_environment(const Environment& e) {
  non_negative(e.intensity, "environment.intensity");
  finite(e.rotation_degrees, "environment.rotation_degrees");
  if (e.type == Environment::Type::map) {
    non_empty(e.map_path, "environment.path");
    if (!has_suffix_ignoring_case(e.map_path, ".hdr") && !has_suffix_ignoring_case(e.map_path, ".exr")) {
      fail("environment.path", "expected an .hdr or .exr file (got \"" + e.map_path + "\")");
    }
    return;
  }
  in_range(e.sun.elevation_degrees, -90.0, 90.0, "environment.sun.elevation_degrees");
  finite(e.sun.azimuth_degrees, "environment.sun.azimuth_degrees");
  const float radius = e.sun.angular_radius_degrees;
  finite(radius, "environment.sun.angular_radius_degrees");
  if (!(radius > 0.0f && radius <= 45.0f)) {
    fail("environment.sun.angular_radius_degrees", "must be in (0, 45] (got " + show(radius) + ")");
  }
  color(e.sun.color, "environment.sun.color");
  non_negative(e.sun.irradiance, "environment.sun.irradiance");
  color(e.sky.zenith_color, "environment.sky.zenith_color");
  color(e.sky.horizon_color, "environment.sky.horizon_color");
  color(e.sky.below_horizon_color, "environment.sky.below_horizon_color");
  non_negative(e.sky.radiance, "environment.sky.radiance");
}

void validate_camera(const Camera& camera, int character_count) {
  positive(camera.near_m, "camera.near");
  finite(camera.far_m, "camera.far");
  if (!(camera.far_m > camera.near_m)) {
    fail("camera.far", "must be greater than camera.near (" + show(camera.near_m) + ")");
  }
  if (const auto* f = std::get_if<FixedCamera>(&camera.kind)) {
    finite(f->position, "camera.position");
    finite(f->target, "camera.target");
    finite(f->up, "camera.up");
    view(f->position, f->target, f->up, "camera.target", "camera.up");
    fov(f->fov_degrees, "camera.fov_degrees");
  } else if (const auto* o = std::get_if<OrbitCamera>(&camera.kind)) {
    finite(o->target, "camera.target");
    positive(o->distance, "camera.distance");
    in_range(o->elevation_degrees, -89.0, 89.0, "camera.elevation_degrees");
    finite(o->start_azimuth_degrees, "camera.start_azimuth_degrees");
    finite(o->degrees_per_second, "camera.degrees_per_second");
    fov(o->fov_degrees, "camera.fov_degrees");
  } else if (const auto* w = std::get_if<FollowCamera>(&camera.kind)) {
    if (w->character < 0 || w->character >= character_count) {
      fail("camera.character", "index " + std::to_string(w->character) + " out of range (" +
                                   std::to_string(character_count) + " characters)");
    }
    finite(w->offset, "camera.offset");
    finite(w->look_at_height, "camera.look_at_height");
    view(w->offset, glm::vec3(0.0f, w->look_at_height, 0.0f), glm::vec3(0.0f, 1.0f, 0.0f),
         "camera.offset", "camera.offset");
    non_negative(w->smoothing_s, "camera.smoothing");
    fov(w->fov_degrees, "camera.fov_degrees");
  } else {
    const auto& k = std::get<KeyframedCamera>(camera.kind);
    if (k.keys.empty()) fail("camera.keys", "needs at least one key");
    finite(k.up, "camera.up");
    for (std::size_t i = 0; i < k.keys.size(); ++i) {
      const CameraKey& key = k.keys[i];
      const std::string path = index_path("camera.keys", i);
      finite(key.time_s, join_path(path, "time"));
      if (i > 0 && !(key.time_s > k.keys[i - 1].time_s)) {
        fail(join_path(path, "time"), "key times must increase strictly (previous key at " +
                                          show(k.keys[i - 1].time_s) + ")");
      }
      finite(key.position, join_path(path, "position"));
      finite(key.target, join_path(path, "target"));
      view(key.position, key.target, k.up, join_path(path, "target"), "camera.up");
      fov(key.fov_degrees, join_path(path, "fov_degrees"));
    }
  }
}

void validate_render(const settings::RenderSettings& r) {
  for (const settings::Field& field : settings::fields())
    if (auto reason = settings::check_value(field, field.get(r))) fail(join_path("render", field.key), *reason);
}

void validate_output(const Output& o) {
  using settings::kMaxImageSize, settings::kMinImageSize;
  const std::string sizes = std::to_string(kMinImageSize) + ".." + std::to_string(kMaxImageSize);
  if (o.width < kMinImageSize || o.width > kMaxImageSize) fail("output.width", "must be in " + sizes + " (got " + std::to_string(o.width) + ")");
  if (o.height < kMinImageSize || o.height > kMaxImageSize) {
    fail("output.height", "must be in " + sizes + " (got " + std::to_string(o.height) + ")");
  }
  if (!std::isfinite(o.fps) || !(o.fps > 0.0) || o.fps > 1000.0) {
    fail("output.fps", "must be in (0, 1000] (got " + show(o.fps) + ")");
  }
  if (o.first_frame < 0) fail("output.frames.first", "must be >= 0 (got " + std::to_string(o.first_frame) + ")");
  if (o.frame_count < 1 || o.frame_count > settings::kMaxFrameCount)
    fail("output.frames.count", "must be in 1.." + std::to_string(settings::kMaxFrameCount) + " (got " + std::to_string(o.frame_count) + ")");
  if (o.frame_count > std::numeric_limits<int>::max() - o.first_frame) {
    fail("output.frames.count", "first + count overflows");
  }
  if (o.formats.empty()) fail("output.formats", "must name at least one format");
  for (std::size_t i = 0; i < o.formats.size(); ++i) {
    for (std::size_t j = 0; j < i; ++j) {
      if (o.formats[j] == o.formats[i]) {
        fail(index_path("output.formats", i),
             "repeats \"" + std::string(names::name_of(names::kOutputFormat, o.formats[i])) + "\"");
      }
    }
  }
}

}  // namespace

Status validate_scene(const Scene& scene) {
  try {
    for (std::size_t i = 0; i < scene.characters.size(); ++i) {
      validate_character(scene.characters[i], index_path("characters", i));
    }
    validate_environment(scene.environment);
    positive(scene.ground.size, "ground.size");
    albedo(scene.ground.albedo, "ground.albedo");
    for (std::size_t i = 0; i < scene.static_meshes.size(); ++i) {
      const StaticMesh& m = scene.static_meshes[i];
      const std::string path = index_path("static_meshes", i);
      non_empty(m.model, join_path(path, "model"));
      validate_transform(m.transform, join_path(path, "transform"));
      if (m.albedo) albedo(*m.albedo, join_path(path, "albedo"));
    }
    validate_camera(scene.camera, static_cast<int>(scene.characters.size()));
    validate_render(scene.render);
    validate_output(scene.output);
  } catch (const detail::FieldError& e) {
    return make_error(e.path + ": " + e.message);
  }
  return {};
}

}  // namespace proxygi::scene
