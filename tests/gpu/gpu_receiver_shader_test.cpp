// The stability sweeps' GPU receiver (run/gpu_receiver_shader.h): the ground receiver at the origin
// rendered by the real frame, with the shadow gather and with the raster splat, equals the CPU
// twin the sweeps run (study::shade_method) for a sphere inside, at the edge of and beyond its
// influence η r, under the sweeps' sky and delta lights. Validation layer on.
#include "gpu_test_context.h"
#include "run/gpu_receiver_shader.h"
#include "study/stability_shading.h"

namespace proxygi::gpu {
namespace {

using testing::GpuTest;
using GpuReceiverShaderTest = GpuTest;

TEST_F(GpuReceiverShaderTest, GatherAndSplatEqualTheCpuTwinAcrossTheInfluenceFade) {
  auto shader = run::make_gpu_receiver_shader(context());
  ASSERT_TRUE(shader) << shader.message();
  const glm::vec3 up(0.0f, 1.0f, 0.0f), direction = glm::normalize(glm::vec3(1.0f, 1.0f, 0.0f));
  const float r = 0.1f;
  // η = 15: inside (3r), near the cut (13r, 14.8r) and beyond it (16r: no shadow at all).
  std::vector<std::vector<render::Sphere>> frames;
  for (float distance : {3.0f, 13.0f, 14.8f, 16.0f}) frames.push_back({render::Sphere{direction * (r * distance), r, glm::vec3(0.8f)}});
  for (study::SweepLight light : {study::SweepLight::sky, study::SweepLight::delta}) {
    const render::FrameTables tables = study::sweep_tables(study::sweep_lighting(light), 4, 8.0, 15.0f);
    for (settings::SplatMethod splat : {settings::SplatMethod::compute, settings::SplatMethod::raster}) {
      SCOPED_TRACE(std::string(settings::name_of(splat)) + (light == study::SweepLight::sky ? ", sky" : ", delta"));
      auto shaded = (*shader)->shade(tables, splat, frames);
      ASSERT_TRUE(shaded) << shaded.message();
      ASSERT_EQ(shaded->size(), frames.size());
      for (std::size_t t = 0; t < frames.size(); ++t) {
        const study::MethodShade twin = study::shade_method(tables, tables.settings.hyb_tau, glm::vec3(0.0f), up, frames[t]);
        const double u = twin.unshadowed / 255.0;
        EXPECT_NEAR((*shaded)[t].unshadowed, twin.unshadowed, 0.05 * u) << t;
        EXPECT_NEAR((*shaded)[t].shadowed, twin.value, 0.05 * u) << t;
      }
      EXPECT_LT((*shaded)[0].shadowed, (*shaded)[0].unshadowed - 10.0 * (*shaded)[0].unshadowed / 255.0);  // a real shadow at 3r
      EXPECT_EQ((*shaded)[3].shadowed, (*shaded)[3].unshadowed);  // beyond η r: not even the fade
    }
  }
}

}  // namespace
}  // namespace proxygi::gpu
