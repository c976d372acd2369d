// Failure mode F8 (notes/stability.md, issue 16): a contact shadow on a ground plane seen at a
// grazing angle, upsampled from k = 4. An absolute depth tolerance made neighbouring ground
// receivers (eye depths ~0.1 m apart) reject each other and the shadow came out in blocks; the
// tangent-plane term relative to eye depth weighs taps on the same plane bilinearly. Checks, on
// the GPU with the validation layer on:
// - on ground pixels whose four taps are ground receivers, bilateral equals bilinear;
// - every covered pixel (ground, a floating wall's silhouette over the ground) matches the CPU
//   twin render::upsample;
// and prints the error of both upsamplers against the k = 1 frame (the blockiness measure).
#include <array>
#include <cstdio>

#include "frame_fixture.h"
#include "gpu_test_context.h"
#include "render/shading.h"
#include "upsample_taps.h"

namespace proxygi::gpu {
namespace {

using testing::GpuTest;
using UpsampleGrazingTest = GpuTest;

constexpr int kSize = 128;
constexpr int kScale = 4;
constexpr float kOnGround = 1e-3f;  // m: receivers and pixels of the plane y = 0

// The ground with a 1.2 m × 0.7 m wall floating 0.2 m above it (normal +Z, facing the camera), so
// its silhouette over the ground is a depth discontinuity.
testing::GroundMesh ground_and_wall() {
  testing::GroundMesh mesh = testing::ground_plane(20.0f, 8);
  const std::uint32_t first = std::uint32_t(mesh.positions.size());
  for (const glm::vec3& corner : {glm::vec3(0.8f, 0.2f, -0.5f), glm::vec3(2.0f, 0.2f, -0.5f), glm::vec3(2.0f, 0.9f, -0.5f),
                                  glm::vec3(0.8f, 0.9f, -0.5f)}) {
    mesh.positions.push_back(corner);
    mesh.normals.emplace_back(0.0f, 0.0f, 1.0f);
  }
  mesh.indices.insert(mesh.indices.end(), {first, first + 1, first + 2, first, first + 2, first + 3});
  return mesh;
}

struct Upsampled {
  testing::RenderedFrame rendered;
  image::ImageF irradiance;
};

Upsampled render(Context& context, int scale, settings::Upsampling upsampling) {
  const std::vector<render::Sphere> spheres = {{{-0.3f, 0.32f, 0.8f}, 0.3f, {0.5f, 0.5f, 0.5f}}};
  FrameConfig config;
  config.width = config.height = kSize;
  config.render.receiver_scale = scale;
  config.render.upsampling = upsampling;
  Upsampled out;
  out.rendered = testing::render_fixture_frame(context, config, sh::project_sky(4, sh::AnalyticSky{}), 4,
                                               ground_and_wall(), spheres, {0.0f, 0.7f, 5.0f});
  if (!out.rendered.frame) return out;
  auto irradiance = out.rendered.frame->read_irradiance();
  EXPECT_TRUE(irradiance.ok());
  if (irradiance.ok()) out.irradiance = std::move(*irradiance);
  return out;
}

float relative_error(const glm::vec3& value, const glm::vec3& expected) {
  return glm::length(value - expected) / std::max(glm::length(expected), 1e-3f);
}

TEST_F(UpsampleGrazingTest, GroundPlaneInterpolatesBilinearlyAndMatchesTheCpuTwin) {
  const Upsampled full = render(context(), 1, settings::Upsampling::bilateral);
  const Upsampled bilateral = render(context(), kScale, settings::Upsampling::bilateral);
  const Upsampled bilinear = render(context(), kScale, settings::Upsampling::bilinear);
  ASSERT_TRUE(full.rendered.frame && bilateral.rendered.frame && bilinear.rendered.frame);
  const SoftGiFrame& frame = *bilateral.rendered.frame;
  auto gbuffer_positions = frame.read_gbuffer_positions();
  auto gbuffer_normals = frame.read_gbuffer_normals();
  auto receiver_positions = frame.read_receiver_positions();
  auto receiver_normals = frame.read_receiver_normals();
  auto shaded = frame.read_shaded();
  ASSERT_TRUE(gbuffer_positions.ok() && gbuffer_normals.ok() && receiver_positions.ok() && receiver_normals.ok() && shaded.ok());
  const int receivers = kSize / kScale;
  const float epsilon = settings::RenderSettings{}.bilateral_depth_epsilon;
  int plane_pixels = 0, covered = 0, shadow_pixels = 0;
  float max_plane_gap = 0.0f;
  float step_bilateral = 0.0f, step_bilinear = 0.0f, step_full = 0.0f;  // max |ΔE.r| to the right neighbour
  double error_bilateral = 0.0, error_bilinear = 0.0, shadow_bilateral = 0.0, shadow_bilinear = 0.0;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const glm::vec4 p = gbuffer_positions->at(x, y);
      if (p.w <= 0.0f) continue;
      ++covered;
      const auto taps = testing::upsample_taps(
          x, y, kScale, receivers, [&](int rx, int ry) { return glm::vec3(shaded->at(rx, ry)); }, *receiver_positions,
          *shaded, *receiver_normals);
      bool all_on_ground = p.y < kOnGround;
      for (const render::UpsampleTap& t : taps) all_on_ground = all_on_ground && t.depth > 0.0f && t.position.y < kOnGround;
      const glm::vec3 gpu(bilateral.irradiance.at(x, y));
      const glm::vec3 expected = render::upsample(taps, glm::vec3(p), p.w, glm::vec3(gbuffer_normals->at(x, y)),
                                                  settings::Upsampling::bilateral, epsilon);
      EXPECT_LE(relative_error(gpu, expected), 1e-3f) << "CPU twin at " << x << "," << y;
      if (!all_on_ground) continue;
      ++plane_pixels;
      const glm::vec3 linear(bilinear.irradiance.at(x, y)), truth(full.irradiance.at(x, y));
      max_plane_gap = std::max(max_plane_gap, relative_error(gpu, linear));
      error_bilateral += relative_error(gpu, truth);
      error_bilinear += relative_error(linear, truth);
      // The shadow: where k = 1 is 2 % below the k = 4 bilinear frame's brightest ground.
      if (truth.r < 0.98f * glm::vec3(bilinear.irradiance.at(x, kSize - 1)).r) {
        ++shadow_pixels;
        shadow_bilateral += relative_error(gpu, truth);
        shadow_bilinear += relative_error(linear, truth);
        if (x + 1 < kSize && gbuffer_positions->at(x + 1, y).y < kOnGround && gbuffer_positions->at(x + 1, y).w > 0.0f) {
          step_bilateral = std::max(step_bilateral, std::abs(bilateral.irradiance.at(x + 1, y).r - gpu.r));
          step_bilinear = std::max(step_bilinear, std::abs(bilinear.irradiance.at(x + 1, y).r - linear.r));
          step_full = std::max(step_full, std::abs(full.irradiance.at(x + 1, y).r - truth.r));
        }
      }
    }
  std::printf("F8 grazing k=%d: %d plane pixels, max |bilateral - bilinear|/bilinear %.4f; mean rel. error vs k=1: "
              "bilateral %.4f, bilinear %.4f; in the shadow (%d px): bilateral %.4f, bilinear %.4f\n",
              kScale, plane_pixels, max_plane_gap, error_bilateral / std::max(plane_pixels, 1),
              error_bilinear / std::max(plane_pixels, 1), shadow_pixels, shadow_bilateral / std::max(shadow_pixels, 1),
              shadow_bilinear / std::max(shadow_pixels, 1));
  std::printf("F8 grazing: max step between neighbouring shadow pixels (E.r): bilateral %.4f, bilinear %.4f, k=1 %.4f\n",
              step_bilateral, step_bilinear, step_full);
  EXPECT_GE(plane_pixels, kSize * kSize / 4);
  EXPECT_GE(shadow_pixels, 20) << "the sphere must cast a contact shadow in view";
  EXPECT_GE(covered, plane_pixels + 50) << "the wall must be in view";
  EXPECT_LE(max_plane_gap, 1e-3f) << "taps on one plane must weigh bilinearly at any depth";
}

}  // namespace
}  // namespace proxygi::gpu
