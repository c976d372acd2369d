// render.antialiasing (issue 16, silhouettes): a supersampled frame shades f× the display per axis
// and supersample_resolve.comp box-filters it. Checks, on the GPU with the validation layer on:
// - the frame at 64² with ssaa2 (k = 2) equals the CPU twin render::resolve_supersampled applied
//   to the same scene rendered without anti-aliasing at 128² (k = 2): the shading grid is that
//   frame, so the resolve alone is compared (HDR exactly, the 8-bit frame within one code);
// - the resolve changes the silhouette pixels (a ground patch's edge against the sky): they take
//   values between their samples', where a point-sampled frame keeps one of them;
// - ssaa4 and a setting change in place (off → ssaa2 → off) rebuild the targets and agree with
//   frames created with those settings.
#include <algorithm>
#include <cstdlib>

#include "frame_fixture.h"
#include "gpu_test_context.h"
#include "render/supersample_resolve.h"

namespace proxygi::gpu {
namespace {

using testing::GpuTest;
using SupersampleResolveTest = GpuTest;

constexpr float kSkyRadiance = 1.0f;

// A 3 m ground patch under a white sky, seen from above so its edges cross the image.
struct Frame {
  image::ImageF hdr;
  std::vector<std::uint8_t> ldr;
};
Frame render(Context& context, std::uint32_t size, settings::Antialiasing antialiasing) {
  FrameConfig config;
  config.width = config.height = size;
  config.render.receiver_scale = 2;
  config.render.antialiasing = antialiasing;
  const std::vector<render::Sphere> spheres = {{{0.3f, 0.35f, 0.2f}, 0.3f, glm::vec3(0.8f)}};
  auto rendered = testing::render_fixture_frame(context, config, testing::constant_sky_sh(4, kSkyRadiance), 4,
                                                testing::ground_plane(3.0f, 6), spheres);
  Frame out;
  if (!rendered.frame) return out;
  auto hdr = rendered.frame->read_hdr();
  auto ldr = rendered.frame->read_ldr();
  EXPECT_TRUE(hdr.ok() && ldr.ok());
  if (hdr.ok()) out.hdr = std::move(*hdr);
  if (ldr.ok()) out.ldr = std::move(*ldr);
  return out;
}

int max_code_difference(const std::vector<std::uint8_t>& a, const std::vector<std::uint8_t>& b, std::size_t& differing) {
  int worst = 0;
  differing = 0;
  for (std::size_t i = 0; i < std::min(a.size(), b.size()); ++i) {
    const int d = std::abs(int(a[i]) - int(b[i]));
    worst = std::max(worst, d);
    differing += d != 0;
  }
  return worst;
}

TEST_F(SupersampleResolveTest, Ssaa2EqualsTheCpuResolveOfTheFrameAtTwiceTheSize) {
  const Frame samples = render(context(), 128, settings::Antialiasing::off);
  const Frame resolved = render(context(), 64, settings::Antialiasing::ssaa2);
  ASSERT_EQ(samples.hdr.pixels.size(), 128u * 128u);
  ASSERT_EQ(resolved.hdr.pixels.size(), 64u * 64u);
  ASSERT_EQ(resolved.ldr.size(), 64u * 64u * 4u);
  const render::ResolvedFrame twin = render::resolve_supersampled(samples.hdr, samples.ldr, 2);
  float worst_hdr = 0.0f;
  for (std::size_t i = 0; i < twin.hdr.pixels.size(); ++i)
    for (int c = 0; c < 4; ++c) worst_hdr = std::max(worst_hdr, std::abs(twin.hdr.pixels[i][c] - resolved.hdr.pixels[i][c]));
  EXPECT_EQ(worst_hdr, 0.0f);  // the same sums in the same order, divided by a power of two
  std::size_t differing = 0;
  EXPECT_LE(max_code_difference(twin.ldr, resolved.ldr, differing), 1);  // pow on the GPU and the CPU
  EXPECT_LE(differing, twin.ldr.size() / 100);

  // Silhouette pixels: the ground's edge against the sky mixes the two.
  int mixed = 0;
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x) {
      float low = 1e30f, high = -1e30f;
      for (int j = 0; j < 2; ++j)
        for (int i = 0; i < 2; ++i) {
          const float v = samples.hdr.at(2 * x + i, 2 * y + j).g;
          low = std::min(low, v), high = std::max(high, v);
        }
      const float v = resolved.hdr.at(x, y).g;
      if (high - low > 0.1f && v > low + 0.01f && v < high - 0.01f) ++mixed;
    }
  EXPECT_GT(mixed, 20) << "the ground patch's edges cross the image";
}

TEST_F(SupersampleResolveTest, Ssaa4AndChangesInPlaceMatchCreatedFrames) {
  const Frame samples = render(context(), 128, settings::Antialiasing::off);
  const Frame resolved = render(context(), 32, settings::Antialiasing::ssaa4);
  ASSERT_EQ(resolved.hdr.pixels.size(), 32u * 32u);
  const render::ResolvedFrame twin = render::resolve_supersampled(samples.hdr, samples.ldr, 4);
  for (std::size_t i = 0; i < twin.hdr.pixels.size(); ++i) ASSERT_EQ(twin.hdr.pixels[i], resolved.hdr.pixels[i]) << i;

  // off → ssaa2 → off in place, against frames created with each setting.
  FrameConfig config;
  config.width = config.height = 64;
  config.render.receiver_scale = 2;
  config.frames_in_flight = 1;
  const render::FrameTables tables = render::make_frame_tables(testing::constant_sky_sh(4, kSkyRadiance), config.render, {});
  const testing::GroundMesh ground = testing::ground_plane(3.0f, 6);
  auto mesh = upload_static_mesh(context(), ground.positions, ground.normals, ground.indices, glm::vec4(0.8f, 0.8f, 0.8f, 1));
  ASSERT_TRUE(mesh.ok());
  const DrawItem draws[] = {mesh->draw()};
  auto frame = SoftGiFrame::create(context(), config, tables, image::ImageF(8, 4, glm::vec4(1.0f)));
  ASSERT_TRUE(frame.ok()) << frame.message();
  const std::vector<render::Sphere> spheres = {{{0.3f, 0.35f, 0.2f}, 0.3f, glm::vec3(0.8f)}};
  auto draw = [&]() {
    EXPECT_TRUE((*frame)->write_slot(0, testing::look_at({0.0f, 4.0f, 3.0f}, {0.0f, 0.0f, 0.0f}, 60.0f, 1.0f), spheres).ok());
    EXPECT_TRUE(context().submit_and_wait([&](VkCommandBuffer c) { (*frame)->record(c, 0, draws, FrameOutput::readback()); }).ok());
    return *(*frame)->read_ldr();
  };
  const std::vector<std::uint8_t> off = draw();
  config.render.antialiasing = settings::Antialiasing::ssaa2;
  ASSERT_TRUE((*frame)->apply(config, tables).ok());
  EXPECT_EQ(draw(), render(context(), 64, settings::Antialiasing::ssaa2).ldr);
  config.render.antialiasing = settings::Antialiasing::off;
  ASSERT_TRUE((*frame)->apply(config, tables).ok());
  EXPECT_EQ(draw(), off);
  EXPECT_EQ(off, render(context(), 64, settings::Antialiasing::off).ldr);
}

}  // namespace
}  // namespace proxygi::gpu
