// The viewer driven by scripts on the offscreen presenter (label gpu, validation on, zero
// messages): a frame with the UI hidden is record's frame; Space, arrows and a drag change time
// and camera as expected; a live change of SH order and k gives record's frame for those
// settings; a malformed model leaves the previous scene running and shows its error.
#include <fstream>

#include <stb/stb_image_write.h>

#include "gpu/gpu_test_context.h"
#include "gpu/pass_timestamps.h"
#include "scene/scene_defaults.h"
#include "scene/scene_parse.h"
#include "viewer_test_util.h"

namespace proxygi::view {
namespace {

using ViewerOffscreenTest = gpu::testing::GpuTest;
using namespace view::testing;

constexpr int kSize = 96;

TEST_F(ViewerOffscreenTest, FrameWithTheUiHiddenIsRecordsFrame) {
  // Frame 12 of the default scene: Up (+10) and Right twice (+1 each).
  const auto run = run_viewer_script(R"({"events": [
      {"t": 0, "key": "up"}, {"t": 0, "key": "right"}, {"t": 0, "key": "right"},
      {"t": 0.05, "screenshot": "hidden.png", "ui": false},
      {"t": 0.05, "screenshot": "with_ui.png", "ui": true}]})",
                                     "default", kSize, kSize, true, "record_equal");
  ASSERT_TRUE(run.status.ok()) << run.status.message();
  EXPECT_EQ(run.state["frame"], 12);
  ASSERT_TRUE(run.shots.count("hidden.png"));
  const auto expected = record_frame(context(), scene::default_scene(), kSize, kSize, 12);
  expect_within_one_code(run.shots.at("hidden.png"), expected, "record_equal", "hidden");
  EXPECT_GT(max_code_difference(run.shots.at("with_ui.png").rgba, expected), 1);  // the UI shows
}

TEST_F(ViewerOffscreenTest, SpaceArrowsAndADragChangeTimeAndCamera) {
  const auto run = run_viewer_script(R"({"step_s": 0.05, "events": [
      {"t": 0, "screenshot": "start.png", "ui": false},
      {"t": 0, "key": "space"},
      {"t": 0.5, "key": "space"},
      {"t": 0.5, "screenshot": "played.png", "ui": false},
      {"t": 0.55, "key": "right"}, {"t": 0.55, "key": "up"},
      {"t": 0.6, "drag": {"button": "left", "dx": 120, "dy": 0}},
      {"t": 0.65, "screenshot": "dragged.png", "ui": false}]})",
                                     "default", kSize, kSize, true, "script_input");
  ASSERT_TRUE(run.status.ok()) << run.status.message();
  // Played 0.5 s (10 steps of 0.05 s: frame 12 of 24 fps), then +1 and +10 frames: frame 23.
  EXPECT_EQ(run.state["frame"], 23);
  EXPECT_FALSE(run.state["playing"]);
  EXPECT_TRUE(run.state["free_camera"]);
  const auto& eye = run.state["camera"]["eye"];
  const scene::FixedCamera scene_camera = std::get<scene::FixedCamera>(scene::default_scene().camera.kind);
  EXPECT_GT(std::abs(eye[0].get<float>() - scene_camera.position.x), 1.0f);  // orbited 36 degrees
  ASSERT_EQ(run.shots.size(), 3u);
  EXPECT_GT(max_code_difference(run.shots.at("start.png").rgba, run.shots.at("played.png").rgba), 8);
  EXPECT_GT(max_code_difference(run.shots.at("played.png").rgba, run.shots.at("dragged.png").rgba), 8);
}

TEST_F(ViewerOffscreenTest, LiveShOrderAndReceiverScaleGiveRecordsFrame) {
  const auto run = run_viewer_script(R"({"events": [
      {"t": 0, "key": "up"},
      {"t": 0.05, "set": {"sh_order": 5, "receiver_scale": 2}},
      {"t": 0.1, "screenshot": "changed.png", "ui": false},
      {"t": 0.1, "set": {"sh_order": 3, "receiver_scale": 8, "tonemap": "reinhard"}},
      {"t": 0.15, "screenshot": "changed_again.png", "ui": false}]})",
                                     "default", kSize, kSize, true, "live_settings");
  ASSERT_TRUE(run.status.ok()) << run.status.message();
  EXPECT_EQ(run.state["settings"]["sh_order"], 3);
  scene::Scene scene = scene::default_scene();
  scene.render.sh_order = 5;
  scene.render.receiver_scale = 2;
  expect_within_one_code(run.shots.at("changed.png"), record_frame(context(), scene, kSize, kSize, 10), "live_settings",
                         "changed");
  scene.render.sh_order = 3;
  scene.render.receiver_scale = 8;
  scene.render.tonemap = settings::Tonemap::reinhard;
  expect_within_one_code(run.shots.at("changed_again.png"), record_frame(context(), scene, kSize, kSize, 10),
                         "live_settings", "changed_again");
}

TEST_F(ViewerOffscreenTest, AMalformedModelKeepsThePreviousSceneAndShowsTheError) {
  const auto bad = output_dir("malformed") / "broken.glb";
  std::ofstream(bad) << "glTF this is not a binary glTF";
  const std::string script = R"({"events": [
      {"t": 0, "open": ")" + bad.string() + R"("},
      {"t": 0.05, "key": "up"},
      {"t": 0.1, "screenshot": "after.png", "ui": false}]})";
  const auto run = run_viewer_script(script, "default", kSize, kSize, true, "malformed");
  ASSERT_TRUE(run.status.ok()) << run.status.message();
  EXPECT_EQ(run.state["scene"], "default");
  EXPECT_NE(run.state["message"].get<std::string>().find("broken.glb"), std::string::npos) << run.state["message"];
  expect_within_one_code(run.shots.at("after.png"), record_frame(context(), scene::default_scene(), kSize, kSize, 10),
                         "malformed", "after");
}

TEST_F(ViewerOffscreenTest, SavedSceneRecordsTheFrameOnScreen) {
  const auto saved = output_dir("save") / "seen.json";
  const std::string script = R"({"events": [
      {"t": 0, "key": "up"}, {"t": 0, "drag": {"button": "left", "dx": 60, "dy": 20}},
      {"t": 0, "set": {"sh_order": 5}},
      {"t": 0.05, "screenshot": "seen.png", "ui": false},
      {"t": 0.05, "save": ")" + saved.string() + R"("}]})";
  const auto run = run_viewer_script(script, "default", kSize, kSize, true, "save");
  ASSERT_TRUE(run.status.ok()) << run.status.message();
  auto scene = scene::load_scene(saved);
  ASSERT_TRUE(scene.ok()) << scene.message();
  EXPECT_EQ(scene->output.first_frame, 10);
  EXPECT_EQ(scene->render.sh_order, 5);
  // `record` of the saved scene renders its first frame as the viewer showed it.
  expect_within_one_code(run.shots.at("seen.png"), record_frame(context(), *scene, kSize, kSize, 10), "save", "seen");
}

TEST_F(ViewerOffscreenTest, ViewsShowTheFramesInputsAndCycleBackToTheFinalFrame) {
  const std::vector<std::string> views = {"albedo", "normals", "irradiance", "receivers", "direct",
                                          "indirect", "occlusion", "heat_map"};
  std::string events = R"({"t": 0, "key": "up"}, {"t": 0, "screenshot": "final.png", "ui": false})";
  for (const std::string& view : views)
    events += R"(, {"t": 0, "key": "v"}, {"t": 0, "screenshot": ")" + view + R"(.png", "ui": false})";
  events += R"(, {"t": 0, "key": "v"}, {"t": 0, "screenshot": "again.png", "ui": false})";
  const auto run = run_viewer_script(R"({"events": [)" + events + "]}", "default", kSize, kSize, true, "views");
  ASSERT_TRUE(run.status.ok()) << run.status.message();
  ASSERT_EQ(run.shots.size(), views.size() + 2);
  const auto& final_frame = run.shots.at("final.png").rgba;
  for (const std::string& view : views) {
    if (view == "direct") continue;
    EXPECT_GT(max_code_difference(run.shots.at(view + ".png").rgba, final_frame), 16) << view;
  }
  // Direct only lacks the bounce light; receivers at 1/4 (no upsampling) differ from the upsampled irradiance.
  EXPECT_GT(max_code_difference(run.shots.at("direct.png").rgba, final_frame), 1);
  EXPECT_GT(max_code_difference(run.shots.at("receivers.png").rgba, run.shots.at("irradiance.png").rgba), 4);
  expect_within_one_code(run.shots.at("again.png"), record_frame(context(), scene::default_scene(), kSize, kSize, 10),
                         "views", "again");
  EXPECT_EQ(run.state["view"], "final");
}

// An .hdr or .exr dropped on the window (the open event a drop sends) becomes the shown scene's
// environment: the frame is record's for the scene with that map. Both files are made here.
TEST_F(ViewerOffscreenTest, ADroppedHdrOrExrSetsTheEnvironment) {
  constexpr int kWidth = 32, kHeight = 16;
  image::ImageF map(kWidth, kHeight);
  std::vector<float> rgb;
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      // Warm sky over a dark blue floor, brighter toward +u: direction matters.
      const glm::vec3 value = y < kHeight / 2 ? glm::vec3(1.6f, 0.9f, 0.4f) * (0.5f + float(x) / kWidth)
                                              : glm::vec3(0.05f, 0.1f, 0.3f);
      map.at(x, y) = glm::vec4(value, 1.0f);
      rgb.insert(rgb.end(), {value.r, value.g, value.b});
    }
  const auto dir = output_dir("drop_environment");
  const auto hdr = dir / "made.hdr", exr = dir / "made.exr";
  ASSERT_NE(stbi_write_hdr(hdr.c_str(), kWidth, kHeight, 3, rgb.data()), 0);
  ASSERT_TRUE(image::write_exr(exr, map).ok());
  const std::string script = R"({"events": [
      {"t": 0, "key": "up"},
      {"t": 0, "open": ")" + hdr.string() + R"("},
      {"t": 0.05, "screenshot": "hdr.png", "ui": false},
      {"t": 0.05, "open": ")" + exr.string() + R"("},
      {"t": 0.1, "screenshot": "exr.png", "ui": false}]})";
  const auto run = run_viewer_script(script, "default", kSize, kSize, true, "drop_environment");
  ASSERT_TRUE(run.status.ok()) << run.status.message();
  EXPECT_EQ(run.state["message"], "");
  EXPECT_EQ(std::filesystem::path(run.state["environment"].get<std::string>()), std::filesystem::absolute(exr));
  for (const auto& [file, shot] : {std::pair{hdr, "hdr.png"}, std::pair{exr, "exr.png"}}) {
    scene::Scene scene = scene::default_scene();
    scene.environment.type = scene::Environment::Type::map;
    scene.environment.map_path = std::filesystem::absolute(file).string();
    const auto expected = record_frame(context(), scene, kSize, kSize, 10);
    expect_within_one_code(run.shots.at(shot), expected, "drop_environment", shot);
    EXPECT_GT(max_code_difference(run.shots.at(shot).rgba, record_frame(context(), scene::default_scene(), kSize, kSize, 10)), 16)
        << shot << ": the environment did not change";
  }
}

// W draws the characters' triangle edges over the frame (a UI overlay: absent without the UI).
TEST_F(ViewerOffscreenTest, WireframeKeyDrawsTheTriangleEdges) {
  const auto run = run_viewer_script(R"({"events": [
      {"t": 0, "key": "up"}, {"t": 0, "key": "h"},
      {"t": 0, "screenshot": "before.png", "ui": true}, {"t": 0, "screenshot": "before_again.png", "ui": true},
      {"t": 0, "key": "w"},
      {"t": 0, "screenshot": "wire.png", "ui": true}, {"t": 0, "screenshot": "wire_hidden.png", "ui": false}]})",
                                     "default", kSize * 2, kSize * 2, true, "wireframe");
  ASSERT_TRUE(run.status.ok()) << run.status.message();
  EXPECT_EQ(max_code_difference(run.shots.at("before.png").rgba, run.shots.at("before_again.png").rgba), 0);
  EXPECT_GT(max_code_difference(run.shots.at("before.png").rgba, run.shots.at("wire.png").rgba), 16);
  expect_within_one_code(run.shots.at("wire_hidden.png"), record_frame(context(), scene::default_scene(), kSize * 2, kSize * 2, 10),
                         "wireframe", "wire_hidden");
  EXPECT_TRUE(run.state["toggles"]["wireframe"]);
}

// A model without a cached rig is shown at once without proxies while its rig is fitted (the fit
// held back until three such frames were drawn), then with them.
TEST_F(ViewerOffscreenTest, AModelShowsBeforeItsRigFitCompletes) {
  const auto dir = output_dir("before_fit");
  std::filesystem::remove(dir / "figure.proxies.json");
  std::filesystem::copy_file(PROXYGI_SOURCE_DIR "/assets/mannequin.glb", dir / "figure.glb",
                             std::filesystem::copy_options::overwrite_existing);
  ViewerOptions options;
  options.open = (dir / "figure.glb").string();
  options.assets_dir = PROXYGI_SOURCE_DIR "/assets";
  options.offscreen = true;
  options.width = options.height = 64;
  options.validation = true;
  options.hold_rigs_frames = 3;
  options.quit_when_rigged = true;
  options.state_out = dir / "state.json";
  ASSERT_TRUE(run_viewer(options).ok());
  std::ifstream in(options.state_out);
  const auto state = nlohmann::json::parse(in, nullptr, false);
  EXPECT_EQ(state["previews"], 1);
  EXPECT_GE(state["frames_without_proxies"], 3);
  EXPECT_GT(state["proxies"], 0);
  EXPECT_GT(state["frames"], state["frames_without_proxies"]);
  EXPECT_EQ(state["validation_messages"], 0);
  EXPECT_TRUE(std::filesystem::exists(dir / "figure.proxies.json"));
}

// The HUD's pass times: one fenced timing checks the device's timestamps first; where they are
// plausible, every later update comes from timestamps in a frame shown (here every frame: period
// 0), so the HUD renders no frame of its own. Steady frame times skip the warm-up frames.
TEST_F(ViewerOffscreenTest, HudPassTimesComeFromTheFramesShown) {
  ViewerOptions options = playing_options("hud_pass_times", true, 64, 12);
  options.pass_timing_period_s = 0.0;
  const auto state = run_for_state(options);
  EXPECT_EQ(state["validation_messages"], 0);
  EXPECT_EQ(state["frames"], 12);
  EXPECT_EQ(state["frame_ms_steady"]["frames"], 12 - 1 - int(state["frame_ms_steady"]["warmup_frames"]))
      << "every frame after the warm-up, less the last (its time ends with the next frame)";
  EXPECT_GT(state["frame_ms_steady"]["mean"], 0.0);
  const int shown = state["pass_timings_shown"], in_frame = state["in_frame_pass_timings"];
  if (gpu::timestamps_unusable(context()).empty()) {
    // Frame 1 is timed fenced; frames 2 .. 10 in the frame (11 and 12 are still in flight at the end).
    EXPECT_EQ(in_frame, 9);
    EXPECT_EQ(shown, in_frame + 1);
  } else {
    EXPECT_EQ(in_frame, 0);
    EXPECT_GE(shown, 1);
  }
}

// --measure-blocks without a window: offscreen and readback blocks alternate (validation on).
TEST_F(ViewerOffscreenTest, MeasureBlocksAlternateOffscreenAndReadback) {
  ViewerOptions options = playing_options("measure_blocks", true, 64, 2 * 2 * 3 + 1);
  options.measure_block_frames = 3;
  const auto state = run_for_state(options);
  EXPECT_EQ(state["validation_messages"], 0);
  const auto& blocks = state["measure_blocks_ms"];
  EXPECT_TRUE(blocks["window"].empty());
  EXPECT_TRUE(blocks["window_no_ui"].empty());
  EXPECT_EQ(blocks["offscreen"].size(), 2u);
  EXPECT_EQ(blocks["readback"].size(), 2u);
}

}  // namespace
}  // namespace proxygi::view
