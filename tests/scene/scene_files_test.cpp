// The built-in scenes, the writer, and the committed assets/scenes/*.json.
// To regenerate the committed files after changing a built-in scene, run
//   PROXYGI_UPDATE_SCENE_ASSETS=1 build/<preset>/tests/scene/scene_tests --gtest_filter='*Committed*'
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

#include "scene/camera.h"
#include "scene/character_motion.h"
#include "scene/scene_defaults.h"
#include "scene/scene_parse.h"
#include "scene/scene_validate.h"
#include "scene/scene_write.h"

namespace proxygi::scene {
namespace {

const std::filesystem::path kScenesDir = std::filesystem::path(PROXYGI_SOURCE_DIR) / "assets" / "scenes";

std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// parse(to_json(x)) == x, with base_dir set to where the text claims to come from.
void expect_round_trip(Scene scene, const std::filesystem::path& file) {
  Result<std::string> text = to_json(scene);
  ASSERT_TRUE(text.ok()) << text.message();
  Result<Scene> parsed = parse_scene(*text, file);
  ASSERT_TRUE(parsed.ok()) << parsed.message() << "\n" << *text;
  scene.base_dir = file.parent_path();
  EXPECT_TRUE(*parsed == scene) << *text;
  // Writing again gives the same bytes.
  Result<std::string> again = to_json(*parsed);
  ASSERT_TRUE(again.ok());
  EXPECT_EQ(*again, *text);
}

TEST(SceneFiles, BuiltInScenesAreValid) {
  EXPECT_TRUE(validate_scene(default_scene()).ok()) << validate_scene(default_scene()).message();
  EXPECT_TRUE(validate_scene(crowd_scene()).ok()) << validate_scene(crowd_scene()).message();
}

TEST(SceneFiles, DefaultSceneIsTheDocumentedShot) {
  const Scene s = default_scene();
  ASSERT_EQ(s.characters.size(), 1u);
  EXPECT_TRUE(is_builtin_mannequin(s.characters[0].model));
  EXPECT_EQ(s.characters[0].clip, ClipRef(std::string("walk")));
  ASSERT_TRUE(s.characters[0].path.has_value());
  EXPECT_EQ(s.environment.type, Environment::Type::sky);
  EXPECT_GT(s.environment.sun.irradiance, 0.0f);
  EXPECT_TRUE(s.ground.enabled);
  for (int i = 0; i < 3; ++i) EXPECT_GE(s.ground.albedo[i], 0.7f);  // light ground shows bleeding
  EXPECT_EQ(s.output.width, 512);
  EXPECT_EQ(s.output.height, 512);
  EXPECT_DOUBLE_EQ(s.output.fps, 24.0);
  const double duration = s.output.frame_count / s.output.fps;
  EXPECT_GE(duration, 2.0);
  EXPECT_LE(duration, 10.0);
  // The walk covers its whole path within the shot.
  const WalkPath& path = *s.characters[0].path;
  EXPECT_GE(duration * path.speed, glm::length(path.end - path.start) - 1e-4);
}

// The fixed camera sees the mannequin (feet and head, with some room for swinging arms) at
// every frame of the walk.
TEST(SceneFiles, DefaultCameraFramesTheWholeWalk) {
  const Scene s = default_scene();
  const Character& walker = s.characters[0];
  for (int frame = s.output.first_frame; frame <= last_frame(s.output); ++frame) {
    const double t = frame_time_s(s.output, frame);
    const CameraState camera = evaluate_scene_camera(s, t);
    const glm::vec3 root = character_root_position(walker, t);
    for (const glm::vec3& offset : {glm::vec3(-0.4f, 0.0f, -0.4f), glm::vec3(0.4f, 0.0f, 0.4f),
                                    glm::vec3(-0.4f, 1.9f, 0.0f), glm::vec3(0.4f, 1.9f, 0.0f)}) {
      const glm::vec2 px = project_to_pixel(camera, s.output.width, s.output.height, root + offset);
      EXPECT_GT(px.x, 0.05f * s.output.width) << "frame " << frame;
      EXPECT_LT(px.x, 0.95f * s.output.width) << "frame " << frame;
      EXPECT_GT(px.y, 0.05f * s.output.height) << "frame " << frame;
      EXPECT_LT(px.y, 0.95f * s.output.height) << "frame " << frame;
    }
  }
}

TEST(SceneFiles, CrowdSceneHasTwentyAnimatedMannequinsThatNeverCollide) {
  const Scene s = crowd_scene();
  ASSERT_EQ(s.characters.size(), 20u);
  int walking = 0;
  int running = 0;
  for (const Character& c : s.characters) {
    EXPECT_TRUE(is_builtin_mannequin(c.model));
    ASSERT_TRUE(std::holds_alternative<std::string>(c.clip));
    walking += std::get<std::string>(c.clip) == "walk";
    running += std::get<std::string>(c.clip) == "run";
    EXPECT_TRUE(c.path.has_value());
  }
  EXPECT_EQ(walking, 10);
  EXPECT_EQ(running, 10);
  // Clip phases differ across the crowd.
  std::vector<float> offsets;
  for (const Character& c : s.characters) offsets.push_back(c.time_offset_s);
  std::sort(offsets.begin(), offsets.end());
  EXPECT_GE(std::unique(offsets.begin(), offsets.end()) - offsets.begin(), 5);
  // Roots stay at least 1 m apart and on the ground for the whole shot.
  for (int frame = s.output.first_frame; frame <= last_frame(s.output); ++frame) {
    const double t = frame_time_s(s.output, frame);
    for (std::size_t i = 0; i < s.characters.size(); ++i) {
      const glm::vec3 a = character_root_position(s.characters[i], t);
      EXPECT_LT(std::fabs(a.x), 0.5f * s.ground.size);
      EXPECT_LT(std::fabs(a.z), 0.5f * s.ground.size);
      for (std::size_t j = 0; j < i; ++j) {
        const glm::vec3 b = character_root_position(s.characters[j], t);
        EXPECT_GE(glm::length(a - b), 1.0f) << "characters " << j << " and " << i << " at frame " << frame;
      }
    }
  }
}

TEST(SceneFiles, RoundTripBuiltInScenes) {
  expect_round_trip(default_scene(), "assets/scenes/default.json");
  expect_round_trip(crowd_scene(), "crowd.json");
}

// A scene that uses every optional field and the other forms (quaternion, per-axis scale,
// clip index, map environment, each camera kind, non-round numbers).
TEST(SceneFiles, RoundTripEveryForm) {
  Scene s = default_scene();
  s.description = "odd \"quotes\" and unicode: \xC3\xA9";
  Character c;
  c.model = "hero.glb";
  c.clip = 3;
  c.speed = 0.1f;
  c.time_offset_s = 1.0f / 3.0f;
  c.transform.translation = glm::vec3(0.1f, -2.5e-7f, 123456.78f);
  c.transform.rotation.form = Rotation::Form::quaternion;
  c.transform.rotation.quaternion = glm::normalize(glm::quat(0.3f, 0.1f, -0.7f, 0.2f));
  c.transform.scale = glm::vec3(1.0f, 2.0f, 3.0f);
  c.proxies = "hero.rig.proxies.json";
  s.characters.push_back(c);
  StaticMesh m;
  m.model = "box.glb";
  m.albedo = glm::vec3(0.3f, 0.2f, 0.1f);
  m.transform.rotation.euler_degrees = glm::vec3(90.0f, 0.0f, 12.5f);
  s.static_meshes.push_back(m);
  s.render.tonemap = settings::Tonemap::clamp;
  s.render.exposure_ev = -0.7f;
  s.render.proxy_lod = settings::ProxyLod::automatic;
  s.output.formats = {OutputFormat::mp4, OutputFormat::png, OutputFormat::exr};
  expect_round_trip(s, "a/b.json");

  Camera orbit;
  orbit.kind = OrbitCamera{glm::vec3(0.5f, 1.0f, -0.5f), 6.5f, -10.0f, 33.3f, -7.5f, 55.0f};
  Camera follow;
  follow.kind = FollowCamera{1, glm::vec3(0.0f, 2.0f, 3.0f), 1.1f, 0.0f, 30.0f};
  KeyframedCamera keyframed;
  keyframed.interpolation = KeyframedCamera::Interpolation::linear;
  keyframed.keys = {CameraKey{0.0f, glm::vec3(0, 1, 5), glm::vec3(0, 1, 0), 40.0f},
                    CameraKey{1.7f, glm::vec3(3, 1, 4), glm::vec3(0, 1, 0), 50.0f}};
  Camera keys;
  keys.kind = keyframed;
  for (const Camera& camera : {orbit, follow, keys}) {
    s.camera = camera;
    expect_round_trip(s, "a/b.json");
  }

  // Sun and sky are not written for a map environment: reset them so the round trip applies.
  s.environment = Environment{};
  s.environment.type = Environment::Type::map;
  s.environment.map_path = "studio.hdr";
  s.environment.intensity = 0.8f;
  s.environment.rotation_degrees = 190.0f;
  expect_round_trip(s, "a/b.json");
}

TEST(SceneFiles, WriterRefusesInvalidScenes) {
  Scene s = default_scene();
  s.output.width = 4;
  Result<std::string> text = to_json(s);
  ASSERT_FALSE(text.ok());
  EXPECT_EQ(text.message(), "to_json: output.width: must be in 16..8192 (got 4)");
}

TEST(SceneFiles, WriterRefusesStringsThatAreNotUtf8) {
  Scene s = default_scene();
  s.description = "bad \xFF byte";
  Result<std::string> text = to_json(s);
  ASSERT_FALSE(text.ok());
  EXPECT_EQ(text.message(), "to_json: a string (description, model or path) is not valid UTF-8");
}

// Damaged copies of a real scene file never crash the parser: each is accepted or refused
// with a message naming the file (deterministic mutations: byte flips, truncation, deletions).
TEST(SceneFiles, DamagedFilesAreRefusedCleanly) {
  Result<std::string> original = to_json(crowd_scene());
  ASSERT_TRUE(original.ok());
  std::uint32_t state = 12345u;
  auto next = [&state]() {  // xorshift32
    state ^= state << 13;
    state ^= state >> 17;
    state ^= state << 5;
    return state;
  };
  const char replacements[] = "{}[]\",:0123456789-.eE \\\x00\xFFtrufalsn";
  int refused = 0;
  for (int i = 0; i < 3000; ++i) {
    std::string text = *original;
    const int edits = 1 + int(next() % 3);
    for (int e = 0; e < edits; ++e) {
      const std::size_t at = next() % text.size();
      switch (next() % 3) {
        case 0: text[at] = replacements[next() % (sizeof(replacements) - 1)]; break;
        case 1: text.resize(at); break;
        default: text.erase(at, 1 + next() % 8); break;
      }
      if (text.empty()) break;
    }
    Result<Scene> scene = parse_scene(text, "fuzz.json");
    if (!scene.ok()) {
      ++refused;
      EXPECT_EQ(scene.message().rfind("fuzz.json: ", 0), 0u) << scene.message();
    }
  }
  EXPECT_GT(refused, 1000);  // most damage is caught
}

TEST(SceneFiles, SaveSceneWritesWhatLoadSceneReads) {
  const std::filesystem::path file = std::filesystem::path(PROXYGI_TEST_OUTPUT_DIR) / "scene_save" / "crowd.json";
  std::filesystem::create_directories(file.parent_path());
  ASSERT_TRUE(save_scene(crowd_scene(), file).ok());
  Result<Scene> loaded = load_scene(file);
  ASSERT_TRUE(loaded.ok()) << loaded.message();
  Scene expected = crowd_scene();
  expected.base_dir = file.parent_path();
  EXPECT_TRUE(*loaded == expected);
}

// assets/scenes/*.json are exactly what the code generates (and so parse back to the
// built-ins).
TEST(SceneFiles, CommittedSceneFilesMatchTheBuiltIns) {
  const bool update = std::getenv("PROXYGI_UPDATE_SCENE_ASSETS") != nullptr;
  const std::pair<const char*, Scene> scenes[] = {{"default.json", default_scene()},
                                                  {"crowd.json", crowd_scene()}};
  for (const auto& [name, scene] : scenes) {
    const std::filesystem::path file = kScenesDir / name;
    if (update) {
      ASSERT_TRUE(save_scene(scene, file).ok());
    }
    Result<std::string> generated = to_json(scene);
    ASSERT_TRUE(generated.ok()) << generated.message();
    EXPECT_EQ(read_text(file), *generated) << file << " is stale: regenerate it (see the top of this test file)";
    Result<Scene> loaded = load_scene(file);
    ASSERT_TRUE(loaded.ok()) << loaded.message();
    Scene expected = scene;
    expected.base_dir = kScenesDir;
    EXPECT_TRUE(*loaded == expected) << file;
  }
}

}  // namespace
}  // namespace proxygi::scene
