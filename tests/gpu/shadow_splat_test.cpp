// The raster shadow splat (ShadowSplatPass): its bounding mesh, its log-occlusion vectors against
// the CPU twin at sample receivers (relative error ≤ 1e-3), and whole frames against the compute
// gather (the other splat method), with the validation layer on.
#include <cmath>

#include "frame_fixture.h"
#include "gpu/scene_renderer.h"
#include "gpu/shadow_splat_pass.h"
#include "gpu_test_context.h"
#include "render/shading.h"
#include "scene/scene_defaults.h"

namespace proxygi::gpu {
namespace {

using ShadowSplatTest = testing::GpuTest;


testing::RenderedFrame render_plane(Context& context, settings::SplatMethod splat, int order, std::uint32_t size,
                                    std::uint32_t scale, const std::vector<render::Sphere>& spheres, const glm::vec3& eye) {
  FrameConfig config;
  config.width = config.height = size;
  config.render.receiver_scale = scale;
  config.render.splat = splat;
  return testing::render_fixture_frame(context, config, testing::constant_sky_sh(order, 1.0), order,
                                       testing::ground_plane(20.0f, 4), spheres, eye);
}

// Spheres over, straddling and overlapping the plane, and a small one whose sphere of influence
// contains the eye (eye {0, 1, 4}): its bounding mesh surrounds the camera.
const std::vector<render::Sphere> kSpheres = {{{0.0f, 0.8f, 0.0f}, 0.5f, {0.9f, 0.1f, 0.1f}},
                                              {{0.7f, 0.3f, 0.4f}, 0.3f, {0.1f, 0.2f, 0.9f}},
                                              {{-0.6f, 0.1f, 0.9f}, 0.25f, {0.5f, 0.5f, 0.5f}},
                                              {{0.0f, 0.5f, 3.0f}, 0.15f, {0.5f, 0.5f, 0.5f}}};
const glm::vec3 kEye{0.0f, 1.0f, 4.0f};

TEST(ShadowSplatMesh, BoundingMeshContainsTheUnitSphereAndFacesOutward) {
  const auto mesh = unit_sphere_bounding_mesh();
  ASSERT_EQ(mesh.size(), 240u);
  float farthest = 0.0f;
  for (std::size_t i = 0; i < mesh.size(); i += 3) {
    const glm::vec3 a(mesh[i]), b(mesh[i + 1]), c(mesh[i + 2]);
    const glm::vec3 normal = glm::normalize(glm::cross(b - a, c - a));
    EXPECT_GE(glm::dot(normal, a), 1.0f) << "face " << i / 3 << " cuts into the unit sphere or faces inward";
    farthest = std::max(farthest, glm::length(a));
  }
  EXPECT_LT(farthest, 1.1f) << "coarse but not loose";
}

TEST_F(ShadowSplatTest, RasterSplatMatchesCpuTwinAtSampleReceivers) {
  for (int order : {4, 6}) {  // order 6: 9 targets, two draws of 5
    for (std::uint32_t scale : {1u, 2u}) {
      auto rendered = render_plane(context(), settings::SplatMethod::raster, order, 64, scale, kSpheres, kEye);
      ASSERT_TRUE(rendered.frame);
      auto log_occlusion = rendered.frame->read_log_occlusion();
      ASSERT_TRUE(log_occlusion.ok());
      int checked = 0, shadowed = 0;
      testing::for_each_receiver(*rendered.frame, 2, [&](const testing::ReceiverSample& r) {
        const auto cpu = render::accumulate_log_occlusion(rendered.tables, r.position, r.normal, kSpheres);
        const auto error = testing::log_occlusion_error(*log_occlusion, r.index, cpu);
        EXPECT_LE(error.difference, 1e-3f * error.norm + 1e-6f)
            << "order " << order << ", k " << scale << ", receiver " << r.x << "," << r.y;
        ++checked;
        if (error.norm > 1e-2f) ++shadowed;
      });
      EXPECT_GE(checked, 100 / int(scale * scale));
      EXPECT_GE(shadowed, 20 / int(scale * scale)) << "the samples must include shadowed receivers";
    }
  }
}

TEST_F(ShadowSplatTest, RasterSplatMatchesComputeGatherOnWholeFrames) {
  for (int order : {3, 5}) {
    for (std::uint32_t scale : {1u, 4u}) {
      auto raster = render_plane(context(), settings::SplatMethod::raster, order, 96, scale, kSpheres, kEye);
      auto gather = render_plane(context(), settings::SplatMethod::compute, order, 96, scale, kSpheres, kEye);
      ASSERT_TRUE(raster.frame && gather.frame);
      auto raster_log = raster.frame->read_log_occlusion();
      auto gather_log = gather.frame->read_log_occlusion();
      auto raster_hdr = raster.frame->read_hdr();
      auto gather_hdr = gather.frame->read_hdr();
      ASSERT_TRUE(raster_log.ok() && gather_log.ok() && raster_hdr.ok() && gather_hdr.ok());
      ASSERT_EQ(raster_log->size(), gather_log->size());
      const std::size_t coefficients = std::size_t(order * order);
      int shadowed = 0, mismatched = 0;
      for (std::size_t receiver = 0; receiver < raster_log->size() / coefficients; ++receiver) {
        float difference = 0.0f, norm = 0.0f;
        for (std::size_t i = 0; i < coefficients; ++i) {
          const float a = (*raster_log)[receiver * coefficients + i], b = (*gather_log)[receiver * coefficients + i];
          difference += (a - b) * (a - b);
          norm += b * b;
        }
        if (std::sqrt(difference) > 1e-3f * std::sqrt(norm) + 1e-6f) ++mismatched;
        if (norm > 1e-4f) ++shadowed;
      }
      EXPECT_EQ(mismatched, 0) << "order " << order << ", k " << scale;
      EXPECT_GE(shadowed, 50 / int(scale * scale));
      float worst = 0.0f;
      for (std::size_t i = 0; i < raster_hdr->pixels.size(); ++i)
        worst = std::max(worst, glm::length(glm::vec3(raster_hdr->pixels[i] - gather_hdr->pixels[i])) /
                                    std::max(glm::length(glm::vec3(gather_hdr->pixels[i])), 1e-3f));
      EXPECT_LE(worst, 1e-3f) << "radiance, order " << order << ", k " << scale;
    }
  }
}

TEST_F(ShadowSplatTest, SceneRenderSplatRasterMatchesComputeOnTheDefaultScene) {
  // render.splat selects the splat through SceneRenderer; the animated character's proxies, the
  // real camera and k = 4 give the same picture either way (within one sRGB code).
  scene::Scene scene = scene::default_scene();
  scene.output.width = scene.output.height = 128;
  std::vector<std::uint8_t> pictures[2];
  for (settings::SplatMethod splat : {settings::SplatMethod::compute, settings::SplatMethod::raster}) {
    scene.render.splat = splat;
    auto renderer = SceneRenderer::create(context(), scene, {PROXYGI_SOURCE_DIR "/assets", false});
    ASSERT_TRUE(renderer.ok()) << renderer.message();
    ASSERT_EQ((*renderer)->frame().settings().splat,
              splat == settings::SplatMethod::raster ? settings::SplatMethod::raster : settings::SplatMethod::compute);
    auto rendered = (*renderer)->render(40);
    ASSERT_TRUE(rendered.ok()) << rendered.message();
    pictures[splat == settings::SplatMethod::raster ? 1 : 0] = rendered->ldr;
  }
  ASSERT_EQ(pictures[0].size(), pictures[1].size());
  int largest = 0;
  for (std::size_t i = 0; i < pictures[0].size(); ++i)
    largest = std::max(largest, std::abs(int(pictures[0][i]) - int(pictures[1][i])));
  EXPECT_LE(largest, 1);
}

}  // namespace
}  // namespace proxygi::gpu
