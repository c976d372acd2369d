// The three indirect operators of indirect.comp (one pipeline variant each) against their CPU twin
// render::accumulate_indirect at sample receivers (relative error ≤ 1e-3), under a sky with
// directional lighting so that the operators differ.
#include <cmath>

#include "frame_fixture.h"
#include "gpu_test_context.h"
#include "render/shading.h"

namespace proxygi::gpu {
namespace {

using IndirectOperatorTest = testing::GpuTest;

// Order-4 lighting: a bright zenith, a warm side and some band-2/3 structure (unwindowed).
sh::RgbSh directional_sky() {
  sh::RgbSh sky = testing::constant_sky_sh(4, 1.0);
  const double band1[3][3] = {{-0.9, 0.4, 0.3}, {-0.8, 0.2, -0.1}, {-1.1, 0.1, -0.4}};  // m = −1 (−y), 0 (z), 1 (−x)
  for (int c = 0; c < 3; ++c) {
    auto& channel = sky.channels[std::size_t(c)];
    for (int m = 0; m < 3; ++m) channel[std::size_t(1 + m)] = band1[c][m];
    // Every order-3 coefficient non-zero, so that every weight of the exact operator matters.
    channel[4] = 0.15;
    channel[5] = 0.12 - 0.03 * c;
    channel[6] = -0.3 + 0.05 * c;
    channel[7] = -0.1;
    channel[8] = 0.2;
    channel[11] = 0.1;
  }
  return sky;
}


testing::RenderedFrame render(Context& context, settings::IndirectOperator op, const std::vector<render::Sphere>& spheres) {
  FrameConfig config;
  config.width = config.height = 64;
  config.render.receiver_scale = 2;
  config.render.indirect_operator = op;
  return testing::render_fixture_frame(context, config, directional_sky(), 4, testing::ground_plane(20.0f, 4), spheres);
}

float relative_error(const glm::vec3& gpu, const glm::vec3& cpu) {
  return glm::length(gpu - cpu) / std::max(glm::length(cpu), 1e-3f);
}

TEST_F(IndirectOperatorTest, EachOperatorMatchesItsCpuTwinAtSampleReceivers) {
  const std::vector<render::Sphere> spheres = {{{0.0f, 0.8f, 0.0f}, 0.5f, {0.9f, 0.1f, 0.1f}},
                                               {{0.7f, 0.3f, 0.4f}, 0.3f, {0.1f, 0.2f, 0.9f}},
                                               {{-0.6f, 0.1f, -0.3f}, 0.35f, {0.2f, 0.8f, 0.2f}}};  // straddles the plane
  const settings::IndirectOperator operators[] = {settings::IndirectOperator::point, settings::IndirectOperator::averaged,
                                                settings::IndirectOperator::exact};
  std::vector<image::ImageF> results;
  for (settings::IndirectOperator op : operators) {
    SCOPED_TRACE(settings::name_of(op));
    auto rendered = render(context(), op, spheres);
    ASSERT_TRUE(rendered.frame);
    auto positions = rendered.frame->read_receiver_positions();
    auto normals = rendered.frame->read_receiver_normals();
    auto direct = rendered.frame->read_direct();
    auto indirect = rendered.frame->read_indirect();
    ASSERT_TRUE(positions.ok() && normals.ok() && direct.ok() && indirect.ok());
    int checked = 0, lit = 0;
    for (int y = 0; y < positions->height; y += 2)
      for (int x = 0; x < positions->width; x += 2) {
        const glm::vec4 p = positions->at(x, y);
        if (p.w <= 0.0f) continue;
        const glm::vec3 n(normals->at(x, y));
        const auto cpu = render::accumulate_indirect(rendered.tables, glm::vec3(p), n, spheres, direct->at(x, y).w, op);
        EXPECT_LE(relative_error(glm::vec3(indirect->at(x, y)), cpu.irradiance), 1e-3f) << "at " << x << "," << y;
        EXPECT_NEAR(indirect->at(x, y).w, cpu.summed_solid_angle, 1e-3f * cpu.summed_solid_angle + 1e-6f);
        ++checked;
        if (cpu.irradiance.r + cpu.irradiance.g + cpu.irradiance.b > 1e-3f) ++lit;
      }
    EXPECT_GE(checked, 100);
    EXPECT_GE(lit, 30) << "the samples must include receivers lit by the proxies";
    results.push_back(std::move(*indirect));
  }
  // The variants really differ under this sky (else the comparisons above could not tell them apart).
  for (std::size_t a = 0; a < results.size(); ++a)
    for (std::size_t b = a + 1; b < results.size(); ++b) {
      float largest = 0.0f, difference = 0.0f, total = 0.0f;
      for (std::size_t i = 0; i < results[a].pixels.size(); ++i) {
        const glm::vec3 first(results[a].pixels[i]), second(results[b].pixels[i]);
        largest = std::max(largest, relative_error(first, second));
        difference += glm::length(first - second);
        total += glm::length(second);
      }
      std::printf("indirect %s vs %s: mean |difference| %.1f %% of the mean, largest %.1f %%\n",
                  settings::name_of(operators[a]).data(), settings::name_of(operators[b]).data(),
                  100.0f * difference / std::max(total, 1e-6f), 100.0f * largest);
      EXPECT_GT(largest, 1e-2f) << settings::name_of(operators[a]) << " vs "
                                << settings::name_of(operators[b]);
    }
}

}  // namespace
}  // namespace proxygi::gpu
