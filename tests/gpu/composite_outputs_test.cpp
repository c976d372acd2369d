// upsample+composite writes only the float targets its caller reads (FrameOutput::float_targets):
// the lean pipelines (":no_aov", ":ldr_only") give the same bytes as the full one, and reading a
// target the last frame did not write fails instead of returning an older frame's.
#include "frame_fixture.h"
#include "gpu_test_context.h"

namespace proxygi::gpu {
namespace {

using CompositeOutputsTest = testing::GpuTest;

TEST_F(CompositeOutputsTest, LeanOutputsMatchTheFullCompositeAndStaleTargetsAreRefused) {
  constexpr int kOrder = 4;
  FrameConfig config;
  config.width = config.height = 64;
  config.render.receiver_scale = 2;
  config.render.sh_order = kOrder;
  config.frames_in_flight = 1;
  const auto tables = render::make_frame_tables(testing::constant_sky_sh(kOrder, 1.0), config.render, {});
  const auto ground = testing::ground_plane(20.0f, 4);
  auto mesh =
      upload_static_mesh(context(), ground.positions, ground.normals, ground.indices, glm::vec4(0.8f, 0.8f, 0.8f, 1));
  ASSERT_TRUE(mesh.ok()) << mesh.message();
  const DrawItem draws[] = {mesh->draw()};
  auto created = SoftGiFrame::create(context(), config, tables, image::ImageF(8, 4, glm::vec4(1.0f)));
  ASSERT_TRUE(created.ok()) << created.message();
  SoftGiFrame& frame = **created;
  const std::vector<render::Sphere> spheres = {{{0.0f, 0.8f, 0.0f}, 0.5f, {0.9f, 0.1f, 0.1f}}};
  // Two cameras, so that a target left from the other camera's frame cannot pass for this one's.
  const FrameView camera_a = testing::look_at({0.0f, 1.0f, 4.0f}, {0.0f, 0.0f, 0.0f}, 60.0f, 1.0f);
  const FrameView camera_b = testing::look_at({3.0f, 2.5f, 1.0f}, {0.0f, 0.0f, 0.0f}, 60.0f, 1.0f);
  auto render = [&](const FrameView& view, const FrameOutput& output) {
    ASSERT_TRUE(frame.write_slot(0, view, spheres).ok());
    ASSERT_TRUE(context().submit_and_wait([&](VkCommandBuffer c) { frame.record(c, 0, draws, output); }).ok());
  };
  FrameOutput no_aov = FrameOutput::readback(true);
  no_aov.float_targets = false;
  FrameOutput ldr_only = FrameOutput::readback(false);
  ldr_only.float_targets = false;

  render(camera_a, FrameOutput::readback());
  const auto ldr_a = frame.read_ldr();
  const auto hdr_a = frame.read_hdr();
  const auto irradiance_a = frame.read_irradiance();
  ASSERT_TRUE(ldr_a.ok() && hdr_a.ok() && irradiance_a.ok());
  render(camera_b, FrameOutput::readback());
  const auto ldr_b = frame.read_ldr();
  ASSERT_TRUE(ldr_b.ok());
  ASSERT_NE(*ldr_b, *ldr_a) << "the two cameras must see different frames";

  render(camera_a, no_aov);  // HDR read back, no irradiance AOV
  auto ldr = frame.read_ldr();
  auto hdr = frame.read_hdr();
  ASSERT_TRUE(ldr.ok() && hdr.ok());
  EXPECT_EQ(*ldr, *ldr_a);
  EXPECT_EQ(hdr->pixels, hdr_a->pixels);
  EXPECT_FALSE(frame.read_irradiance().ok());

  render(camera_b, FrameOutput::readback());
  render(camera_a, ldr_only);  // the 8-bit frame alone
  ldr = frame.read_ldr();
  ASSERT_TRUE(ldr.ok());
  EXPECT_EQ(*ldr, *ldr_a);
  EXPECT_FALSE(frame.read_hdr().ok());
  EXPECT_FALSE(frame.read_irradiance().ok());

  render(camera_a, FrameOutput::readback());  // every target again
  auto irradiance = frame.read_irradiance();
  ASSERT_TRUE(irradiance.ok());
  EXPECT_EQ(irradiance->pixels, irradiance_a->pixels);
}

}  // namespace
}  // namespace proxygi::gpu
