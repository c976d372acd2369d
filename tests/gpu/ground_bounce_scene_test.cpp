// The ground bounce on the default scene against the path tracer (issue 17 item 1): the
// mannequin's mean radiance over its interior pixels (the reference's character region) against
// the one-bounce reference under the same SH lighting at 256² (frame 40, 32 spp, one seed), with
// and without the bounce, and the open ground unchanged by it (≤ 0.5 %).
#include <memory>

#include "gpu/scene_renderer.h"
#include "gpu_test_context.h"
#include "ref/embree_scene.h"
#include "ref/metrics.h"
#include "ref/path_tracer.h"
#include "ref/reference_render.h"
#include "ref/scene_geometry.h"
#include "scene/scene_defaults.h"

namespace proxygi::gpu {
namespace {

using GroundBounceSceneTest = testing::GpuTest;

constexpr int kSize = 256;
constexpr int kFrame = 40;

TEST_F(GroundBounceSceneTest, BodyRadianceMatchesThePathTracerOnTheDefaultScene) {
  scene::Scene scene = scene::default_scene();
  scene.output.width = scene.output.height = kSize;
  auto loaded = world::World::load(scene, {.assets_dir = PROXYGI_SOURCE_DIR "/assets", .load_rigs = true,
                                           .write_rig_cache = false});
  ASSERT_TRUE(loaded.ok()) << loaded.message();
  const std::shared_ptr<const world::World> world(std::move(*loaded));

  // The path-traced reference of the frame and its character mask.
  world::WorldState state;
  ASSERT_TRUE(world->evaluate(scene::frame_time_s(scene.output, kFrame), std::nullopt, state).ok());
  const ref::SceneGeometry geometry = ref::make_scene_geometry(*world);
  auto meshes = ref::world_meshes(*world, state, geometry);
  ASSERT_TRUE(meshes.ok()) << meshes.message();
  auto embree = ref::EmbreeScene::build(std::move(*meshes));
  ASSERT_TRUE(embree.ok()) << embree.message();
  auto lighting = ref::EnvironmentLight::from_scene(scene, ref::LightingKind::sh, scene.render.sh_order);
  auto background = ref::EnvironmentLight::from_scene(scene, ref::LightingKind::full, scene.render.sh_order);
  ASSERT_TRUE(lighting.ok() && background.ok());
  const ref::PathTracer tracer(*embree, *lighting, *background, {.transport = ref::LightTransport::one_bounce});
  auto sums = ref::render_samples(tracer, state.camera, {.width = kSize, .height = kSize, .spp = 32, .seed = 1});
  ASSERT_TRUE(sums.ok()) << sums.message();
  const image::ImageF reference = ref::to_images(*sums).radiance;
  const ref::PixelFeatures features = ref::render_features(*embree, state.camera, kSize, kSize);
  const ref::ReceiverMask character = ref::mask_from_image(features.character);
  // Open ground: the plane's normal is exactly +Y (the mannequin's never is, to the last bit).
  const ref::ReceiverMask ground = ref::mask_where(kSize, kSize, [&](int x, int y) {
    return features.mask.at(x, y).r > 0.0f && features.normal.at(x, y) == glm::vec4(0.0f, 1.0f, 0.0f, 1.0f);
  });
  ASSERT_GE(character.count(), 150u) << "the mannequin must cover enough pixels";
  ASSERT_GE(ground.count(), 10000u);

  auto renderer = SceneRenderer::create(context(), world, scene.render, kSize, kSize);
  ASSERT_TRUE(renderer.ok()) << renderer.message();
  auto with_bounce = (*renderer)->render(kFrame);
  ASSERT_TRUE(with_bounce.ok()) << with_bounce.message();
  settings::RenderSettings off = scene.render;
  off.ground_bounce = false;
  ASSERT_TRUE((*renderer)->apply_settings(off, kSize, kSize).ok());
  auto without_bounce = (*renderer)->render(kFrame);
  ASSERT_TRUE(without_bounce.ok()) << without_bounce.message();

  const double traced = ref::mean_luminance(reference, &character);
  const double ratio = ref::mean_luminance(with_bounce->hdr, &character) / traced;
  const double ratio_off = ref::mean_luminance(without_bounce->hdr, &character) / traced;
  std::printf("body radiance / path tracer: %.3f with the ground bounce, %.3f without (%zu pixels)\n", ratio, ratio_off,
              character.count());
  EXPECT_NEAR(ratio, 1.0, 0.05);
  EXPECT_LT(ratio_off, ratio - 0.1) << "the ground bounce must add a large part of the body's light";
  const double ground_on = ref::mean_luminance(with_bounce->hdr, &ground);
  EXPECT_NEAR(ground_on / ref::mean_luminance(without_bounce->hdr, &ground), 1.0, 0.005) << "the ground must stay as it was";
  EXPECT_NEAR(ground_on / ref::mean_luminance(reference, &ground), 1.0, 0.01) << "the ground against the path tracer";
}

}  // namespace
}  // namespace proxygi::gpu
