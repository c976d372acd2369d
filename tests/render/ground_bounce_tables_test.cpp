// The frame tables' ground bounce (render/frame_tables.h): receivers above the ground read the
// ground-lit LH cubes, the ground keeps the environment's, and the CPU twins give the closed form.
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "render/baselines.h"
#include "render/frame_tables.h"
#include "render/shading.h"
#include "sh/basis.h"

namespace proxygi::render {
namespace {

sh::RgbSh constant_sky(int order, double radiance) {
  sh::RgbSh sky;
  sky.order = order;
  for (auto& channel : sky.channels) {
    channel.assign(std::size_t(order * order), 0.0);
    channel[0] = radiance * sh::kSqrtFourPi;
  }
  return sky;
}

TEST(GroundBounceTables, ReceiverAboveGroundGetsTheClosedFormAndTheGroundIsUnchanged) {
  // White sky L = 1, ground albedo a = (0.8, 0.5, 0.2): E_g = π, g = a. An unoccluded receiver
  // above the ground facing down gets E = a π, a vertical one π (1 + a) / 2; on the ground,
  // facing up, E = π as without the bounce. Tolerance: the cube's bilinear lookup (16² faces).
  settings::RenderSettings settings;
  const glm::vec3 albedo(0.8f, 0.5f, 0.2f);
  const FrameTables tables = make_frame_tables(constant_sky(4, 1.0), settings, GroundInput{true, albedo});
  const float pi = float(sh::kPi);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(tables.ground_radiance[c], albedo[c], 1e-6f);
  const glm::vec3 above(0.0f, 1.0f, 0.0f), on_ground(0.3f, 0.0f, -0.2f);
  const glm::vec3 down = unshadowed_irradiance(tables, above, {0.0f, -1.0f, 0.0f});
  const glm::vec3 side = unshadowed_irradiance(tables, above, glm::normalize(glm::vec3(1.0f, 0.0f, 0.3f)));
  const glm::vec3 up = unshadowed_irradiance(tables, on_ground, {0.0f, 1.0f, 0.0f});
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(down[c], albedo[c] * pi, 2e-3f * pi) << "channel " << c;
    EXPECT_NEAR(side[c], 0.5f * pi * (1.0f + albedo[c]), 2e-3f * pi) << "channel " << c;
    EXPECT_NEAR(up[c], pi, 2e-3f * pi) << "channel " << c;
  }
  // The ground's cubes are those of the tables without a ground, value for value.
  const FrameTables sky_only = make_frame_tables(constant_sky(4, 1.0), settings);
  for (int c = 0; c < 3; ++c) EXPECT_EQ(tables.lighting_cube[std::size_t(c)].values, sky_only.lighting_cube[std::size_t(c)].values);
  // The unoccluded HYB twin agrees with E(N) (O_p = a(0)·1).
  const std::vector<float> no_occlusion(16, 0.0f);
  const DirectResult direct = exponentiate_and_shade(tables, no_occlusion, settings.hyb_tau, above, {0.0f, -1.0f, 0.0f});
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(direct.irradiance[c], down[c], 1e-2f * down[c]);
}

TEST(GroundBounceTables, OffOrWithoutGroundTheSecondCubeSetRepeatsTheFirst) {
  settings::RenderSettings off;
  off.ground_bounce = false;
  const FrameTables tables = make_frame_tables(constant_sky(4, 1.0), off, GroundInput{true, glm::vec3(0.8f)});
  const FrameTables no_ground = make_frame_tables(constant_sky(4, 1.0), settings::RenderSettings{}, GroundInput{false, glm::vec3(0.8f)});
  for (const FrameTables* t : {&tables, &no_ground}) {
    EXPECT_EQ(t->ground_radiance, glm::vec3(0.0f));
    for (int c = 0; c < 3; ++c) EXPECT_EQ(t->lighting_cube[std::size_t(c)].values, t->lighting_cube[std::size_t(3 + c)].values);
  }
}

TEST(GroundBounceTables, CubeSetSwitchesJustAboveTheGroundPlane) {
  EXPECT_EQ(lighting_cube_set({1.0f, 0.0f, 2.0f}), 0);
  EXPECT_EQ(lighting_cube_set({1.0f, -0.5f, 2.0f}), 0);
  EXPECT_EQ(lighting_cube_set({1.0f, 0.01f, 2.0f}), 3);
  EXPECT_EQ(lighting_cube_set({0.0f, 1.7f, 0.0f}), 3);
}

}  // namespace
}  // namespace proxygi::render
