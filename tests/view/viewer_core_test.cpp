// The viewer core without a window or a GPU: the key map of ../shared/notes/viewer-regression.md
// §1 on the playback clock and the cameras, loop modes, settings by field, and scripts.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <future>
#include <thread>

#include "scene/scene_defaults.h"
#include "settings/fields.h"
#include "view/scene_loader.h"
#include "view/scene_open.h"
#include "view/script.h"
#include "view/viewer_core.h"
#include "world/model_stage.h"

namespace proxygi::view {
namespace {

scene::CameraState scene_camera() {
  scene::CameraState camera;
  camera.eye = {0.0f, 1.5f, 5.0f};
  camera.target = {0.0f, 1.0f, 0.0f};
  return camera;
}

ViewerCore make_core() {
  ViewerCore core(scene::default_scene());  // 24 fps, frames 0..95
  core.set_scene_camera(scene_camera());
  return core;
}

TEST(ViewerCore, SpaceTogglesPlaybackAndArrowsStepOnTheFrameGrid) {
  ViewerCore core = make_core();
  EXPECT_FALSE(core.state().playback.playing);
  core.handle(KeyEvent{Key::space});
  EXPECT_TRUE(core.state().playback.playing);
  core.advance(0.5);
  EXPECT_NEAR(core.state().playback.time_s, 0.5, 1e-12);
  core.handle(KeyEvent{Key::right});  // steps pause
  EXPECT_FALSE(core.state().playback.playing);
  EXPECT_EQ(core.state().playback.frame(), 13);
  EXPECT_DOUBLE_EQ(core.state().playback.time_s, 13 / 24.0);
  core.handle(KeyEvent{Key::up});
  EXPECT_EQ(core.state().playback.frame(), 23);
  core.handle(KeyEvent{Key::down});
  core.handle(KeyEvent{Key::left});
  EXPECT_EQ(core.state().playback.frame(), 12);
  core.handle(KeyEvent{Key::right, {.shift = true}});
  EXPECT_EQ(core.state().playback.frame(), 95);
  core.handle(KeyEvent{Key::up});  // clamped at the end
  EXPECT_EQ(core.state().playback.frame(), 95);
  core.handle(KeyEvent{Key::left, {.shift = true}});
  EXPECT_EQ(core.state().playback.frame(), 0);
}

TEST(ViewerCore, SpeedReverseAndLoopModes) {
  ViewerCore core = make_core();
  core.handle(KeyEvent{Key::equal});
  EXPECT_DOUBLE_EQ(core.state().playback.speed, 2.0);
  core.handle(KeyEvent{Key::minus});
  core.handle(KeyEvent{Key::minus});
  EXPECT_DOUBLE_EQ(core.state().playback.speed, 0.5);
  core.handle(KeyEvent{Key::backspace});
  EXPECT_DOUBLE_EQ(core.state().playback.speed, 1.0);
  core.handle(KeyEvent{Key::space, {.shift = true, .ctrl = true}});
  EXPECT_EQ(core.state().playback.direction, -1);
  core.handle(KeyEvent{Key::backspace});

  // Loop: past the end wraps to the start.
  core.seek(95 / 24.0 - 0.1);
  core.handle(KeyEvent{Key::space});
  core.advance(0.2);
  EXPECT_NEAR(core.state().playback.time_s, 0.1, 1e-9);
  // Once (L): stops at the end.
  core.handle(KeyEvent{Key::l});
  EXPECT_EQ(core.state().playback.loop, LoopMode::once);
  core.seek(95 / 24.0 - 0.1);
  core.advance(0.2);
  EXPECT_DOUBLE_EQ(core.state().playback.time_s, 95 / 24.0);
  EXPECT_FALSE(core.state().playback.playing);
  // Ping-pong (P): bounces and reverses.
  core.handle(KeyEvent{Key::p});
  core.handle(KeyEvent{Key::space});
  core.seek(95 / 24.0 - 0.1);
  core.advance(0.2);
  EXPECT_NEAR(core.state().playback.time_s, 95 / 24.0 - 0.1, 1e-9);
  EXPECT_EQ(core.state().playback.direction, -1);
  // Fixed step: one frame per advance, whatever the wall time.
  core.state().playback.fixed_step = true;
  core.handle(KeyEvent{Key::backspace});
  core.seek(0.0);
  core.advance(3.0);
  EXPECT_DOUBLE_EQ(core.state().playback.time_s, 1 / 24.0);
}

TEST(ViewerCore, DragsOrbitPanAndZoomAFreeCameraStartingAtTheSceneCamera) {
  ViewerCore core = make_core();
  EXPECT_FALSE(core.camera_override());
  core.handle(DragEvent{MouseButton::left, 0.0f, 0.0f});
  ASSERT_TRUE(core.camera_override());
  const scene::CameraState start = *core.camera_override();
  EXPECT_NEAR(glm::length(start.eye - scene_camera().eye), 0.0f, 1e-5f);  // no jump

  core.handle(DragEvent{MouseButton::left, 100.0f, 0.0f});  // orbit: same distance, new azimuth
  const scene::CameraState orbited = core.camera();
  EXPECT_NEAR(glm::length(orbited.eye - orbited.target), glm::length(start.eye - start.target), 1e-4f);
  EXPECT_NEAR(core.state().camera.azimuth_degrees, -30.0f, 1e-3f);
  EXPECT_EQ(orbited.target, start.target);

  core.handle(DragEvent{MouseButton::right, 50.0f, 0.0f});  // pan moves the target
  EXPECT_GT(glm::length(core.camera().target - start.target), 0.01f);
  const float before = core.state().camera.distance;
  core.handle(ScrollEvent{1.0f});  // wheel zooms in
  EXPECT_LT(core.state().camera.distance, before);
  core.handle(DragEvent{MouseButton::middle, 0.0f, 50.0f, {.ctrl = true}});  // Ctrl+middle zooms
  EXPECT_GT(core.state().camera.distance, before * 0.9f);

  core.set_bounds({1.0f, 0.5f, 0.0f}, 0.5f);
  core.handle(KeyEvent{Key::home});  // frame all
  EXPECT_EQ(core.state().camera.target, glm::vec3(1.0f, 0.5f, 0.0f));
  core.handle(KeyEvent{Key::c});  // back to the scene camera
  EXPECT_FALSE(core.camera_override());
}

TEST(ViewerCore, SettingsByFieldAndRequestsForTheApplication) {
  ViewerCore core = make_core();
  core.handle(SetSettingEvent{"sh_order", 5});
  core.handle(SetSettingEvent{"receiver_scale", 2});
  EXPECT_EQ(core.state().settings.sh_order, 5);
  EXPECT_EQ(core.state().settings.receiver_scale, 2);
  core.handle(SetSettingEvent{"sh_order", 9});
  EXPECT_EQ(core.state().settings.sh_order, 5);
  EXPECT_NE(core.state().message.find("sh_order"), std::string::npos);
  core.handle(KeyEvent{Key::f12});
  core.handle(KeyEvent{Key::escape});
  core.handle(OpenFileEvent{"x.glb"});
  const auto requests = core.take_requests();
  ASSERT_EQ(requests.size(), 3u);
  EXPECT_TRUE(std::holds_alternative<ScreenshotEvent>(requests[0]));
  EXPECT_TRUE(std::holds_alternative<QuitEvent>(requests[1]));
  EXPECT_TRUE(core.take_requests().empty());
  core.handle(KeyEvent{Key::f10});
  core.handle(KeyEvent{Key::f1});
  EXPECT_FALSE(core.state().toggles.ui);
  EXPECT_TRUE(core.state().toggles.help);
}

TEST(ViewerScript, ParsesEveryEventKindAndNamesTheBadOne) {
  auto script = parse_script(R"({"step_s": 0.05, "events": [
      {"t": 1.0, "quit": true},
      {"t": 0.0, "key": "space", "shift": true},
      {"t": 0.5, "drag": {"button": "right", "dx": 4, "dy": -2}},
      {"t": 0.5, "scroll": 1},
      {"t": 0.5, "set": {"sh_order": 5, "tonemap": "reinhard", "indirect_method": "none"}},
      {"t": 0.6, "screenshot": "a.png", "ui": false},
      {"t": 0.6, "open": "m.glb"}, {"t": 0.6, "save": "s.json"},
      {"t": 0.7, "resize": [64, 32]}, {"t": 0.8, "minimize": true}, {"t": 0.9, "restore": true},
      {"t": 0.95, "move": [-20, 900]}]})");
  ASSERT_TRUE(script.ok()) << script.message();
  EXPECT_EQ(*script->step_s, 0.05);
  ASSERT_EQ(script->events.size(), 14u);
  const auto& move = std::get<MoveEvent>(script->events[12].event);
  EXPECT_EQ(move.x, -20);
  EXPECT_EQ(move.y, 900);
  EXPECT_TRUE(std::holds_alternative<KeyEvent>(script->events[0].event));
  EXPECT_TRUE(std::get<KeyEvent>(script->events[0].event).mods.shift);
  EXPECT_TRUE(std::holds_alternative<QuitEvent>(script->events.back().event));  // sorted by time
  // A set's keys come in key order (a JSON object has no order): indirect, sh_order, tonemap.
  const auto& tonemap = std::get<SetSettingEvent>(script->events[5].event);
  EXPECT_EQ(tonemap.key, "tonemap");
  EXPECT_EQ(tonemap.value, double(settings::Tonemap::reinhard));

  ScriptPlayer player(*script);
  EXPECT_EQ(player.due(0.0).size(), 1u);
  EXPECT_EQ(player.due(0.55).size(), 5u);
  EXPECT_FALSE(player.finished());
  EXPECT_EQ(player.due(10.0).size(), 1u);  // up to the screenshot
  EXPECT_TRUE(player.has_due(10.0));
  EXPECT_EQ(player.due(10.0).size(), 7u);
  EXPECT_TRUE(player.finished());

  auto bad = parse_script(R"({"events": [{"t": 0, "key": "space"}, {"t": 1, "key": "spce"}]})");
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.message().find("events[1]"), std::string::npos) << bad.message();
  EXPECT_NE(bad.message().find("spce"), std::string::npos) << bad.message();
  EXPECT_FALSE(parse_script(R"({"events": [{"t": 0, "set": {"sh_ordr": 5}}]})").ok());
  EXPECT_FALSE(parse_script("[1, 2]").ok());
  auto bad_move = parse_script(R"({"events": [{"t": 0, "move": [1]}]})");
  ASSERT_FALSE(bad_move.ok());
  EXPECT_NE(bad_move.message().find("move"), std::string::npos) << bad_move.message();
}

// shadow_eta "auto" in a script's set event (as in scene files); 0, its stored form, is refused
// as a number, and "auto" where a field has none names the field.
TEST(ViewerScript, SetTakesAutoEtaAndRefusesItsStoredZero) {
  auto script = parse_script(R"({"events": [{"t": 0, "set": {"shadow_eta": "auto"}}, {"t": 1, "set": {"shadow_eta": 20}}]})");
  ASSERT_TRUE(script.ok()) << script.message();
  ASSERT_EQ(script->events.size(), 2u);
  ViewerCore core(scene::default_scene());
  core.handle(script->events[0].event);
  EXPECT_EQ(core.state().settings.shadow_eta, settings::kEtaFromLighting);
  EXPECT_TRUE(core.state().message.empty()) << core.state().message;
  core.handle(script->events[1].event);
  EXPECT_EQ(core.state().settings.shadow_eta, 20.0f);

  const std::pair<const char*, const char*> bad[] = {
      {R"({"events": [{"t": 0, "set": {"shadow_eta": 0}}]})", "set.shadow_eta: shadow_eta: must be > 1 or \"auto\" (got 0)"},
      {R"({"events": [{"t": 0, "set": {"shadow_eta": "big"}}]})", "unknown value \"big\" (expected a number or \"auto\")"},
      {R"({"events": [{"t": 0, "set": {"indirect_eta": "auto"}}]})", "indirect_eta: expected a number, not \"auto\""},
      {R"({"events": [{"t": 0, "set": {"tonemap": "filmic"}}]})", "tonemap: unknown value \"filmic\""},
  };
  for (const auto& [text, needle] : bad) {
    auto parsed = parse_script(text);
    ASSERT_FALSE(parsed.ok()) << text;
    EXPECT_NE(parsed.message().find(needle), std::string::npos) << parsed.message();
  }
}

}  // namespace
}  // namespace proxygi::view

namespace proxygi::view {
namespace {

TEST(ViewerOpen, ABareModelGetsRecordsStage) {
  const std::filesystem::path assets = PROXYGI_SOURCE_DIR "/assets";
  const std::string model = PROXYGI_SOURCE_DIR "/assets/mannequin.glb";
  auto scene = open_scene(model, nullptr, assets);
  ASSERT_TRUE(scene.ok()) << scene.message();
  // The stage `record MODEL.glb` renders (world::stage_scene), not a look-alike.
  auto recorded = world::stage_scene(model, assets);
  ASSERT_TRUE(recorded.ok()) << recorded.message();
  EXPECT_TRUE(*scene == *recorded);
  ASSERT_EQ(scene->characters.size(), 1u);
  EXPECT_EQ(scene->characters[0].transform.scale, glm::vec3(1.0f));  // its own size
  EXPECT_TRUE(scene->ground.enabled);
  EXPECT_TRUE(std::holds_alternative<scene::FixedCamera>(scene->camera.kind));
  EXPECT_GT(scene->output.frame_count, 1);  // one pass of the first clip
  // Standing on the ground over the clip: the lowest point of the motion is at y = 0.
  auto world = world::World::load(*scene, {.assets_dir = assets, .load_rigs = false});
  ASSERT_TRUE(world.ok()) << world.message();
  auto bounds = world::bounds_over_time(**world, 0.0, scene::frame_time_s(scene->output, scene::last_frame(scene->output)), 24);
  ASSERT_TRUE(bounds.ok()) << bounds.message();
  EXPECT_NEAR(bounds->first.y, 0.0f, 1e-3f);

  // "mannequin" and "builtin:mannequin" name the bundled figure, as in record and fit.
  for (const char* name : {"mannequin", "builtin:mannequin"}) {
    EXPECT_EQ(open_kind(name), OpenKind::model) << name;
    auto mannequin = open_scene(name, nullptr, assets);
    ASSERT_TRUE(mannequin.ok()) << name << ": " << mannequin.message();
    auto expected = world::stage_scene("builtin:mannequin", assets);
    ASSERT_TRUE(expected.ok()) << expected.message();
    EXPECT_TRUE(*mannequin == *expected) << name;
    EXPECT_EQ(mannequin->characters.at(0).model, "builtin:mannequin");
  }
  EXPECT_TRUE(open_scene("default", nullptr, assets).ok());
  EXPECT_TRUE(open_scene("crowd", nullptr, assets).ok());
  auto missing = open_scene("/no/such/model.glb", nullptr, assets);
  ASSERT_FALSE(missing.ok());
  EXPECT_NE(missing.message().find("model.glb"), std::string::npos);
}

TEST(ViewerOpen, AnEnvironmentFileReplacesTheCurrentScenesEnvironment) {
  scene::Scene current = scene::crowd_scene();
  const std::filesystem::path file = std::filesystem::path(PROXYGI_TEST_OUTPUT_DIR) / "view_open_environment.hdr";
  std::filesystem::create_directories(file.parent_path());
  std::ofstream(file) << "placeholder";  // open_scene only names it; the world reads it
  for (const std::string& name : {file.string(), std::string("studio.EXR")}) EXPECT_EQ(open_kind(name), OpenKind::environment);
  auto scene = open_scene(file.string(), &current, PROXYGI_SOURCE_DIR "/assets");
  ASSERT_TRUE(scene.ok()) << scene.message();
  EXPECT_EQ(scene->environment.type, scene::Environment::Type::map);
  EXPECT_EQ(std::filesystem::path(scene->environment.map_path), std::filesystem::absolute(file));
  scene->environment = current.environment;
  EXPECT_TRUE(*scene == current);  // everything else is the shown scene
}

// A model without a cached rig: the loader offers the scene without proxies while the rig is
// fitted (the fit held back by the gate), then the world with them, keeping the viewer's state.
TEST(ViewerLoader, AModelShowsWithoutProxiesWhileItsRigIsFittedThenWithThem) {
  const std::filesystem::path dir = std::filesystem::path(PROXYGI_TEST_OUTPUT_DIR) / "view_loader_preview";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const std::filesystem::path model = dir / "figure.glb";
  std::filesystem::copy_file(PROXYGI_SOURCE_DIR "/assets/mannequin.glb", model);
  std::promise<void> gate;
  SceneLoader loader(PROXYGI_SOURCE_DIR "/assets", {.preview_after_s = 0.0, .rig_gate = gate.get_future().share()});
  loader.open(model.string(), nullptr);
  std::optional<Result<LoadedScene>> preview;
  // Bounded so a broken loader fails instead of hanging (not a speed check).
  for (int i = 0; i < 12000 && !preview; ++i) {
    preview = loader.poll();
    if (!preview) std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  ASSERT_TRUE(preview && preview->ok()) << (preview ? preview->message() : "no preview");
  EXPECT_TRUE((*preview)->preview);
  EXPECT_FALSE((*preview)->keep_state);
  EXPECT_EQ((*preview)->world->proxy_count(), 0u);
  EXPECT_EQ((*preview)->world->instances().size(), 1u);
  EXPECT_TRUE(loader.busy());
  EXPECT_FALSE(loader.poll());  // offered once
  EXPECT_NE(loader.progress().find("fitting"), std::string::npos) << loader.progress();
  gate.set_value();
  auto rigged = loader.wait();
  ASSERT_TRUE(rigged && rigged->ok()) << (rigged ? rigged->message() : "nothing");
  EXPECT_FALSE((*rigged)->preview);
  EXPECT_TRUE((*rigged)->keep_state);  // replaces the preview shown
  EXPECT_GT((*rigged)->world->proxy_count(), 0u);
  EXPECT_FALSE(loader.busy());
  EXPECT_TRUE(std::filesystem::exists(dir / "figure.proxies.json"));  // fitted and cached

  // Now cached: a load that ends before the preview's wait offers no preview.
  SceneLoader cached(PROXYGI_SOURCE_DIR "/assets", {.preview_after_s = 1e9});
  cached.open(model.string(), nullptr);
  auto direct = cached.wait();
  ASSERT_TRUE(direct && direct->ok());
  EXPECT_FALSE((*direct)->preview);
  EXPECT_FALSE((*direct)->keep_state);
  EXPECT_GT((*direct)->world->proxy_count(), 0u);
}

}  // namespace
}  // namespace proxygi::view
