// Every field of the scene file parses into the struct field it documents.
#include <gtest/gtest.h>

#include <string>

#include "scene/scene_parse.h"
#include "scene/scene_write.h"

namespace proxygi::scene {
namespace {

// Every key of schema version 1 with a non-default value (fixed camera; the other camera kinds
// and the map environment are below).
constexpr const char* kFullScene = R"({
  "schema_version": 1,
  "description": "every field",
  "characters": [
    {
      "model": "chars/hero.glb",
      "clip": "run",
      "speed": 1.5,
      "time_offset": 0.25,
      "transform": {"translation": [1, 2, 3], "rotation_degrees": [10, 20, 30], "scale": [1, 2, 3]},
      "proxies": "rigs/hero.proxies.json",
      "path": {"start": [-1, 0, 0], "end": [1, 0, 2], "speed": 0.8, "repeat": "ping_pong"}
    },
    {
      "model": "builtin:mannequin",
      "clip": 2,
      "transform": {"rotation_quaternion": [0, 0.70710678, 0, 0.70710678], "scale": 0.5}
    }
  ],
  "environment": {
    "type": "sky",
    "intensity": 2.0,
    "rotation_degrees": 45,
    "sun": {"elevation_degrees": 30, "azimuth_degrees": -60, "angular_radius_degrees": 1.5,
            "color": [1, 0.9, 0.8], "irradiance": 4},
    "sky": {"zenith_color": [0.1, 0.2, 0.3], "horizon_color": [0.4, 0.5, 0.6],
            "below_horizon_color": [0.7, 0.8, 0.9], "radiance": 0.75}
  },
  "ground": {"enabled": false, "size": 12.5, "albedo": [0.5, 0.6, 0.7]},
  "static_meshes": [
    {"model": "props/box.glb", "transform": {"translation": [0, 0.5, -2]}, "albedo": [0.9, 0.1, 0.1]},
    {"model": "props/wall.gltf"}
  ],
  "camera": {"type": "fixed", "position": [0, 2, 6], "target": [0, 1, 0], "up": [0, 1, 0.1],
             "fov_degrees": 35, "near": 0.2, "far": 50},
  "render": {"method": "vertex", "sh_order": 5, "receiver_scale": 2, "shadow_eta": 12, "indirect_eta": 8,
             "indirect_operator": "exact", "exponential": "ol", "hyb_tau": 0.5,
             "upsampling": "bilinear", "splat": "compute", "indirect_method": "none",
             "tonemap": "reinhard", "exposure_ev": -1.5, "static_transfer": "l1",
             "proxy_lod": "auto"},
  "output": {"width": 640, "height": 360, "fps": 30, "frames": {"first": 10, "last": 19},
             "formats": ["exr", "mp4"]}
})";

Scene parse_ok(const std::string& text) {
  Result<Scene> scene = parse_scene(text, "shots/scene.json");
  EXPECT_TRUE(scene.ok()) << (scene.ok() ? "" : scene.message());
  return scene.ok() ? *scene : Scene{};
}

TEST(SceneParse, EveryFieldOfTheFullScene) {
  const Scene s = parse_ok(kFullScene);
  EXPECT_EQ(s.description, "every field");
  EXPECT_EQ(s.base_dir, std::filesystem::path("shots"));
  ASSERT_EQ(s.characters.size(), 2u);

  const Character& a = s.characters[0];
  EXPECT_EQ(a.model, "chars/hero.glb");
  EXPECT_EQ(a.clip, ClipRef(std::string("run")));
  EXPECT_FLOAT_EQ(a.speed, 1.5f);
  EXPECT_FLOAT_EQ(a.time_offset_s, 0.25f);
  EXPECT_EQ(a.transform.translation, glm::vec3(1, 2, 3));
  EXPECT_EQ(a.transform.rotation.form, Rotation::Form::euler_degrees);
  EXPECT_EQ(a.transform.rotation.euler_degrees, glm::vec3(10, 20, 30));
  EXPECT_EQ(a.transform.scale, glm::vec3(1, 2, 3));
  ASSERT_TRUE(a.proxies.has_value());
  EXPECT_EQ(*a.proxies, "rigs/hero.proxies.json");
  ASSERT_TRUE(a.path.has_value());
  EXPECT_EQ(a.path->start, glm::vec3(-1, 0, 0));
  EXPECT_EQ(a.path->end, glm::vec3(1, 0, 2));
  EXPECT_FLOAT_EQ(a.path->speed, 0.8f);
  EXPECT_EQ(a.path->repeat, WalkPath::Repeat::ping_pong);

  const Character& b = s.characters[1];
  EXPECT_TRUE(is_builtin_mannequin(b.model));
  EXPECT_EQ(b.clip, ClipRef(2));
  EXPECT_FLOAT_EQ(b.speed, 1.0f);  // defaults
  EXPECT_FLOAT_EQ(b.time_offset_s, 0.0f);
  EXPECT_FALSE(b.proxies.has_value());
  EXPECT_FALSE(b.path.has_value());
  EXPECT_EQ(b.transform.rotation.form, Rotation::Form::quaternion);
  EXPECT_FLOAT_EQ(b.transform.rotation.quaternion.y, 0.70710678f);
  EXPECT_FLOAT_EQ(b.transform.rotation.quaternion.w, 0.70710678f);
  EXPECT_EQ(b.transform.scale, glm::vec3(0.5f));

  const Environment& e = s.environment;
  EXPECT_EQ(e.type, Environment::Type::sky);
  EXPECT_FLOAT_EQ(e.intensity, 2.0f);
  EXPECT_FLOAT_EQ(e.rotation_degrees, 45.0f);
  EXPECT_FLOAT_EQ(e.sun.elevation_degrees, 30.0f);
  EXPECT_FLOAT_EQ(e.sun.azimuth_degrees, -60.0f);
  EXPECT_FLOAT_EQ(e.sun.angular_radius_degrees, 1.5f);
  EXPECT_EQ(e.sun.color, glm::vec3(1, 0.9f, 0.8f));
  EXPECT_FLOAT_EQ(e.sun.irradiance, 4.0f);
  EXPECT_EQ(e.sky.zenith_color, glm::vec3(0.1f, 0.2f, 0.3f));
  EXPECT_EQ(e.sky.horizon_color, glm::vec3(0.4f, 0.5f, 0.6f));
  EXPECT_EQ(e.sky.below_horizon_color, glm::vec3(0.7f, 0.8f, 0.9f));
  EXPECT_FLOAT_EQ(e.sky.radiance, 0.75f);

  EXPECT_FALSE(s.ground.enabled);
  EXPECT_FLOAT_EQ(s.ground.size, 12.5f);
  EXPECT_EQ(s.ground.albedo, glm::vec3(0.5f, 0.6f, 0.7f));

  ASSERT_EQ(s.static_meshes.size(), 2u);
  EXPECT_EQ(s.static_meshes[0].model, "props/box.glb");
  EXPECT_EQ(s.static_meshes[0].transform.translation, glm::vec3(0, 0.5f, -2));
  ASSERT_TRUE(s.static_meshes[0].albedo.has_value());
  EXPECT_EQ(*s.static_meshes[0].albedo, glm::vec3(0.9f, 0.1f, 0.1f));
  EXPECT_FALSE(s.static_meshes[1].albedo.has_value());
  EXPECT_EQ(s.static_meshes[1].transform, Transform{});

  const auto* camera = std::get_if<FixedCamera>(&s.camera.kind);
  ASSERT_NE(camera, nullptr);
  EXPECT_EQ(camera->position, glm::vec3(0, 2, 6));
  EXPECT_EQ(camera->target, glm::vec3(0, 1, 0));
  EXPECT_EQ(camera->up, glm::vec3(0, 1, 0.1f));
  EXPECT_FLOAT_EQ(camera->fov_degrees, 35.0f);
  EXPECT_FLOAT_EQ(s.camera.near_m, 0.2f);
  EXPECT_FLOAT_EQ(s.camera.far_m, 50.0f);

  const settings::RenderSettings& r = s.render;
  EXPECT_EQ(r.sh_order, 5);
  EXPECT_EQ(r.receiver_scale, 2);
  EXPECT_FLOAT_EQ(r.shadow_eta, 12.0f);
  EXPECT_FLOAT_EQ(r.indirect_eta, 8.0f);
  EXPECT_EQ(r.indirect_operator, settings::IndirectOperator::exact);
  EXPECT_EQ(r.exponential, settings::Exponential::ol);
  EXPECT_FLOAT_EQ(r.hyb_tau, 0.5f);
  EXPECT_EQ(r.upsampling, settings::Upsampling::bilinear);
  EXPECT_EQ(r.splat, settings::SplatMethod::compute);
  EXPECT_EQ(r.method, settings::ShadingMethod::vertex);
  EXPECT_EQ(r.indirect_method, settings::IndirectMethod::none);
  EXPECT_EQ(r.tonemap, settings::Tonemap::reinhard);
  EXPECT_FLOAT_EQ(r.exposure_ev, -1.5f);
  EXPECT_EQ(r.static_transfer, settings::StaticTransfer::l1);
  EXPECT_EQ(r.proxy_lod, settings::ProxyLod::automatic);

  const Output& o = s.output;
  EXPECT_EQ(o.width, 640);
  EXPECT_EQ(o.height, 360);
  EXPECT_DOUBLE_EQ(o.fps, 30.0);
  EXPECT_EQ(o.first_frame, 10);
  EXPECT_EQ(o.frame_count, 10);  // 10..19 inclusive
  EXPECT_EQ(last_frame(o), 19);
  EXPECT_DOUBLE_EQ(frame_time_s(o, 15), 0.5);
  EXPECT_EQ(o.formats, (std::vector<OutputFormat>{OutputFormat::exr, OutputFormat::mp4}));
}

TEST(SceneParse, MinimalSceneTakesEveryDefault) {
  Scene expected;
  expected.base_dir = "shots";
  // A file without ground.size gets the ground reaching the horizon and the far plane beyond it.
  expected.ground.size = kHorizonGroundSize;
  expected.camera.far_m = kHorizonFarM;
  EXPECT_EQ(parse_ok(R"({"schema_version": 1})"), expected);
  // The documented defaults.
  EXPECT_EQ(expected.render.sh_order, 4);
  EXPECT_EQ(expected.render.method, settings::ShadingMethod::image_space);
  EXPECT_EQ(expected.render.receiver_scale, 4);
  EXPECT_FLOAT_EQ(expected.render.shadow_eta, 15.0f);
  EXPECT_FLOAT_EQ(expected.render.indirect_eta, 10.0f);
  EXPECT_EQ(expected.render.indirect_operator, settings::IndirectOperator::averaged);
  EXPECT_EQ(expected.render.exponential, settings::Exponential::hyb);
  EXPECT_FLOAT_EQ(expected.render.hyb_tau, 0.25f);
  EXPECT_EQ(expected.render.upsampling, settings::Upsampling::bilateral);
  EXPECT_EQ(expected.render.indirect_method, settings::IndirectMethod::proxy);
  EXPECT_EQ(expected.output.width, 512);
  EXPECT_EQ(expected.output.height, 512);
  EXPECT_DOUBLE_EQ(expected.output.fps, 24.0);
  EXPECT_TRUE(std::holds_alternative<FixedCamera>(expected.camera.kind));
}

// Files written before render.indirect_method keep their meaning.
TEST(SceneParse, TheOlderIndirectBooleanReadsAsAnIndirectMethod) {
  for (const auto& [text, expected] : {std::pair{R"({"schema_version": 1, "render": {"indirect": false}})", settings::IndirectMethod::none},
                                       std::pair{R"({"schema_version": 1, "render": {"indirect": true}})", settings::IndirectMethod::proxy}}) {
    auto scene = parse_scene(text, "old.json");
    ASSERT_TRUE(scene.ok()) << scene.message();
    EXPECT_EQ(scene->render.indirect_method, expected) << text;
  }
}

TEST(SceneParse, ShadowEtaAutoReadsAsEtaFromTheLightingAndIsWrittenBack) {
  auto scene = parse_scene(R"({"schema_version": 1, "render": {"shadow_eta": "auto"}})", "auto.json");
  ASSERT_TRUE(scene.ok()) << scene.message();
  EXPECT_EQ(scene->render.shadow_eta, settings::kEtaFromLighting);
  auto text = to_json(*scene);
  ASSERT_TRUE(text.ok()) << text.message();
  EXPECT_NE(text->find("\"shadow_eta\": \"auto\""), std::string::npos) << *text;
  auto again = parse_scene(*text, "again.json");
  ASSERT_TRUE(again.ok()) << again.message();
  EXPECT_EQ(again->render.shadow_eta, settings::kEtaFromLighting);
}

// render.quality: "manual" (the default), a named level or {"target_relative_mse": x}, each
// written back in the form it was read.
TEST(SceneParse, QualityReadsItsThreeFormsAndWritesThemBack) {
  const std::pair<const char*, float> cases[] = {{R"("manual")", settings::kQualityManual},
                                                 {R"("balanced")", 0.009f},
                                                 {R"("draft")", 0.012f},
                                                 {R"({"target_relative_mse": 0.011})", 0.011f}};
  for (const auto& [form, value] : cases) {
    const std::string text = std::string(R"({"schema_version": 1, "render": {"quality": )") + form + "}}";
    auto scene = parse_scene(text, "quality.json");
    ASSERT_TRUE(scene.ok()) << scene.message();
    EXPECT_EQ(scene->render.quality, value) << form;
    auto written = to_json(*scene);
    ASSERT_TRUE(written.ok()) << written.message();
    auto again = parse_scene(*written, "again.json");
    ASSERT_TRUE(again.ok()) << again.message();
    EXPECT_EQ(again->render, scene->render) << form;
  }
  auto target = parse_scene(R"({"schema_version": 1, "render": {"quality": {"target_relative_mse": 0.011}}})", "t.json");
  ASSERT_TRUE(target.ok());
  auto text = to_json(*target);
  ASSERT_TRUE(text.ok());
  EXPECT_NE(text->find("\"target_relative_mse\": 0.011"), std::string::npos) << *text;
  EXPECT_EQ(parse_ok(R"({"schema_version": 1})").render.quality, settings::kQualityManual);
}

TEST(SceneParse, OrbitCamera) {
  const Scene s = parse_ok(R"({"schema_version": 1, "camera": {"type": "orbit", "target": [1, 1, 1],
      "distance": 7, "elevation_degrees": 25, "start_azimuth_degrees": 90,
      "degrees_per_second": -45, "fov_degrees": 50}})");
  const auto* o = std::get_if<OrbitCamera>(&s.camera.kind);
  ASSERT_NE(o, nullptr);
  EXPECT_EQ(o->target, glm::vec3(1, 1, 1));
  EXPECT_FLOAT_EQ(o->distance, 7.0f);
  EXPECT_FLOAT_EQ(o->elevation_degrees, 25.0f);
  EXPECT_FLOAT_EQ(o->start_azimuth_degrees, 90.0f);
  EXPECT_FLOAT_EQ(o->degrees_per_second, -45.0f);
  EXPECT_FLOAT_EQ(o->fov_degrees, 50.0f);
}

TEST(SceneParse, FollowCamera) {
  const Scene s = parse_ok(R"({"schema_version": 1,
      "characters": [{"model": "a.glb"}, {"model": "b.glb"}],
      "camera": {"type": "follow", "character": 1, "offset": [0, 2, 5], "look_at_height": 1.2,
                 "smoothing": 0.75, "fov_degrees": 60}})");
  const auto* f = std::get_if<FollowCamera>(&s.camera.kind);
  ASSERT_NE(f, nullptr);
  EXPECT_EQ(f->character, 1);
  EXPECT_EQ(f->offset, glm::vec3(0, 2, 5));
  EXPECT_FLOAT_EQ(f->look_at_height, 1.2f);
  EXPECT_FLOAT_EQ(f->smoothing_s, 0.75f);
  EXPECT_FLOAT_EQ(f->fov_degrees, 60.0f);
}

TEST(SceneParse, KeyframedCamera) {
  const Scene s = parse_ok(R"({"schema_version": 1, "camera": {"type": "keyframed",
      "interpolation": "linear", "up": [0, 1, 0],
      "keys": [{"time": 0, "position": [0, 1, 5], "target": [0, 1, 0], "fov_degrees": 40},
               {"time": 2.5, "position": [5, 1, 0], "target": [0, 1, 0]}]}})");
  const auto* k = std::get_if<KeyframedCamera>(&s.camera.kind);
  ASSERT_NE(k, nullptr);
  EXPECT_EQ(k->interpolation, KeyframedCamera::Interpolation::linear);
  ASSERT_EQ(k->keys.size(), 2u);
  EXPECT_FLOAT_EQ(k->keys[0].fov_degrees, 40.0f);
  EXPECT_FLOAT_EQ(k->keys[1].time_s, 2.5f);
  EXPECT_EQ(k->keys[1].position, glm::vec3(5, 1, 0));
  EXPECT_FLOAT_EQ(k->keys[1].fov_degrees, 45.0f);  // default
}

TEST(SceneParse, EnvironmentMap) {
  const Scene s = parse_ok(R"({"schema_version": 1, "environment": {"type": "map",
      "path": "hdr/studio.EXR", "intensity": 0.5, "rotation_degrees": -30}})");
  EXPECT_EQ(s.environment.type, Environment::Type::map);
  EXPECT_EQ(s.environment.map_path, "hdr/studio.EXR");
  EXPECT_FLOAT_EQ(s.environment.intensity, 0.5f);
  EXPECT_FLOAT_EQ(s.environment.rotation_degrees, -30.0f);
}

TEST(SceneParse, FrameCountInsteadOfLast) {
  const Scene s = parse_ok(R"({"schema_version": 1, "output": {"frames": {"first": 3, "count": 7}}})");
  EXPECT_EQ(s.output.first_frame, 3);
  EXPECT_EQ(s.output.frame_count, 7);
  EXPECT_EQ(last_frame(s.output), 9);
}

TEST(SceneParse, PathsResolveAgainstTheSceneFolder) {
  const Scene s = parse_ok(kFullScene);
  EXPECT_EQ(resolve_scene_path(s, s.characters[0].model), std::filesystem::path("shots/chars/hero.glb"));
  EXPECT_EQ(resolve_scene_path(s, "/abs/x.glb"), std::filesystem::path("/abs/x.glb"));
  EXPECT_EQ(resolve_model_path(s, s.characters[1].model, "assets"), std::filesystem::path("assets/mannequin.glb"));
  EXPECT_EQ(resolve_proxy_path(s, s.characters[0], "assets"),
            std::filesystem::path("shots/rigs/hero.proxies.json"));
  EXPECT_EQ(resolve_proxy_path(s, s.characters[1], "assets"),
            std::filesystem::path("assets/mannequin.proxies.json"));
}

TEST(SceneParse, LoadSceneReadsAFileAndRefusesAMissingOne) {
  const std::filesystem::path dir = std::filesystem::path(PROXYGI_TEST_OUTPUT_DIR) / "scene_load";
  std::filesystem::create_directories(dir);
  const std::filesystem::path file = dir / "tiny.json";
  {
    std::FILE* f = std::fopen(file.c_str(), "wb");
    ASSERT_NE(f, nullptr);
    std::fputs(R"({"schema_version": 1, "description": "from disk"})", f);
    std::fclose(f);
  }
  Result<Scene> loaded = load_scene(file);
  ASSERT_TRUE(loaded.ok()) << loaded.message();
  EXPECT_EQ(loaded->description, "from disk");
  EXPECT_EQ(loaded->base_dir, dir);

  Result<Scene> missing = load_scene(dir / "missing.json");
  ASSERT_FALSE(missing.ok());
  EXPECT_NE(missing.message().find("missing.json"), std::string::npos) << missing.message();
}

}  // namespace
}  // namespace proxygi::scene
