// A CesiumMan frame on the GPU: its albedo AOV shows the base color texture (varies over the
// character) rather than one mean color, and agrees with the reference path tracer's albedo
// feature (Embree hit at each pixel center, level-0 lookup by the same CPU twin). Skipped when
// ../shared/assets is absent.
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "gpu/scene_renderer.h"
#include "gpu_test_context.h"
#include "ref/reference_render.h"
#include "ref/scene_geometry.h"
#include "scene/camera.h"
#include "scene/scene_defaults.h"
#include "world/world.h"

namespace proxygi::gpu {
namespace {

using TextureSharedAssetsTest = testing::GpuTest;

const std::filesystem::path kCesiumMan = std::filesystem::path(PROXYGI_SHARED_ASSETS_DIR) / "gltf" / "CesiumMan.glb";

scene::Scene cesium_man_scene(int size) {
  scene::Scene scene = scene::default_scene();
  scene.characters.resize(1);
  scene.characters[0].model = kCesiumMan.string();
  scene.characters[0].clip = 0;
  scene.characters[0].path.reset();  // stands at the origin
  scene::FixedCamera camera;
  camera.position = glm::vec3(0.0f, 1.0f, 2.6f);
  camera.target = glm::vec3(0.0f, 0.8f, 0.0f);
  camera.fov_degrees = 50.0f;
  scene.camera.kind = camera;
  scene.ground.enabled = false;  // every covered pixel is the character
  scene.output.width = scene.output.height = size;
  return scene;
}

struct GpuFeatures {
  image::ImageF positions, albedo;
};

GpuFeatures render_gpu(Context& context, const scene::Scene& scene) {
  auto renderer = SceneRenderer::create(context, scene, {PROXYGI_SOURCE_DIR "/assets", false});
  EXPECT_TRUE(renderer.ok()) << (renderer.ok() ? "" : renderer.message());
  if (!renderer.ok()) return {};
  auto rendered = (*renderer)->render(0);
  EXPECT_TRUE(rendered.ok()) << (rendered.ok() ? "" : rendered.message());
  auto positions = (*renderer)->frame().read_gbuffer_positions();
  auto albedo = (*renderer)->frame().read_gbuffer_albedo();
  EXPECT_TRUE(positions.ok() && albedo.ok());
  if (!positions.ok() || !albedo.ok()) return {};
  return {std::move(*positions), std::move(*albedo)};
}

TEST_F(TextureSharedAssetsTest, CesiumManAlbedoVariesOverTheCharacter) {
  if (!std::filesystem::exists(kCesiumMan)) GTEST_SKIP() << kCesiumMan << " not found";
  const GpuFeatures gpu = render_gpu(context(), cesium_man_scene(128));
  ASSERT_EQ(gpu.albedo.width, 128);
  int covered = 0;
  glm::vec3 low(1e9f), high(-1e9f);
  for (std::size_t i = 0; i < gpu.albedo.pixels.size(); ++i) {
    if (gpu.positions.pixels[i].w <= 0.0f) continue;
    ++covered;
    low = glm::min(low, glm::vec3(gpu.albedo.pixels[i]));
    high = glm::max(high, glm::vec3(gpu.albedo.pixels[i]));
  }
  ASSERT_GT(covered, 500) << "the camera should see CesiumMan";
  // The texture spans dark suit and light skin/markings: a spread far beyond rounding.
  const glm::vec3 spread = high - low;
  std::printf("CesiumMan: %d pixels, albedo spread %.3f %.3f %.3f\n", covered, spread.r, spread.g, spread.b);
  EXPECT_GT(std::max({spread.r, spread.g, spread.b}), 0.2f) << "albedo is (nearly) constant over the character";
}

TEST_F(TextureSharedAssetsTest, CesiumManAlbedoAgreesWithTheReference) {
  if (!std::filesystem::exists(kCesiumMan)) GTEST_SKIP() << kCesiumMan << " not found";
  constexpr int kSize = 256;
  const scene::Scene scene = cesium_man_scene(kSize);
  const GpuFeatures gpu = render_gpu(context(), scene);
  ASSERT_EQ(gpu.albedo.width, kSize);
  auto world = world::World::load(scene, {.assets_dir = PROXYGI_SOURCE_DIR "/assets", .load_rigs = false});
  ASSERT_TRUE(world.ok()) << world.message();
  const double t = scene::frame_time_s(scene.output, 0);
  world::WorldState state;
  ASSERT_TRUE((*world)->evaluate(t, std::nullopt, state).ok());
  auto meshes = ref::world_meshes(**world, state, ref::make_scene_geometry(**world));
  ASSERT_TRUE(meshes.ok()) << meshes.message();
  auto embree = ref::EmbreeScene::build(std::move(*meshes));
  ASSERT_TRUE(embree.ok()) << embree.message();
  const auto features = ref::render_features(*embree, scene::evaluate_scene_camera(scene, t), kSize, kSize);

  // The reference's radiance averages jittered rays over each pixel: its albedo as the pixel
  // sees it is the box-filtered one, estimated here with 8×8 stratified rays per pixel.
  const scene::CameraState camera = scene::evaluate_scene_camera(scene, t);
  auto box_albedo = [&](int x, int y, glm::dvec3& mean) {
    mean = glm::dvec3(0.0);
    for (int j = 0; j < 8; ++j)
      for (int i = 0; i < 8; ++i) {
        const scene::Ray ray = scene::ray_through_pixel(camera, kSize, kSize, float(x) + (float(i) + 0.5f) / 8.0f,
                                                        float(y) + (float(j) + 0.5f) / 8.0f);
        const auto hit = embree->intersect(ray.origin, ray.direction);
        if (!hit) return false;  // a silhouette pixel: left out
        mean += glm::dvec3(hit->albedo) / 64.0;
      }
    return true;
  };

  // Interior pixels both see at the same depth (silhouettes differ by rasterization rules).
  int both = 0;
  glm::dvec3 gpu_sum(0.0), reference_sum(0.0), to_center(0.0), to_box(0.0), center_to_box(0.0);
  glm::dvec3 squared_to_box(0.0), squared_center_to_box(0.0);
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const std::size_t i = std::size_t(y * kSize + x);
      if (gpu.positions.pixels[i].w <= 0.0f || features.mask.pixels[i].r <= 0.0f) continue;
      if (std::abs(gpu.positions.pixels[i].w - features.depth.pixels[i].r) > 0.01f) continue;
      glm::dvec3 box;
      if (!box_albedo(x, y, box)) continue;
      ++both;
      const glm::dvec3 g(gpu.albedo.pixels[i]), center(features.albedo.pixels[i]);
      gpu_sum += g;
      reference_sum += center;
      to_center += glm::abs(g - center);
      to_box += glm::abs(g - box);
      squared_to_box += (g - box) * (g - box);
      center_to_box += glm::abs(center - box);
      squared_center_to_box += (center - box) * (center - box);
    }
  ASSERT_GT(both, 2000);
  const glm::dvec3 gpu_mean = gpu_sum / double(both), reference_mean = reference_sum / double(both);
  to_center /= double(both);
  to_box /= double(both);
  center_to_box /= double(both);
  std::printf("CesiumMan %d px: mean albedo GPU %.4f %.4f %.4f, reference %.4f %.4f %.4f; mean |GPU - reference| "
              "at pixel centers %.4f %.4f %.4f, box-filtered over the pixel %.4f %.4f %.4f\n",
              both, gpu_mean.r, gpu_mean.g, gpu_mean.b, reference_mean.r, reference_mean.g, reference_mean.b,
              to_center.r, to_center.g, to_center.b, to_box.r, to_box.g, to_box.b);
  const glm::dvec3 rms = glm::sqrt(squared_to_box / double(both));
  const glm::dvec3 center_rms = glm::sqrt(squared_center_to_box / double(both));
  std::printf("  against the box-filtered albedo: GPU mean |d| %.4f %.4f %.4f, RMS %.4f %.4f %.4f; level-0 center lookup "
              "mean |d| %.4f %.4f %.4f, RMS %.4f %.4f %.4f\n",
              to_box.r, to_box.g, to_box.b, rms.r, rms.g, rms.b, center_to_box.r, center_to_box.g, center_to_box.b,
              center_rms.r, center_rms.g, center_rms.b);
  // Same texels, same orientation and factor: the means over the figure agree within the
  // point-sampling noise of the center lookups (σ_texel / √pixels ≈ 0.3 / √2000 ≈ 0.007).
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(gpu_mean[c], reference_mean[c], 0.01) << "channel " << c;
  // Per pixel, the GPU's mipmapping (with its LOD bias, gpu/material_textures.h) approximates
  // the pixel box the reference's radiance integrates better than level-0 sampling at the pixel
  // center would (the GPU's level-0 lookups equal the reference's center lookups to 4e-4).
  for (int c = 0; c < 3; ++c) {
    EXPECT_LT(to_box[c], center_to_box[c]) << "channel " << c;
    EXPECT_LT(rms[c], center_rms[c]) << "channel " << c;
  }
}

}  // namespace
}  // namespace proxygi::gpu
