// The shared sample characters opened as bare models (`proxygi view MODEL.glb`): each stands on
// the default stage, framed, and its first frame is reported with the time it took (the model
// is copied first, so its fitted rig is cached in the test's folder, not in ../shared).
#include <chrono>

#include "gpu/gpu_test_context.h"
#include "viewer_test_util.h"

namespace proxygi::view {
namespace {

using namespace view::testing;
using ViewerSharedAssetsTest = gpu::testing::GpuTest;

class ViewerSharedCharacter : public ViewerSharedAssetsTest, public ::testing::WithParamInterface<const char*> {};

TEST_P(ViewerSharedCharacter, OpensOnTheDefaultStageAndFillsTheFrame) {
  const std::filesystem::path source = std::filesystem::path(PROXYGI_SHARED_ASSETS_DIR) / "gltf" / GetParam();
  if (!std::filesystem::exists(source)) GTEST_SKIP() << source << " not found";
  const std::string test = std::string("shared_") + GetParam();
  const auto model = output_dir(test) / GetParam();
  std::filesystem::copy_file(source, model, std::filesystem::copy_options::overwrite_existing);
  const auto started = std::chrono::steady_clock::now();
  // The normals view (V twice) as well: the ground's normal is one colour, so the character shows
  // against it whatever its albedo (a white character on the light horizon ground does not, in colour).
  const auto run = run_viewer_script(R"({"events": [{"t": 0, "screenshot": "first.png", "ui": false},
                                                    {"t": 0, "key": "v"}, {"t": 0, "key": "v"},
                                                    {"t": 0, "screenshot": "normals.png", "ui": false}]})",
                                     model.string(), 128, 128, true, test);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  ASSERT_TRUE(run.status.ok()) << run.status.message();
  std::printf("%s: first frame after %.2f s (this run; the rig %s)\n", GetParam(), seconds, "fitted or cached");
  const Shot& shot = run.shots.at("normals.png");
  // Framed: the middle of the picture is the character (its normals differ from the ground's below it).
  const auto pixel = [&](int x, int y) { return &shot.rgba[(std::size_t(y) * shot.width + x) * 4]; };
  int differing = 0;
  for (int y = 40; y < 88; ++y)
    for (int x = 40; x < 88; ++x)
      differing += std::abs(int(pixel(x, y)[0]) - int(pixel(x, 127)[0])) + std::abs(int(pixel(x, y)[2]) - int(pixel(x, 127)[2])) > 40;
  EXPECT_GT(differing, 48 * 48 / 20) << "the character does not show in the middle of the frame";
  write_shot(shot, shot.rgba, output_dir(test) / "normals.png");
}

INSTANTIATE_TEST_SUITE_P(Characters, ViewerSharedCharacter,
                         ::testing::Values("CesiumMan.glb", "Fox.glb", "RiggedSimple.glb"),
                         [](const auto& param_info) { const std::string name(param_info.param); return name.substr(0, name.find('.')); });

}  // namespace
}  // namespace proxygi::view
