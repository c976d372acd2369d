// A CesiumMan frame on the GPU: its albedo AOV shows the base color texture (varies over the
// character) rather than one mean color. Skipped when ../shared/assets is absent.
#include <cstdio>
#include <filesystem>

#include "gpu/scene_renderer.h"
#include "gpu_test_context.h"
#include "scene/scene_defaults.h"

namespace proxygi::gpu {
namespace {

using TextureSharedAssetsTest = testing::GpuTest;

TEST_F(TextureSharedAssetsTest, CesiumManAlbedoVariesOverTheCharacter) {
  const auto model = std::filesystem::path(PROXYGI_SHARED_ASSETS_DIR) / "gltf" / "CesiumMan.glb";
  if (!std::filesystem::exists(model)) GTEST_SKIP() << model << " not found";
  scene::Scene scene = scene::default_scene();
  ASSERT_FALSE(scene.characters.empty());
  scene.characters.resize(1);
  scene.characters[0].model = model.string();
  scene.characters[0].clip = 0;
  scene.characters[0].path.reset();  // stands at the origin
  scene::FixedCamera camera;
  camera.position = glm::vec3(0.0f, 1.0f, 2.6f);
  camera.target = glm::vec3(0.0f, 0.8f, 0.0f);
  camera.fov_degrees = 50.0f;
  scene.camera.kind = camera;
  scene.ground.enabled = false;  // every covered pixel is the character
  scene.output.width = scene.output.height = 128;
  auto renderer = SceneRenderer::create(context(), scene, {PROXYGI_SOURCE_DIR "/assets", false});
  ASSERT_TRUE(renderer.ok()) << renderer.message();
  auto rendered = (*renderer)->render(0);
  ASSERT_TRUE(rendered.ok()) << rendered.message();
  auto positions = (*renderer)->frame().read_gbuffer_positions();
  auto albedo = (*renderer)->frame().read_gbuffer_albedo();
  ASSERT_TRUE(positions.ok() && albedo.ok());
  int covered = 0;
  glm::vec3 low(1e9f), high(-1e9f);
  for (std::size_t i = 0; i < albedo->pixels.size(); ++i) {
    if (positions->pixels[i].w <= 0.0f) continue;
    ++covered;
    low = glm::min(low, glm::vec3(albedo->pixels[i]));
    high = glm::max(high, glm::vec3(albedo->pixels[i]));
  }
  ASSERT_GT(covered, 500) << "the camera should see CesiumMan";
  // The texture spans dark suit and light skin/markings: a spread far beyond rounding.
  const glm::vec3 spread = high - low;
  std::printf("CesiumMan: %d pixels, albedo spread %.3f %.3f %.3f\n", covered, spread.r, spread.g, spread.b);
  EXPECT_GT(std::max({spread.r, spread.g, spread.b}), 0.2f) << "albedo is (nearly) constant over the character";
}

}  // namespace
}  // namespace proxygi::gpu
