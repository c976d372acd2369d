#pragma once
// Helpers for the viewer tests: run the viewer application in this process with a script and
// keep its screenshots in memory (the PNG writer is replaced), read its state file, and render
// the frame `record` renders for the same scene, time and settings.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "gpu/scene_renderer.h"
#include "image/image.h"
#include "scene/scene.h"
#include "view/viewer_app.h"

namespace proxygi::view::testing {

struct Shot {
  std::vector<std::uint8_t> rgba;
  int width = 0, height = 0;
};

struct ViewerRun {
  Status status;
  std::map<std::string, Shot> shots;  // by the script's screenshot path
  nlohmann::json state;
};

inline std::filesystem::path output_dir(const std::string& test) {
  const std::filesystem::path dir = std::filesystem::path(PROXYGI_TEST_OUTPUT_DIR) / "view" / test;
  std::filesystem::create_directories(dir);
  return dir;
}

// Runs `proxygi view` with `script_json`; screenshots are captured, not written. `adjust`
// changes further options.
inline ViewerRun run_viewer_script(const std::string& script_json, const std::string& open, int width, int height,
                                   bool offscreen, const std::string& test,
                                   const std::function<void(ViewerOptions&)>& adjust = nullptr) {
  ViewerRun run;
  ViewerOptions options;
  options.open = open;
  options.assets_dir = PROXYGI_SOURCE_DIR "/assets";
  options.offscreen = offscreen;
  options.width = width, options.height = height;
  options.validation = true;
  auto script = parse_script(script_json);
  EXPECT_TRUE(script.ok()) << script.message();
  if (!script) return run;
  options.script = std::move(*script);
  options.state_out = output_dir(test) / "state.json";
  options.write_png = [&run](const std::filesystem::path& path, std::span<const std::uint8_t> rgba, int w, int h) {
    run.shots[path.string()] = Shot{{rgba.begin(), rgba.end()}, w, h};
    return Status{};
  };
  if (adjust) adjust(options);
  run.status = view::run_viewer(options);
  std::ifstream in(options.state_out);
  if (in) run.state = nlohmann::json::parse(in, nullptr, false);
  return run;
}

// A run without a script: the default scene playing for `max_frames` frames at size², validation
// on, the adaptive resolution off, the state file in the test's output folder.
inline ViewerOptions playing_options(const std::string& test, bool offscreen, int size, int max_frames) {
  ViewerOptions options;
  options.open = "default";
  options.assets_dir = PROXYGI_SOURCE_DIR "/assets";
  options.offscreen = offscreen;
  options.width = options.height = size;
  options.validation = true;
  options.play = true;
  options.adaptive_resolution = false;
  options.max_frames = max_frames;
  options.state_out = output_dir(test) / "state.json";
  return options;
}

// Runs the viewer (expecting success) and reads its state file (discarded JSON when absent).
inline nlohmann::json run_for_state(const ViewerOptions& options) {
  const Status status = view::run_viewer(options);
  EXPECT_TRUE(status.ok()) << status.message();
  std::ifstream in(options.state_out);
  return nlohmann::json::parse(in, nullptr, false);
}

// The largest per-channel difference of two RGBA8 images (255 when sizes differ).
inline int max_code_difference(const std::vector<std::uint8_t>& a, const std::vector<std::uint8_t>& b) {
  if (a.size() != b.size()) return 255;
  int worst = 0;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (i % 4 != 3) worst = std::max(worst, std::abs(int(a[i]) - int(b[i])));
  return worst;
}

// Writes a captured screenshot as a PNG (to look at, or for docs/).
inline void write_shot(const Shot& shot, const std::vector<std::uint8_t>& rgba, const std::filesystem::path& file) {
  (void)image::write_png_rgba8(file, rgba, shot.width, shot.height);
}

// Within one sRGB code of `expected`; on failure both are written to output_dir(test) to look at.
inline void expect_within_one_code(const Shot& shot, const std::vector<std::uint8_t>& expected, const std::string& test,
                                   const std::string& name) {
  const int worst = max_code_difference(shot.rgba, expected);
  EXPECT_LE(worst, 1) << name << ": the viewer's frame differs from record's";
  if (worst <= 1 || shot.rgba.size() != expected.size()) return;
  write_shot(shot, shot.rgba, output_dir(test) / (name + ".viewer.png"));
  write_shot(shot, expected, output_dir(test) / (name + ".record.png"));
}

// `record`'s frame: a scene renderer over the scene at its output size, frame `frame`.
inline std::vector<std::uint8_t> record_frame(gpu::Context& context, scene::Scene scene, int width, int height,
                                              int frame) {
  scene.output.width = width, scene.output.height = height;
  auto renderer = gpu::SceneRenderer::create(context, scene, {PROXYGI_SOURCE_DIR "/assets", false});
  EXPECT_TRUE(renderer.ok()) << renderer.message();
  if (!renderer) return {};
  auto finished = (*renderer)->render(frame);
  EXPECT_TRUE(finished.ok()) << finished.message();
  return finished.ok() ? finished->ldr : std::vector<std::uint8_t>{};
}

}  // namespace proxygi::view::testing
