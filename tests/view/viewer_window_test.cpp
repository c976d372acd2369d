// The real window (label display): GLFW + the Vulkan swapchain on an X server the test starts
// (Xvfb), validation on with zero messages. Skipped cleanly when no X server can start.
#include <cstdlib>
#include <fstream>
#include <thread>

#include "gpu/gpu_test_context.h"
#include "scene/scene_defaults.h"
#include "viewer_test_util.h"
#include "xvfb.h"

namespace proxygi::view {
namespace {

using namespace view::testing;

constexpr int kSize = 96;

class ViewerWindowTest : public gpu::testing::GpuTest {
 protected:
  void SetUp() override {
    if (!xvfb_.available()) GTEST_SKIP() << "no X server: " << xvfb_.why_not();
    GpuTest::SetUp();
  }
  Xvfb xvfb_;
};

TEST_F(ViewerWindowTest, SwapchainFrameWithTheUiHiddenIsRecordsFrame) {
  const auto run = run_viewer_script(R"({"events": [
      {"t": 0, "key": "up"}, {"t": 0, "key": "right"},
      {"t": 0.05, "screenshot": "hidden.png", "ui": false}]})",
                                     "default", kSize, kSize, false, "window_record_equal");
  ASSERT_TRUE(run.status.ok()) << run.status.message();
  ASSERT_TRUE(run.shots.count("hidden.png"));
  ASSERT_EQ(run.shots.at("hidden.png").width, kSize);
  expect_within_one_code(run.shots.at("hidden.png"), record_frame(context(), scene::default_scene(), kSize, kSize, 11),
                         "window_record_equal", "hidden");
}

TEST_F(ViewerWindowTest, ResizeMinimizeRestoreAndRecreateMidPlayback) {
  const auto run = run_viewer_script(R"({"events": [
      {"t": 0, "key": "space"},
      {"t": 0.1, "resize": [64, 48]}, {"t": 0.2, "screenshot": "small.png"},
      {"t": 0.3, "resize": [160, 120]}, {"t": 0.4, "screenshot": "large.png"},
      {"t": 0.5, "minimize": true}, {"t": 0.7, "restore": true},
      {"t": 0.8, "resize": [96, 96]},
      {"t": 1.0, "key": "space"}, {"t": 1.0, "key": "left", "shift": true},
      {"t": 1.05, "screenshot": "back.png", "ui": false}]})",
                                     "default", kSize, kSize, false, "window_resize");
  ASSERT_TRUE(run.status.ok()) << run.status.message();  // includes: zero validation messages
  EXPECT_GE(run.state["swapchain_recreations"].get<int>(), 3);
  EXPECT_EQ(run.shots.at("small.png").width, 64);
  EXPECT_EQ(run.shots.at("large.png").height, 120);
  expect_within_one_code(run.shots.at("back.png"), record_frame(context(), scene::default_scene(), kSize, kSize, 0),
                         "window_resize", "back");
}

TEST_F(ViewerWindowTest, AKeyPressFromXdotoolStartsPlayback) {
  if (std::system("command -v xdotool > /dev/null") != 0) GTEST_SKIP() << "xdotool is not installed";
  ViewerOptions options;
  options.open = "default";
  options.assets_dir = PROXYGI_SOURCE_DIR "/assets";
  options.width = options.height = kSize;
  options.validation = true;
  options.max_frames = 2000;  // a bound in case the keys never arrive
  options.state_out = output_dir("xdotool") / "state.json";
  std::thread keys([] {
    // Wait for the window, focus it (no window manager under Xvfb), press Space, then Esc.
    const int pressed = std::system(
        "xdotool search --sync --name 'proxygi' windowfocus --sync key space > /dev/null 2>&1; sleep 1; "
        "xdotool search --name 'proxygi' windowfocus key Escape > /dev/null 2>&1");
    (void)pressed;
  });
  const Status status = run_viewer(options);
  keys.join();
  ASSERT_TRUE(status.ok()) << status.message();
  std::ifstream in(options.state_out);
  const auto state = nlohmann::json::parse(in, nullptr, false);
  EXPECT_TRUE(state["playing"]) << "Space did not reach the window";
  EXPECT_LT(state["frames"].get<int>(), 2000) << "Esc did not reach the window";
  EXPECT_GT(state["time_s"].get<double>(), 0.0);
}

TEST_F(ViewerWindowTest, AMalformedModelOpenedInTheWindowShowsItsErrorAndKeepsTheScene) {
  const auto bad = output_dir("window_malformed") / "broken.gltf";
  std::ofstream(bad) << "{\"asset\": {\"version\": \"2.0\"}, \"meshes\": [{\"primitives\": [{\"attributes\": {\"POSITION\": 7}}]}]}";
  // The same event a file dropped on the window makes (Window::on_drop).
  const std::string script = R"({"events": [
      {"t": 0, "screenshot": "before.png", "ui": true},
      {"t": 0, "open": ")" + bad.string() + R"("},
      {"t": 0.05, "screenshot": "error.png", "ui": true},
      {"t": 0.05, "screenshot": "scene.png", "ui": false}]})";
  const auto run = run_viewer_script(script, "default", 320, 240, false, "window_malformed");
  ASSERT_TRUE(run.status.ok()) << run.status.message();
  EXPECT_EQ(run.state["scene"], "default");
  const std::string message = run.state["message"];
  EXPECT_NE(message.find("broken.gltf"), std::string::npos) << message;
  EXPECT_GT(max_code_difference(run.shots.at("before.png").rgba, run.shots.at("error.png").rgba), 32);  // shown
  write_shot(run.shots.at("error.png"), run.shots.at("error.png").rgba, output_dir("window_malformed") / "error.png");
  expect_within_one_code(run.shots.at("scene.png"), record_frame(context(), scene::default_scene(), 320, 240, 0),
                         "window_malformed", "scene");
}

// The README's screenshot: the window at 960×540 with the HUD, settings, timeline and the
// proxy, skeleton and grid overlays, mid-walk (written to the test output folder).
TEST_F(ViewerWindowTest, ScreenshotOfTheWindowWithItsUi) {
  const auto run = run_viewer_script(R"({"events": [
      {"t": 0, "key": "o"}, {"t": 0, "key": "b"}, {"t": 0, "key": "g"}, {"t": 0, "key": "up"},
      {"t": 0, "key": "up"}, {"t": 0, "key": "up"}, {"t": 0, "key": "up"},
      {"t": 0.05, "drag": {"button": "left", "dx": -60, "dy": 25}}, {"t": 0.05, "scroll": 2},
      {"t": 0.1, "screenshot": "readme.png", "ui": true}]})",
                                     "default", 960, 540, false, "window_readme");
  ASSERT_TRUE(run.status.ok()) << run.status.message();
  const Shot& shot = run.shots.at("readme.png");
  EXPECT_EQ(shot.width, 960);
  write_shot(shot, shot.rgba, output_dir("window_readme") / "viewer.png");
}

// --measure-blocks in a real window: blocks cycle through the window with and without the UI,
// an offscreen image of the swapchain's format and readback, with zero validation messages.
TEST_F(ViewerWindowTest, MeasureBlocksCycleThroughEveryFrameEnding) {
  // Two whole cycles; the last frame's time is never taken.
  ViewerOptions options = playing_options("window_measure_blocks", false, kSize, 2 * 4 * 3 + 1);
  options.measure_block_frames = 3;
  const auto state = run_for_state(options);
  EXPECT_EQ(state["validation_messages"], 0);
  const auto& blocks = state["measure_blocks_ms"];
  EXPECT_EQ(blocks["block_frames"], 3);
  for (const char* end : {"window", "window_no_ui", "offscreen", "readback"}) {
    ASSERT_EQ(blocks[end].size(), 2u) << end;
    for (double ms : blocks[end]) EXPECT_GT(ms, 0.0) << end;
  }
}

// A window moved across the desktop mid-playback (as a move onto another monitor of a RandR
// desktop is: one X screen, the window elsewhere on it) keeps rendering, then paused and sent to
// frame 0 it equals record's frame; zero validation messages. Xvfb's RandR has one output, so
// GLFW sees one monitor: a change of content scale or refresh rate between real monitors is not
// exercised (a content-scale change reaches the viewer as a framebuffer resize, tested above).
TEST_F(ViewerWindowTest, MovingTheWindowMidPlaybackKeepsRendering) {
  const auto run = run_viewer_script(R"({"events": [
      {"t": 0, "key": "space"}, {"t": 0, "move": [0, 0]}, {"t": 0.1, "screenshot": "first.png"},
      {"t": 0.2, "move": [900, 600]}, {"t": 0.4, "screenshot": "moved.png"},
      {"t": 0.6, "key": "space"}, {"t": 0.6, "key": "left", "shift": true},
      {"t": 0.65, "screenshot": "back.png", "ui": false}]})",
                                     "default", kSize, kSize, false, "window_move");
  ASSERT_TRUE(run.status.ok()) << run.status.message();  // includes: zero validation messages
  EXPECT_EQ(run.state["window_position"], nlohmann::json::array({900, 600}));
  EXPECT_GE(run.state["monitors"].get<int>(), 1);
  EXPECT_EQ(run.shots.at("moved.png").width, kSize);
  EXPECT_FALSE(run.state["playing"]);
  expect_within_one_code(run.shots.at("back.png"), record_frame(context(), scene::default_scene(), kSize, kSize, 0),
                         "window_move", "back");
}

}  // namespace
}  // namespace proxygi::view
