// The VSGL sun variant's frame tables (render/frame_tables.h SunInput, render.vsgl_sun): the
// vertex VPLs' L̃ is the scene's lighting without the sun disc, the sun below the horizon or
// vsgl_sun off keeps the whole L̃, and the scene's sun lands in the tables as the scene states it.
#include <cmath>

#include <gtest/gtest.h>

#include "render/environment_lighting.h"
#include "render/frame_tables.h"
#include "scene/environment.h"
#include "scene/scene_defaults.h"

namespace proxygi::render {
namespace {

scene::Scene sunny_scene(float elevation_degrees) {
  scene::Scene scene = scene::default_scene();
  scene.environment.type = scene::Environment::Type::sky;
  scene.environment.sun.elevation_degrees = elevation_degrees;
  return scene;
}

TEST(VsglSunTables, SendersAreLitByTheLightingWithoutTheSun) {
  const scene::Scene scene = sunny_scene(50.0f);
  const int order = 4;
  const sh::AnalyticSky sky = to_sh_sky(scene.environment);
  sh::AnalyticSky dark = sky;
  dark.sun_radiance = glm::dvec3(0.0);
  settings::RenderSettings settings;
  settings.indirect_method = settings::IndirectMethod::vsgl;
  const SunInput sun = scene_sun(scene, order);
  ASSERT_TRUE(sun.present);
  const FrameTables tables = make_frame_tables(sh::project_sky(order, sky), settings, {}, {}, sun);
  const FrameTables without_sun = make_frame_tables(sh::project_sky(order, dark), settings);
  ASSERT_TRUE(tables.vsgl_sun);
  double sun_share = 0.0;
  for (int c = 0; c < 3; ++c)
    for (int i = 0; i < 9; ++i) {
      const float expected = without_sun.irradiance_order3[std::size_t(c)][std::size_t(i)];
      EXPECT_NEAR(tables.vsgl_sender_order3[std::size_t(c)][std::size_t(i)], expected,
                  1e-5f * std::abs(tables.irradiance_order3[std::size_t(c)][0])) << c << " " << i;
      sun_share += std::abs(tables.irradiance_order3[std::size_t(c)][std::size_t(i)] - expected);
    }
  EXPECT_GT(sun_share, 0.1);  // the sun is a large part of the default sky's L̃
  const glm::vec3 irradiance = scene::AnalyticSky(scene.environment).sun_irradiance();
  EXPECT_EQ(tables.sun_irradiance, irradiance);
  EXPECT_NEAR(glm::distance(tables.sun_direction, scene::sun_direction(scene.environment)), 0.0f, 1e-6f);
}

TEST(VsglSunTables, SunBelowTheHorizonOrOffKeepsTheWholeIrradiance) {
  settings::RenderSettings settings;
  settings.indirect_method = settings::IndirectMethod::vsgl;
  for (const bool below : {true, false}) {
    const scene::Scene scene = sunny_scene(below ? -10.0f : 50.0f);
    settings.vsgl_sun = below ? settings::VsglSun::automatic : settings::VsglSun::off;
    const sh::RgbSh lighting = sh::project_sky(4, to_sh_sky(scene.environment));
    const FrameTables tables = make_frame_tables(lighting, settings, {}, {}, scene_sun(scene, 4));
    EXPECT_FALSE(tables.vsgl_sun) << below;
    EXPECT_EQ(tables.vsgl_sender_order3, tables.irradiance_order3) << below;
  }
}

}  // namespace
}  // namespace proxygi::render
