#pragma once
// Scene: what `proxygi record`, `view`, `regress`, `bench` and `reference` render, as plain
// structs with defaults. Read from JSON by scene_parse.h (which validates every field), written
// back by scene_write.h, built in code by scene_defaults.h.
//
// Conventions: glTF space (right-handed, +Y up, meters, seconds); angles in the file and in
// these structs are degrees unless a name says radians; colors are linear RGB (never sRGB);
// GLM matrices are column-major. Paths are kept as written in the file (relative to
// Scene::base_dir, the scene file's folder) so a scene writes back unchanged; resolve them with
// resolve_scene_path(). The model "builtin:mannequin" names the bundled assets/mannequin.glb,
// which the renderer resolves (resolve_model_path below does it given the assets folder).
//
// Usage:
//   Result<Scene> scene = load_scene("shots/walk.json");
//   if (!scene) return scene.error();
//   for (const Character& c : scene->characters) load(resolve_model_path(*scene, c.model, assets));
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include "settings/render_settings.h"

namespace proxygi::scene {

// The newest schema version this build reads and writes. Version 2 adds per-character clip
// timelines (Character::timeline); version 1 files still load (kMinSchemaVersion), and a scene
// without timelines is written as version 1 so older files round-trip unchanged.
inline constexpr int kSchemaVersion = 2;
inline constexpr int kMinSchemaVersion = 1;
inline constexpr std::string_view kBuiltinMannequin = "builtin:mannequin";

// Rotation in one of two forms, kept as written so files round-trip.
//  - euler_degrees (x, y, z): rotate about +X first, then +Y, then +Z, all about the fixed world
//    axes (extrinsic XYZ), i.e. R = Rz(z) * Ry(y) * Rx(x). Positive angles are counter-clockwise
//    looking down the axis toward the origin (right-hand rule).
//  - quaternion: glm::quat (w, x, y, z in the constructor; [x, y, z, w] in the file, as glTF).
//    Validated to unit length within 1e-3; to_quat() renormalizes.
struct Rotation {
  enum class Form { euler_degrees, quaternion };
  Form form = Form::euler_degrees;
  glm::vec3 euler_degrees{0.0f};
  glm::quat quaternion{1.0f, 0.0f, 0.0f, 0.0f};

  glm::quat to_quat() const;
  bool operator==(const Rotation&) const = default;
};

// Placement of a model in the world: to_matrix() = T * R * S (scale first), as glTF nodes.
struct Transform {
  glm::vec3 translation{0.0f};  // meters
  Rotation rotation;
  glm::vec3 scale{1.0f};        // per axis, each > 0; written as one number when uniform

  glm::mat4 to_matrix() const;
  bool operator==(const Transform&) const = default;
};

// Straight-line root motion for clips that animate in place. At scene time t the root travels
// s = speed * t meters from `start` toward `end` (t < 0 is treated as 0); at the end it stops
// (`none`), jumps back to start (`loop`) or walks back (`ping_pong`). The character turns about
// +Y to face its direction of travel; glTF characters face +Z, so +Z is mapped onto the travel
// direction projected on the ground plane. See character_motion.h.
struct WalkPath {
  enum class Repeat { none, loop, ping_pong };
  glm::vec3 start{0.0f};  // meters, world space
  glm::vec3 end{0.0f};    // meters, world space; must differ from start
  float speed = 1.0f;     // meters per second, > 0
  Repeat repeat = Repeat::none;
  bool operator==(const WalkPath&) const = default;
};

// A clip is named (glTF animation name) or indexed (glTF animation index, >= 0).
using ClipRef = std::variant<std::string, int>;

// One segment of a character's clip timeline (schema version 2). From scene time `start_s` the
// segment plays `clip` at clip time clip_offset_s + speed * (t - start_s), wrapped by `mode`
// (loop: modulo the clip duration; once: clamped to it; ping_pong: forward then backward).
// It lasts `duration_s` seconds, or `repeat` passes through the clip (repeat * clip duration /
// speed; a ping-pong pass is there and back). Give one of the two. `crossfade_s` > 0 blends
// this segment into the next over the first crossfade_s seconds of the next one (anim::BlendJob,
// weight (t - next.start) / crossfade_s); the outgoing segment keeps playing by its mode
// meanwhile. Before the first segment the character holds its first pose; in a gap and after the
// last segment it holds the previous segment's end pose. Segments are ordered by start and may
// not overlap (a segment's end, start + length, must be <= the next start); see world/timeline.h.
struct ClipSegment {
  enum class Mode { loop, once, ping_pong };
  ClipRef clip{std::in_place_type<int>, 0};
  double start_s = 0.0;                 // scene seconds, >= 0
  std::optional<double> duration_s;     // seconds, > 0
  std::optional<int> repeat;            // passes, >= 1
  float speed = 1.0f;                   // clip seconds per scene second, > 0
  float clip_offset_s = 0.0f;           // clip time at the segment's start, >= 0
  Mode mode = Mode::loop;
  float crossfade_s = 0.0f;             // >= 0; must be 0 on the last segment
  bool operator==(const ClipSegment&) const = default;
};

struct Character {
  std::string model;  // glTF/GLB path relative to the scene folder, or "builtin:mannequin"
  ClipRef clip{std::in_place_type<int>, 0};
  float speed = 1.0f;          // playback rate: clip seconds per scene second (finite)
  float time_offset_s = 0.0f;  // clip time at scene time 0: clip_t = time_offset_s + speed * t
  Transform transform;         // model space -> world (or -> path frame when `path` is set)
  // Proxy rig (*.proxies.json) relative to the scene folder; when absent the rig is cached
  // next to the model (default_proxy_path).
  std::optional<std::string> proxies;
  // Fit settings of the cached rig (proxies/fit.h FitOptions; defaults 0.05 and 96). A rig named
  // in `proxies` is used as it was made, whatever these say.
  std::optional<float> proxy_tolerance;  // relative to the bind-pose diagonal, (0, 1]
  std::optional<int> proxy_max_spheres;  // [1, settings::kMaxProxySpheres]
  std::optional<WalkPath> path;
  // Schema version 2: clip segments over scene time. When non-empty it replaces clip, speed and
  // time_offset (which the file may then not give).
  std::vector<ClipSegment> timeline;
  bool operator==(const Character&) const = default;
};

// Analytic sky with a sun; see environment.h for the radiance formula.
struct Sun {
  float elevation_degrees = 45.0f;  // above the horizon, [-90, 90]
  // Azimuth about +Y: 0 puts the sun toward +Z, 90 toward +X. Any finite value.
  float azimuth_degrees = 0.0f;
  float angular_radius_degrees = 2.0f;  // disc half-angle, (0, 45]; the real sun is ~0.27
  glm::vec3 color{1.0f, 0.96f, 0.9f};   // linear RGB tint, each >= 0
  // Irradiance from the whole disc onto a surface facing the sun, per unit of color (>= 0; 0
  // removes the sun). Independent of the radius: the disc radiance is
  // irradiance / (pi * sin^2(radius)).
  float irradiance = 3.0f;
  bool operator==(const Sun&) const = default;
};

struct Sky {
  glm::vec3 zenith_color{0.25f, 0.45f, 0.85f};   // linear RGB radiance straight up, >= 0
  glm::vec3 horizon_color{0.75f, 0.85f, 1.0f};   // at the horizon, >= 0
  glm::vec3 below_horizon_color{0.3f, 0.28f, 0.25f};  // uniform below the horizon (distant ground), >= 0
  float radiance = 0.5f;  // multiplies the three colors, >= 0
  bool operator==(const Sky&) const = default;
};

// Environment lighting: the analytic sky, or an equirectangular HDR/EXR image (mapping in
// environment.h). `intensity` scales either; the whole environment is rotated by
// rotation_degrees about +Y (right-hand rule: positive turns +Z toward +X).
struct Environment {
  enum class Type { sky, map };
  Type type = Type::sky;
  Sun sun;                 // used when type == sky
  Sky sky;                 // used when type == sky
  std::string map_path;    // used when type == map: *.hdr or *.exr, relative to the scene folder
  float intensity = 1.0f;  // >= 0
  float rotation_degrees = 0.0f;
  bool operator==(const Environment&) const = default;
};

// The ground of the built-in scenes and of every scene file without ground.size: 2 km, seen up
// to a far plane of 1.5 km (unless the file gives camera.far), so it meets the horizon: no edge
// and no band of the sky's below-horizon colour. Scenes built in code keep Ground's 20 m.
inline constexpr float kHorizonGroundSize = 2000.0f;  // meters, edge length
inline constexpr float kHorizonFarM = 1500.0f;        // meters, camera far plane

// A square in the y = 0 plane centered at the origin.
struct Ground {
  bool enabled = true;
  float size = 20.0f;                 // edge length, meters, > 0
  glm::vec3 albedo{0.8f, 0.8f, 0.8f}; // linear RGB, each in [0, 1]
  bool operator==(const Ground&) const = default;
};

struct StaticMesh {
  std::string model;  // glTF/GLB path relative to the scene folder
  Transform transform;
  std::optional<glm::vec3> albedo;  // replaces every material's base color, each in [0, 1]
  bool operator==(const StaticMesh&) const = default;
};

// Camera kinds. Every kind has near/far clip distances (meters, 0 < near < far); fov is the
// vertical field of view in degrees, [1, 179]. Evaluate with camera.h.
struct FixedCamera {
  glm::vec3 position{0.0f, 1.5f, 5.0f};
  glm::vec3 target{0.0f, 1.0f, 0.0f};  // must differ from position
  glm::vec3 up{0.0f, 1.0f, 0.0f};      // not parallel to target - position
  float fov_degrees = 45.0f;
  bool operator==(const FixedCamera&) const = default;
};

// Circles `target` at `distance`; azimuth(t) = start_azimuth_degrees + degrees_per_second * t,
// measured like the sun's (0: camera on the +Z side of the target, 90: +X side).
struct OrbitCamera {
  glm::vec3 target{0.0f, 1.0f, 0.0f};
  float distance = 5.0f;                // meters, > 0
  float elevation_degrees = 20.0f;      // above the target's horizontal plane, [-89, 89]
  float start_azimuth_degrees = 0.0f;
  float degrees_per_second = 30.0f;     // positive: counter-clockwise seen from above
  float fov_degrees = 45.0f;
  bool operator==(const OrbitCamera&) const = default;
};

// Follows a character's root: eye = root + offset, target = root + (0, look_at_height, 0), where
// root is the box-filtered root position over [t - smoothing_s, t] (0: no smoothing). The
// filter is stateless so any frame renders the same alone or in a sequence (shards).
struct FollowCamera {
  int character = 0;                       // index into Scene::characters
  glm::vec3 offset{0.0f, 1.5f, 4.0f};      // meters, world axes; must not be (0, look_at_height, 0)
  float look_at_height = 1.0f;             // meters above the root
  float smoothing_s = 0.5f;                // seconds, >= 0
  float fov_degrees = 45.0f;
  bool operator==(const FollowCamera&) const = default;
};

struct CameraKey {
  float time_s = 0.0f;
  glm::vec3 position{0.0f, 1.5f, 5.0f};
  glm::vec3 target{0.0f, 1.0f, 0.0f};  // must differ from position
  float fov_degrees = 45.0f;
  bool operator==(const CameraKey&) const = default;
};

// Keys with strictly increasing times. Before the first key and after the last the camera holds
// that key. Position and target interpolate linearly or with Catmull-Rom (a cubic Hermite through
// the keys, tangents from central differences in time, one-sided at the ends); fov is always
// linear so it cannot overshoot.
struct KeyframedCamera {
  enum class Interpolation { linear, catmull_rom };
  std::vector<CameraKey> keys;  // at least one
  Interpolation interpolation = Interpolation::catmull_rom;
  glm::vec3 up{0.0f, 1.0f, 0.0f};
  bool operator==(const KeyframedCamera&) const = default;
};

struct Camera {
  std::variant<FixedCamera, OrbitCamera, FollowCamera, KeyframedCamera> kind;
  float near_m = 0.05f;
  float far_m = 200.0f;
  bool operator==(const Camera&) const = default;
};

// The render settings (method, SH order, k, η, τ, ...) are settings::RenderSettings: one
// definition shared by the scene file, the GPU frame, the chart and the viewer.

enum class OutputFormat { png, exr, mp4 };

// Frame f (first_frame <= f < first_frame + frame_count) shows scene time f / fps.
struct Output {
  int width = 512;    // pixels, settings::kMinImageSize..kMaxImageSize
  int height = 512;   // pixels, settings::kMinImageSize..kMaxImageSize
  double fps = 24.0;  // frames per second, (0, 1000]
  int first_frame = 0;   // >= 0
  int frame_count = 96;  // 1..settings::kMaxFrameCount; the file may give "last" (inclusive) instead
  std::vector<OutputFormat> formats{OutputFormat::png};  // non-empty, no repeats
  bool operator==(const Output&) const = default;
};

struct Scene {
  std::string description;  // free text, shown by tools
  std::vector<Character> characters;
  Environment environment;
  Ground ground;
  std::vector<StaticMesh> static_meshes;
  Camera camera;
  settings::RenderSettings render;
  Output output;
  // Folder of the scene file that relative paths resolve against; not written to the file.
  // Empty for scenes built in code (paths then resolve against the working directory).
  std::filesystem::path base_dir;
  bool operator==(const Scene&) const = default;
};

// Scene time of frame `frame` in seconds.
double frame_time_s(const Output& output, int frame);
int last_frame(const Output& output);  // inclusive

// A path from the file made absolute-or-relative against the scene folder (absolute paths are
// kept). Not for "builtin:" models.
std::filesystem::path resolve_scene_path(const Scene& scene, const std::string& path);
bool is_builtin_mannequin(std::string_view model);
// A command-line argument naming the mannequin: "mannequin" or "builtin:mannequin" when no file
// of that name exists (a file wins). Every command (record, fit, view ...) reads it this way.
bool names_the_mannequin(const std::string& argument);
// The model file to load: assets_dir / "mannequin.glb" for the built-in, else resolved.
std::filesystem::path resolve_model_path(const Scene& scene, const std::string& model,
                                         const std::filesystem::path& assets_dir);
// The rig cached next to a model: "dir/hero.glb" -> "dir/hero.proxies.json".
std::filesystem::path default_proxy_path(const std::filesystem::path& model_file);
// The rig for a character: its `proxies` resolved, or default_proxy_path of its model.
std::filesystem::path resolve_proxy_path(const Scene& scene, const Character& character,
                                         const std::filesystem::path& assets_dir);

}  // namespace proxygi::scene
