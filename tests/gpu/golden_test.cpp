// Golden frames of the built-in default scene at 256×256 (frames 0, 40 and 90), compared by
// run::compare_with_golden with the tolerance Filament uses across drivers (rendering-notes §3.3):
// a pixel fails when any channel differs by more than 5/255, and at most 0.1 % of pixels may fail.
// On the driver that made the goldens (lavapipe, Mesa 22.3.6) the frames are bit-identical; another
// driver may round the transcendental functions and silhouette coverage differently, which this
// bound absorbs. PROXYGI_UPDATE_GOLDEN=1 rewrites tests/golden/*.png from the current renderer.
#include <cstdlib>
#include <filesystem>

#include "gpu/scene_renderer.h"
#include "gpu_test_context.h"
#include "run/golden.h"
#include "scene/scene_defaults.h"

namespace proxygi::gpu {
namespace {

using GoldenTest = testing::GpuTest;

TEST_F(GoldenTest, DefaultSceneFramesMatchGoldens) {
  scene::Scene scene = scene::default_scene();
  scene.output.width = scene.output.height = 256;
  auto renderer = SceneRenderer::create(context(), scene, {PROXYGI_SOURCE_DIR "/assets", false});
  ASSERT_TRUE(renderer.ok()) << renderer.message();
  const bool update = std::getenv("PROXYGI_UPDATE_GOLDEN") != nullptr;
  for (int frame : {0, 40, 90}) {
    auto rendered = (*renderer)->render(frame);
    ASSERT_TRUE(rendered.ok()) << rendered.message();
    const std::filesystem::path golden =
        std::filesystem::path(PROXYGI_SOURCE_DIR) / "tests/golden" / ("default_256_frame" + std::to_string(frame) + ".png");
    if (update) {
      ASSERT_TRUE(run::write_golden(rendered->ldr, 256, 256, golden).ok());
      continue;
    }
    auto comparison = run::compare_with_golden(rendered->ldr, 256, 256, golden);
    ASSERT_TRUE(comparison.ok()) << comparison.message() << " (PROXYGI_UPDATE_GOLDEN=1 makes it)";
    EXPECT_TRUE(comparison->passed) << "frame " << frame << ": " << comparison->failing_pixels
                                    << " pixels differ by more than 5/255";
    std::printf("frame %d: %d of 65536 pixels beyond 5/255, %d differ at all (largest %d codes)\n", frame,
                comparison->failing_pixels, comparison->differing_pixels, comparison->largest_difference);
  }
}

// The 20-mannequin crowd at 128×128 (frames 0 and 3; goldens rendered by the renderer before
// the crowd's per-model buffer sharing, 2026-12-02): speed work on the crowd (shared buffers,
// batched draws or dispatches) must keep its frames bit-identical on lavapipe.
TEST_F(GoldenTest, CrowdFramesMatchGoldens) {
  scene::Scene scene = scene::crowd_scene();
  scene.output.width = scene.output.height = 128;
  auto renderer = SceneRenderer::create(context(), scene, {PROXYGI_SOURCE_DIR "/assets", false});
  ASSERT_TRUE(renderer.ok()) << renderer.message();
  const bool update = std::getenv("PROXYGI_UPDATE_GOLDEN") != nullptr;
  const bool reference_driver = context().report().name.find("llvmpipe") != std::string::npos;
  for (int frame : {0, 3}) {
    auto rendered = (*renderer)->render(frame);
    ASSERT_TRUE(rendered.ok()) << rendered.message();
    const std::filesystem::path golden =
        std::filesystem::path(PROXYGI_SOURCE_DIR) / "tests/golden" / ("crowd_128_frame" + std::to_string(frame) + ".png");
    if (update) {
      ASSERT_TRUE(run::write_golden(rendered->ldr, 128, 128, golden).ok());
      continue;
    }
    auto comparison = run::compare_with_golden(rendered->ldr, 128, 128, golden);
    ASSERT_TRUE(comparison.ok()) << comparison.message() << " (PROXYGI_UPDATE_GOLDEN=1 makes it)";
    EXPECT_TRUE(comparison->passed) << "frame " << frame << ": " << comparison->failing_pixels
                                    << " pixels differ by more than 5/255";
    if (reference_driver) {
      EXPECT_EQ(comparison->differing_pixels, 0) << "frame " << frame << ": the goldens were made on lavapipe";
    }
  }
}

}  // namespace
}  // namespace proxygi::gpu
