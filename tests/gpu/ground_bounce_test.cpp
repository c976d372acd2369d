// The ground bounce on the GPU against its CPU twin (exponentiate.comp ↔ render::exponentiate_and_shade
// with the ground-lit cube set above the ground), validation layer on: a vertical wall standing
// above the ground under the default sky with its sun (below-horizon colour darkened), one proxy
// shadowing part of it.
#include <cmath>

#include "frame_fixture.h"
#include "gpu_test_context.h"
#include "render/shading.h"

namespace proxygi::gpu {
namespace {

using testing::GpuTest;
using GroundBounceTest = GpuTest;

// The fixture's ground with a 2 m × 1 m wall floating 0.3 m above it (normal +Z, facing the camera).
testing::GroundMesh ground_and_wall() {
  testing::GroundMesh mesh = testing::ground_plane(20.0f, 4);
  const std::uint32_t first = std::uint32_t(mesh.positions.size());
  for (const glm::vec3& corner : {glm::vec3(-1.0f, 0.3f, 0.0f), glm::vec3(1.0f, 0.3f, 0.0f), glm::vec3(1.0f, 1.3f, 0.0f),
                                  glm::vec3(-1.0f, 1.3f, 0.0f)}) {
    mesh.positions.push_back(corner);
    mesh.normals.emplace_back(0.0f, 0.0f, 1.0f);
  }
  mesh.indices.insert(mesh.indices.end(), {first, first + 1, first + 2, first, first + 2, first + 3});
  return mesh;
}

float relative_error(const glm::vec3& gpu, const glm::vec3& cpu) {
  return glm::length(gpu - cpu) / std::max(glm::length(cpu), 1e-3f);
}

TEST_F(GroundBounceTest, ReceiversAboveTheGroundMatchTheCpuTwinAndGetTheBounce) {
  const std::vector<render::Sphere> spheres = {{{0.3f, 0.8f, 0.5f}, 0.3f, {0.5f, 0.5f, 0.5f}}};
  FrameConfig config;
  config.width = config.height = 64;
  config.render.receiver_scale = 2;
  sh::AnalyticSky analytic;
  analytic.ground = glm::dvec3(0.05);  // a dark distant ground, so the lit one shows
  const sh::RgbSh sky = sh::project_sky(4, analytic);
  const render::GroundInput ground{true, glm::vec3(0.8f)};
  auto rendered = testing::render_fixture_frame(context(), config, sky, 4, ground_and_wall(), spheres,
                                                {0.0f, 2.5f, 3.5f}, ground);
  ASSERT_TRUE(rendered.frame);
  config.render.sh_order = 4;
  const render::FrameTables sky_only = render::make_frame_tables(sky, config.render);
  auto direct = rendered.frame->read_direct();
  ASSERT_TRUE(direct.ok());
  int on_wall = 0, shadowed_on_wall = 0, on_ground = 0;
  testing::for_each_receiver(*rendered.frame, 1, [&](const testing::ReceiverSample& r) {
    const auto log = render::accumulate_log_occlusion(rendered.tables, r.position, r.normal, spheres);
    const auto cpu = render::exponentiate_and_shade(rendered.tables, log, 0.25f, r.position, r.normal);
    const glm::vec3 gpu(direct->at(r.x, r.y));
    EXPECT_LE(relative_error(gpu, cpu.irradiance), 1e-3f) << "direct at " << r.x << "," << r.y;
    const auto without = render::exponentiate_and_shade(sky_only, log, 0.25f, r.position, r.normal);
    if (r.position.y > 0.01f) {
      // The lit ground (E_g ≈ 3, albedo 0.8) outshines the sky's below-horizon colour.
      EXPECT_GT(gpu.r, 1.1f * without.irradiance.r) << "wall receiver " << r.x << "," << r.y << " got no bounce";
      ++on_wall;
      if (cpu.occlusion_dc < 0.95f * 3.5449077f) ++shadowed_on_wall;
    } else {
      EXPECT_EQ(cpu.irradiance, without.irradiance) << "ground receiver " << r.x << "," << r.y << " changed";
      ++on_ground;
    }
  });
  EXPECT_GE(on_wall, 50);
  EXPECT_GE(shadowed_on_wall, 5) << "the proxy must occlude the bounce on some wall receivers";
  EXPECT_GE(on_ground, 50);
}

}  // namespace
}  // namespace proxygi::gpu
