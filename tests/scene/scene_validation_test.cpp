// Each validation rule refuses bad input with a message that starts with the file and the
// field path. Table-driven: every row patches one field of a valid scene.
#include <gtest/gtest.h>

#include <string>

#include <nlohmann/json.hpp>

#include "scene/scene_parse.h"
#include "scene/scene_validate.h"

namespace proxygi::scene {
namespace {

using nlohmann::json;

// A valid scene that every row starts from; the character and camera are filled in per row.
constexpr const char* kBase = R"({
  "schema_version": 1,
  "static_meshes": [{"model": "m.glb"}],
  "camera": {"type": "fixed"}
})";
constexpr const char* kBaseCharacter =
    R"({"model": "a.glb", "path": {"start": [0, 0, 0], "end": [1, 0, 0]}})";

struct Case {
  const char* scene_patch;      // JSON merge patch (RFC 7386) applied to kBase; null deletes
  const char* character_patch;  // merge patch applied to kBaseCharacter (characters[0])
  const char* expected;         // the message must start with "scene.json: " + expected
};

const Case kCases[] = {
    // Schema version and document shape.
    {R"({"schema_version": 3})", "{}", "schema_version: unsupported version 3 (this build reads versions 1 to 2)"},
    {R"({"schema_version": null})", "{}", "schema_version: required field is missing"},
    {R"({"schema_version": "1"})", "{}", "schema_version: expected an integer"},
    {R"({"camrea": {}})", "{}", "camrea: unknown key (did you mean \"camera\"?)"},
    {R"({"characters": {}})", nullptr, "characters: expected an array, got an object"},
    {R"({"description": 3})", "{}", "description: expected a string, got an integer"},
    // Characters.
    {"{}", R"({"clip": true})", "characters[0].clip: expected a string or an integer"},
    {"{}", R"({"clip": 1.5})", "characters[0].clip: expected a string or an integer"},
    {"{}", R"({"clip": -1})", "characters[0].clip: clip index must be >= 0"},
    {"{}", R"({"clip": ""})", "characters[0].clip: must not be empty"},
    {"{}", R"({"model": null})", "characters[0].model: required field is missing"},
    {"{}", R"({"model": ""})", "characters[0].model: must not be empty"},
    {"{}", R"({"speed": "fast"})", "characters[0].speed: expected a number, got a string"},
    {"{}", R"({"time_offset": null, "time_ofset": 1})", "characters[0].time_ofset: unknown key (did you mean \"time_offset\"?)"},
    {"{}", R"({"trnasform": {}})", "characters[0].trnasform: unknown key (did you mean \"transform\"?)"},
    {"{}", R"({"proxies": ""})", "characters[0].proxies: must not be empty"},
    {"{}", R"({"transform": {"scale": 0}})", "characters[0].transform.scale: must be > 0"},
    {"{}", R"({"transform": {"scale": [1, -1, 1]}})", "characters[0].transform.scale: must be > 0"},
    {"{}", R"({"transform": {"scale": "big"}})", "characters[0].transform.scale: expected a number or an array of 3 numbers"},
    {"{}", R"({"transform": {"rotation_degrees": [0, 0, 0], "rotation_quaternion": [0, 0, 0, 1]}})",
     "characters[0].transform.rotation_quaternion: give rotation_degrees or rotation_quaternion, not both"},
    {"{}", R"({"transform": {"rotation_quaternion": [0, 0, 0, 0]}})", "characters[0].transform.rotation_quaternion: must have unit length"},
    {"{}", R"({"transform": {"rotation_degrees": [1, 2]}})", "characters[0].transform.rotation_degrees: expected an array of 3 numbers"},
    {"{}", R"({"transform": {"translation": [0, 1e39, 0]}})", "characters[0].transform.translation[1]: number out of range"},
    {"{}", R"({"transform": {"translation": [0, "x", 0]}})", "characters[0].transform.translation[1]: expected a number, got a string"},
    {"{}", R"({"path": {"end": [0, 0, 0]}})", "characters[0].path.end: must differ from start"},
    {"{}", R"({"path": {"start": null}})", "characters[0].path.start: required field is missing"},
    {"{}", R"({"path": {"speed": 0}})", "characters[0].path.speed: must be > 0"},
    {"{}", R"({"path": {"repeat": "forever"}})",
     "characters[0].path.repeat: unknown value \"forever\" (expected one of: none, loop, ping_pong)"},
    // Environment.
    {R"({"environment": {"type": "hdr"}})", "{}", "environment.type: unknown value \"hdr\" (expected one of: sky, map)"},
    {R"({"environment": {"intensity": -1}})", "{}", "environment.intensity: must be >= 0"},
    {R"({"environment": {"sun": {"angular_radius_degrees": 0}}})", "{}", "environment.sun.angular_radius_degrees: must be in (0, 45]"},
    {R"({"environment": {"sun": {"angular_radius_degrees": 50}}})", "{}", "environment.sun.angular_radius_degrees: must be in (0, 45]"},
    {R"({"environment": {"sun": {"elevation_degrees": 95}}})", "{}", "environment.sun.elevation_degrees: must be in [-90, 90]"},
    {R"({"environment": {"sun": {"color": [-1, 0, 0]}}})", "{}", "environment.sun.color[0]: must be >= 0"},
    {R"({"environment": {"sun": {"irradiance": -1}}})", "{}", "environment.sun.irradiance: must be >= 0"},
    {R"({"environment": {"sun": {"radius": 1}}})", "{}", "environment.sun.radius: unknown key"},
    {R"({"environment": {"sky": {"radiance": -0.1}}})", "{}", "environment.sky.radiance: must be >= 0"},
    {R"({"environment": {"sky": {"below_horizon_color": [0, 0, -2]}}})", "{}", "environment.sky.below_horizon_color[2]: must be >= 0"},
    {R"({"environment": {"type": "map"}})", "{}", "environment.path: required field is missing"},
    {R"({"environment": {"type": "map", "path": "sky.png"}})", "{}", "environment.path: expected an .hdr or .exr file"},
    {R"({"environment": {"type": "map", "path": "a.hdr", "sun": {}}})", "{}",
     "environment.sun: only allowed when environment.type is \"sky\""},
    {R"({"environment": {"path": "a.hdr"}})", "{}", "environment.path: only allowed when environment.type is \"map\""},
    // Ground and static meshes.
    {R"({"ground": {"size": 0}})", "{}", "ground.size: must be > 0"},
    {R"({"ground": {"albedo": [1.5, 0, 0]}})", "{}", "ground.albedo[0]: must be in [0, 1]"},
    {R"({"ground": {"enabled": "yes"}})", "{}", "ground.enabled: expected true or false, got a string"},
    {R"({"static_meshes": [{"model": "m.glb", "albedo": [0, 0, 2]}]})", "{}", "static_meshes[0].albedo[2]: must be in [0, 1]"},
    {R"({"static_meshes": [{"model": "m.glb", "transform": {"scale": -2}}]})", "{}", "static_meshes[0].transform.scale: must be > 0"},
    // Cameras.
    {R"({"camera": {"type": "dolly"}})", "{}", "camera.type: unknown value \"dolly\""},
    {R"({"camera": {"fov_degrees": 0}})", "{}", "camera.fov_degrees: must be in [1, 179]"},
    {R"({"camera": {"fov_degrees": 180}})", "{}", "camera.fov_degrees: must be in [1, 179]"},
    {R"({"camera": {"near": 0}})", "{}", "camera.near: must be > 0"},
    {R"({"camera": {"near": 1, "far": 0.5}})", "{}", "camera.far: must be greater than camera.near (1)"},
    {R"({"camera": {"position": [0, 1, 0], "target": [0, 1, 0]}})", "{}", "camera.target: must differ from the camera position"},
    {R"({"camera": {"position": [0, 5, 0], "target": [0, 0, 0]}})", "{}", "camera.up: must not be parallel to the view direction"},
    {R"({"camera": {"distance": 3}})", "{}", "camera.distance: unknown key"},
    {R"({"camera": {"type": "orbit", "distance": -1}})", "{}", "camera.distance: must be > 0"},
    {R"({"camera": {"type": "orbit", "elevation_degrees": 90}})", "{}", "camera.elevation_degrees: must be in [-89, 89]"},
    {R"({"camera": {"type": "follow", "character": 5}})", "{}", "camera.character: index 5 out of range (1 characters)"},
    {R"({"camera": {"type": "follow", "smoothing": -1}})", "{}", "camera.smoothing: must be >= 0"},
    {R"({"camera": {"type": "keyframed", "keys": []}})", "{}", "camera.keys: needs at least one key"},
    {R"({"camera": {"type": "keyframed"}})", "{}", "camera.keys: required field is missing"},
    {R"({"camera": {"type": "keyframed", "keys": [{"time": 1, "position": [0, 1, 5], "target": [0, 1, 0]},
                                                   {"time": 1, "position": [0, 1, 4], "target": [0, 1, 0]}]}})",
     "{}", "camera.keys[1].time: key times must increase strictly"},
    {R"({"camera": {"type": "keyframed", "keys": [{"time": 0, "position": [0, 1, 5]}]}})", "{}",
     "camera.keys[0].target: required field is missing"},
    {R"({"camera": {"type": "keyframed", "interpolation": "cubic", "keys": [{"time": 0, "position": [0, 1, 5], "target": [0, 0, 0]}]}})",
     "{}", "camera.interpolation: unknown value \"cubic\""},
    // Render settings.
    {R"({"render": {"sh_order": 7}})", "{}", "render.sh_order: must be in 3..6 (got 7)"},
    {R"({"render": {"sh_order": 2}})", "{}", "render.sh_order: must be in 3..6 (got 2)"},
    {R"({"render": {"sh_order": 4.5}})", "{}", "render.sh_order: expected an integer, got a number"},
    {R"({"render": {"receiver_scale": 3}})", "{}", "render.receiver_scale: must be 1, 2, 4 or 8 (got 3)"},
    {R"({"render": {"shadow_eta": 1}})", "{}", "render.shadow_eta: must be > 1 or \"auto\" (got 1)"},
    {R"({"render": {"shadow_eta": 0}})", "{}", "render.shadow_eta: must be > 1 or \"auto\" (got 0)"},
    {R"({"render": {"shadow_eta": "big"}})", "{}", "render.shadow_eta: unknown value \"big\" (expected a number or \"auto\")"},
    {R"({"render": {"shadow_eta": true}})", "{}", "render.shadow_eta: expected a number"},
    {R"({"render": {"quality": 0}})", "{}", "render.quality: must be > 0 or one of \"manual\", \"draft\", \"balanced\", \"high\" (got 0)"},
    {R"({"render": {"quality": "best"}})", "{}", "render.quality: unknown value \"best\" (expected {\"target_relative_mse\": number}"},
    {R"({"render": {"quality": {"target_relative_mse": 2}}})", "{}", "render.quality.target_relative_mse: must be <= 1"},
    {R"({"render": {"quality": {"target_relative_mse": -0.1}}})", "{}", "render.quality.target_relative_mse: must be > 0"},
    {R"({"render": {"quality": {"target": 0.01}}})", "{}", "render.quality.target_relative_mse: required field is missing"},
    {R"({"render": {"quality": {"target_relative_mse": 0.01, "x": 1}}})", "{}", "render.quality.x: unknown key"},
    {R"({"render": {"quality": {"target_relative_mse": "low"}}})", "{}", "render.quality.target_relative_mse: expected a number"},
    {R"({"render": {"quality": 1.5}})", "{}", "render.quality: must be <= 1"},
    {R"({"render": {"indirect_eta": 0.5}})", "{}", "render.indirect_eta: must be > 1"},
    {R"({"render": {"hyb_tau": 0}})", "{}", "render.hyb_tau: must be > 0"},
    {R"({"render": {"indirect_operator": "fast"}})", "{}", "render.indirect_operator: unknown value \"fast\" (expected one of: point, averaged, exact)"},
    {R"({"render": {"exponential": "ps"}})", "{}", "render.exponential: unknown value \"ps\" (expected one of: hyb, ol)"},
    {R"({"render": {"upsampling": "nearest"}})", "{}", "render.upsampling: unknown value \"nearest\""},
    {R"({"render": {"method": "pixel"}})", "{}", "render.method: unknown value \"pixel\" (expected one of: image, vertex, ao)"},
    {R"({"render": {"static_transfer": "l2"}})", "{}", "render.static_transfer: unknown value \"l2\" (expected one of: l0, ratio, l1)"},
    {R"({"render": {"splat": "mesh"}})", "{}", "render.splat: unknown value \"mesh\""},
    {R"({"render": {"tonemap": "filmic"}})", "{}", "render.tonemap: unknown value \"filmic\" (expected one of: aces, reinhard, clamp)"},
    {R"({"render": {"antialiasing": "msaa4"}})", "{}", "render.antialiasing: unknown value \"msaa4\" (expected one of: off, ssaa2, ssaa4)"},
    {R"({"render": {"antialiasing": 2}})", "{}", "render.antialiasing: expected a string"},
    {R"({"render": {"proxy_lod": "on"}})", "{}", "render.proxy_lod: unknown value \"on\" (expected one of: off, auto)"},
    {R"({"render": {"sh_window": 1}})", "{}", "render.sh_window: expected true or false, got an integer"},
    {R"({"render": {"indirect": false, "indirect_method": "vsgl"}})", "{}", "render.indirect: give only \"indirect_method\" (\"indirect\" is its older boolean form)"},
    {R"({"render": {"indirect": 1}})", "{}", "render.indirect: expected true or false, got an integer"},
    {R"({"render": {"indirect_method": "sg"}})", "{}", "render.indirect_method: unknown value \"sg\" (expected one of: proxy, vsgl, none)"},
    {R"({"render": {"exposure": 1}})", "{}", "render.exposure: unknown key (did you mean \"exposure_ev\"?)"},
    // Output.
    {R"({"output": {"width": 15}})", "{}", "output.width: must be in 16..8192 (got 15)"},
    {R"({"output": {"width": 8193}})", "{}", "output.width: must be in 16..8192 (got 8193)"},
    {R"({"output": {"height": 10}})", "{}", "output.height: must be in 16..8192 (got 10)"},
    {R"({"output": {"fps": 0}})", "{}", "output.fps: must be in (0, 1000]"},
    {R"({"output": {"fps": -24}})", "{}", "output.fps: must be in (0, 1000]"},
    {R"({"output": {"frames": {"first": -1}}})", "{}", "output.frames.first: must be >= 0"},
    {R"({"output": {"frames": {"first": 5, "last": 4}}})", "{}", "output.frames.last: must be >= first (5)"},
    {R"({"output": {"frames": {"count": 0}}})", "{}", "output.frames.count: must be in 1..1000000 (got 0)"},
    {R"({"output": {"frames": {"count": 1000001}}})", "{}", "output.frames.count: must be in 1..1000000 (got 1000001)"},
    {R"({"output": {"frames": {"last": 4, "count": 5}}})", "{}", "output.frames.count: give last or count, not both"},
    {R"({"output": {"formats": []}})", "{}", "output.formats: must name at least one format"},
    {R"({"output": {"formats": ["png", "png"]}})", "{}", "output.formats[1]: repeats \"png\""},
    {R"({"output": {"formats": ["png", "gif"]}})", "{}", "output.formats[1]: unknown value \"gif\" (expected one of: png, exr, mp4)"},
};

std::string build_scene(const Case& c) {
  json scene = json::parse(kBase);
  if (c.character_patch != nullptr) {
    json character = json::parse(kBaseCharacter);
    character.merge_patch(json::parse(c.character_patch));
    scene["characters"] = json::array({character});
  }
  scene.merge_patch(json::parse(c.scene_patch));
  return scene.dump();
}

TEST(SceneValidation, TheBaseSceneIsValid) {
  const Case base{"{}", "{}", ""};
  Result<Scene> scene = parse_scene(build_scene(base), "scene.json");
  EXPECT_TRUE(scene.ok()) << scene.message();
}

TEST(SceneValidation, EachRuleNamesTheField) {
  for (const Case& c : kCases) {
    const std::string text = build_scene(c);
    Result<Scene> scene = parse_scene(text, "scene.json");
    if (scene.ok()) {
      ADD_FAILURE() << "accepted: " << text;
      continue;
    }
    const std::string expected = std::string("scene.json: ") + c.expected;
    EXPECT_EQ(scene.message().rfind(expected, 0), 0u)
        << "message:  " << scene.message() << "\nexpected: " << expected << "\nscene:    " << text;
  }
}

// README "Scene files": a camera without "type" is a fixed camera.
TEST(SceneValidation, ACameraWithoutTypeIsFixed) {
  Result<Scene> scene = parse_scene(R"({"schema_version": 1, "camera": {"position": [0, 2, 6], "fov_degrees": 30}})", "scene.json");
  ASSERT_TRUE(scene.ok()) << scene.message();
  const auto* fixed = std::get_if<FixedCamera>(&scene->camera.kind);
  ASSERT_NE(fixed, nullptr);
  EXPECT_EQ(fixed->position, glm::vec3(0.0f, 2.0f, 6.0f));
  EXPECT_EQ(fixed->fov_degrees, 30.0f);
}

TEST(SceneValidation, DuplicateKeysAreRefused) {
  Result<Scene> scene = parse_scene(R"({"schema_version": 1, "ground": {"size": 1, "size": 2}})", "scene.json");
  ASSERT_FALSE(scene.ok());
  EXPECT_EQ(scene.message(), "scene.json: ground.size: duplicate key");

  scene = parse_scene(R"({"schema_version": 1, "characters": [{"model": "a"}, {"model": "b", "model": "c"}]})",
                      "scene.json");
  ASSERT_FALSE(scene.ok());
  EXPECT_EQ(scene.message(), "scene.json: characters[1].model: duplicate key");
}

TEST(SceneValidation, MalformedDocuments) {
  Result<Scene> scene = parse_scene("{\"schema_version\": 1,}", "scene.json");
  ASSERT_FALSE(scene.ok());
  EXPECT_EQ(scene.message().rfind("scene.json: invalid JSON: parse error at line 1, column 22", 0), 0u)
      << scene.message();

  scene = parse_scene(R"({"schema_version": 1, "ground": {"size": 1e400}})", "scene.json");
  ASSERT_FALSE(scene.ok());
  EXPECT_EQ(scene.message().rfind("scene.json: invalid JSON: number overflow", 0), 0u) << scene.message();

  scene = parse_scene("[1, 2]", "scene.json");
  ASSERT_FALSE(scene.ok());
  EXPECT_EQ(scene.message(), "scene.json: (document): expected an object, got an array");

  scene = parse_scene("", "scene.json");
  ASSERT_FALSE(scene.ok());
  EXPECT_EQ(scene.message().rfind("scene.json: invalid JSON:", 0), 0u) << scene.message();
}

TEST(SceneValidation, ValidateSceneChecksScenesBuiltInCode) {
  Scene scene;
  EXPECT_TRUE(validate_scene(scene).ok());
  scene.render.sh_order = 9;
  Status status = validate_scene(scene);
  ASSERT_FALSE(status.ok());
  EXPECT_EQ(status.message(), "render.sh_order: must be in 3..6 (got 9)");

  scene = Scene{};
  scene.ground.size = std::numeric_limits<float>::quiet_NaN();
  status = validate_scene(scene);
  ASSERT_FALSE(status.ok());
  EXPECT_EQ(status.message(), "ground.size: must be a finite number");
}

}  // namespace
}  // namespace proxygi::scene
