// Failure mode F4 (SH ringing, notes/stability.md): the band-limited visibility of large caps
// overshoots 1 outside them, so a receiver next to a big proxy could come out brighter than with
// no proxy at all (issue 16: 1.15× on the ground beside a character with large spheres). Over
// ground receivers around large spheres under a sun and sky, the shadowed direct light ψ must lie
// in [0, ψ_unshadowed (1 + 1/255)], on the GPU (exponentiate.comp) and in its CPU twin
// (render::exponentiate_and_shade), at SH orders 3–6. Validation layer on.
#include <algorithm>
#include <cstdio>

#include "frame_fixture.h"
#include "gpu_test_context.h"
#include "render/shading.h"

namespace proxygi::gpu {
namespace {

using testing::GpuTest;
using VisibilityBoundsTest = GpuTest;

// Spheres large for the scene and overlapping, as on a character whose spheres are large for its
// limbs: three clusters of eight r = 0.5 m spheres (0.1–0.3 m apart, so the ground receivers'
// log vectors grow large), one resting on the ground, one floating, one cut by the ground; a high
// sun, where the overshoot of the summed caps was largest (order 6: 1.0054× on 8 receivers before
// the clamp; orders 3–5 stayed at or below 1).
std::vector<render::Sphere> large_spheres() {
  std::vector<render::Sphere> spheres;
  const glm::vec3 cluster_base[] = {{0.0f, 0.5f, 0.0f}, {-1.8f, 1.0f, -0.6f}, {1.6f, 0.25f, -0.9f}};
  for (const glm::vec3& base : cluster_base)
    for (int i = 0; i < 8; ++i)
      spheres.push_back({base + glm::vec3(0.1f * float(i % 3), 0.15f * float(i / 3), 0.1f * float(i % 2)), 0.5f, glm::vec3(0.5f)});
  return spheres;
}

sh::AnalyticSky high_sun() {
  sh::AnalyticSky sky;
  sky.sun_direction = glm::normalize(glm::dvec3(0.36, 0.93, 0.0));
  return sky;
}

struct Bounds {
  float max_ratio = 0.0f;       // max ψ / ψ_unshadowed (per channel)
  float min_value = 1e30f;      // min ψ
  int brighter_by_1_percent = 0;
  int over_bound = 0;           // ψ > ψ_unshadowed (1 + 1/255) or ψ < 0
  int receivers = 0;
  void add(const glm::vec3& value, const glm::vec3& unshadowed) {
    ++receivers;
    bool brighter = false, over = false;
    for (int c = 0; c < 3; ++c) {
      max_ratio = std::max(max_ratio, value[c] / std::max(unshadowed[c], 1e-6f));
      min_value = std::min(min_value, value[c]);
      brighter = brighter || value[c] > 1.01f * unshadowed[c];
      over = over || value[c] > unshadowed[c] * (1.0f + 1.0f / 255.0f) || value[c] < 0.0f;
    }
    brighter_by_1_percent += brighter ? 1 : 0;
    over_bound += over ? 1 : 0;
  }
  void print(const char* what, int order) const {
    std::printf("F4 %s n=%d: %d receivers, max psi/unshadowed %.4f, min psi %.4g, >1%% brighter %.2f%%, over bound %d\n",
                what, order, receivers, max_ratio, min_value, 100.0 * brighter_by_1_percent / std::max(receivers, 1),
                over_bound);
  }
};

TEST_F(VisibilityBoundsTest, NoReceiverIsBrighterThanUnshadowedNorNegative) {
  const std::vector<render::Sphere> spheres = large_spheres();
  for (int order = 3; order <= 6; ++order) {
    SCOPED_TRACE("SH order " + std::to_string(order));
    FrameConfig config;
    config.width = config.height = 64;
    config.render.receiver_scale = 1;
    config.render.indirect_method = settings::IndirectMethod::none;
    const sh::RgbSh sky = sh::project_sky(order, high_sun());
    auto rendered = testing::render_fixture_frame(context(), config, sky, order, testing::ground_plane(20.0f, 4), spheres,
                                                  {0.0f, 4.5f, 4.5f});
    ASSERT_TRUE(rendered.frame);
    auto direct = rendered.frame->read_direct();
    ASSERT_TRUE(direct.ok());
    const std::vector<float> no_occlusion(std::size_t(order * order), 0.0f);
    Bounds gpu_bounds, cpu_bounds;
    int occluded = 0;
    testing::for_each_receiver(*rendered.frame, 1, [&](const testing::ReceiverSample& r) {
      const auto log = render::accumulate_log_occlusion(rendered.tables, r.position, r.normal, spheres);
      const auto cpu = render::exponentiate_and_shade(rendered.tables, log, config.render.hyb_tau, r.position, r.normal);
      const auto open = render::exponentiate_and_shade(rendered.tables, no_occlusion, config.render.hyb_tau, r.position, r.normal);
      gpu_bounds.add(glm::vec3(direct->at(r.x, r.y)), open.irradiance);
      cpu_bounds.add(cpu.irradiance, open.irradiance);
      occluded += std::any_of(log.begin(), log.end(), [](float v) { return v != 0.0f; }) ? 1 : 0;
    });
    gpu_bounds.print("gpu", order);
    cpu_bounds.print("cpu", order);
    EXPECT_GE(occluded, 500) << "the spheres must reach many ground receivers";
    EXPECT_EQ(gpu_bounds.over_bound, 0) << "GPU: max ratio " << gpu_bounds.max_ratio << ", min " << gpu_bounds.min_value;
    EXPECT_EQ(cpu_bounds.over_bound, 0) << "CPU twin: max ratio " << cpu_bounds.max_ratio << ", min " << cpu_bounds.min_value;
  }
}

}  // namespace
}  // namespace proxygi::gpu
