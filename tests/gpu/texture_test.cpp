// Base color textures in the G-buffer: a textured quad filling the frame (a 4×4 texture built
// here) against the CPU twin (render/texture_sampling.h) at sample pixels, for nearest and
// linear filters, repeat/clamp/mirrored wrap and a KHR_texture_transform; the CPU mip chain.
#include <algorithm>
#include <cmath>

#include "frame_fixture.h"
#include "gpu/material_textures.h"
#include "gpu_test_context.h"
#include "image/image.h"
#include "render/texture_sampling.h"

namespace proxygi::gpu {
namespace {

using TextureTest = testing::GpuTest;
constexpr int kSize = 64;  // frame pixels per side

// 4×4 sRGB texels, every one different, so a flipped or shifted lookup shows.
anim::Image test_image() {
  anim::Image image;
  image.name = "checker";
  image.width = image.height = 4;
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i)
      image.rgba.insert(image.rgba.end(), {std::uint8_t(20 + 60 * i), std::uint8_t(20 + 60 * j),
                                           std::uint8_t((i + j) % 2 ? 230 : 30), 255});
  return image;
}

std::vector<glm::vec3> linear_texels(const anim::Image& image) {
  std::vector<glm::vec3> texels;
  for (std::size_t i = 0; i < image.rgba.size(); i += 4)
    texels.emplace_back(image::srgb_to_linear(image.rgba[i] / 255.0f), image::srgb_to_linear(image.rgba[i + 1] / 255.0f),
                        image::srgb_to_linear(image.rgba[i + 2] / 255.0f));
  return texels;
}

// A quad covering clip space (view-projection = identity) with uvs from -0.5 to 1.5, so the
// wrap modes show; returns the G-buffer albedo.
image::ImageF render_quad(Context& context, const anim::Image& image, const anim::TextureSampler& description,
                          const glm::mat3& uv_transform, const glm::vec4& factor) {
  settings::RenderSettings table_settings;
  table_settings.sh_order = 3;
  const auto tables = render::make_frame_tables(testing::constant_sky_sh(3, 1.0), table_settings);
  FrameConfig config;
  config.render.sh_order = 3;
  config.width = config.height = kSize;
  config.render.receiver_scale = 1;
  config.frames_in_flight = 1;
  auto frame = SoftGiFrame::create(context, config, tables, image::ImageF(8, 4, glm::vec4(1.0f)));
  EXPECT_TRUE(frame.ok()) << (frame.ok() ? "" : frame.message());
  if (!frame.ok()) return {};
  auto texture = upload_srgb_texture(context, image);
  auto sampler = Sampler::create(context, description);
  EXPECT_TRUE(texture.ok() && sampler.ok());
  if (!texture.ok() || !sampler.ok()) return {};
  const glm::vec3 corners[] = {{-1, -1, 0.5f}, {1, -1, 0.5f}, {1, 1, 0.5f}, {-1, 1, 0.5f}};
  const glm::vec3 normals[] = {{0, 0, -1}, {0, 0, -1}, {0, 0, -1}, {0, 0, -1}};
  const glm::vec2 uvs[] = {{-0.5f, -0.5f}, {1.5f, -0.5f}, {1.5f, 1.5f}, {-0.5f, 1.5f}};
  const std::uint32_t indices[] = {0, 1, 2, 0, 2, 3};
  auto mesh = upload_static_mesh(context, corners, normals, indices, factor, uvs,
                                 {texture->view(), sampler->handle(), uv_transform});
  EXPECT_TRUE(mesh.ok());
  if (!mesh.ok()) return {};
  FrameView view;  // identity view and projection: world = clip space
  view.eye = {0.0f, 0.0f, -1.0f};
  view.forward = {0.0f, 0.0f, 1.0f};
  EXPECT_TRUE((*frame)->write_slot(0, view, {}).ok());
  const DrawItem draws[] = {mesh->draw()};
  EXPECT_TRUE(context.submit_and_wait([&](VkCommandBuffer commands) { (*frame)->record(commands, 0, draws, FrameOutput::readback()); }).ok());
  auto albedo = (*frame)->read_gbuffer_albedo();
  EXPECT_TRUE(albedo.ok());
  return albedo.ok() ? std::move(*albedo) : image::ImageF{};
}

// Half the linear-space step between the 8-bit sRGB codes around `linear`. The device's sRGB
// decode may approximate the curve (lavapipe's is off by up to a third of a code on the texels
// here): it must still name the right 8-bit code, so a wrong or shifted texel (codes differ by
// 60 here) fails.
float half_code_step(float linear) {
  const float code = std::round(image::linear_to_srgb(std::clamp(linear, 0.0f, 1.0f)) * 255.0f);
  return 0.5f * (image::srgb_to_linear(std::min(code + 0.5f, 255.0f) / 255.0f) -
                 image::srgb_to_linear(std::max(code - 0.5f, 0.0f) / 255.0f));
}

// Checks every 3rd pixel against factor × CPU twin; returns how many were checked.
// filter_tolerance: what the device's filtering may add (absolute, linear).
int compare_with_twin(const image::ImageF& albedo, const anim::Image& image, const anim::TextureSampler& description,
                      const glm::mat3& uv_transform, const glm::vec4& factor, float filter_tolerance) {
  const auto texels = linear_texels(image);
  int checked = 0;
  for (int y = 1; y < kSize; y += 3)
    for (int x = 0; x < kSize; x += 3) {
      // Pixel centers interpolate the vertex uvs linearly (w = 1 everywhere).
      const glm::vec2 vertex_uv(-0.5f + 2.0f * (float(x) + 0.5f) / kSize, -0.5f + 2.0f * (float(y) + 0.5f) / kSize);
      const glm::vec2 uv = render::transform_uv(uv_transform, vertex_uv);
      const glm::vec3 texel = render::sample_texels(texels, image.width, image.height, uv, description.wrap_s,
                                                    description.wrap_t, description.magnification);
      const glm::vec3 expected = glm::vec3(factor) * texel;
      const glm::vec3 gpu(albedo.at(x, y));
      for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(gpu[c], expected[c], factor[c] * (half_code_step(texel[c]) + filter_tolerance))
            << "pixel " << x << "," << y << " channel " << c << " uv " << uv.x << "," << uv.y;
      ++checked;
    }
  return checked;
}

TEST_F(TextureTest, NearestTexelsMatchCpuTwinWithTransformAndRepeat) {
  const anim::Image image = test_image();
  anim::TextureSampler description;
  description.magnification = anim::TextureFilter::nearest;
  // KHR_texture_transform: offset (0.125, 0), rotation 0, scale (1, -1): v flipped, u shifted
  // by half a texel (pixel centers stay 1/16 texel away from texel edges).
  const glm::mat3 transform(1, 0, 0, 0, -1, 0, 0.125f, 0, 1);
  const glm::vec4 factor(0.9f, 0.8f, 0.7f, 1.0f);
  const auto albedo = render_quad(context(), image, description, transform, factor);
  ASSERT_EQ(albedo.width, kSize);
  EXPECT_GT(compare_with_twin(albedo, image, description, transform, factor, 0.0f), 400);  // exact texels
}

TEST_F(TextureTest, BilinearTexelsMatchCpuTwinWithClampAndMirror) {
  const anim::Image image = test_image();
  anim::TextureSampler description;  // linear, mipmapped (magnified here: level 0)
  description.wrap_s = anim::TextureWrap::clamp_to_edge;
  description.wrap_t = anim::TextureWrap::mirrored_repeat;
  const glm::vec4 factor(1.0f);
  const auto albedo = render_quad(context(), image, description, glm::mat3(1.0f), factor);
  ASSERT_EQ(albedo.width, kSize);
  // The device interpolates with subTexelPrecisionBits of weight precision (Vulkan §16): the
  // lookup may differ from exact bilinear by 2^-bits of the largest texel difference per axis.
  VkPhysicalDeviceProperties properties{};
  vkGetPhysicalDeviceProperties(context().physical_device(), &properties);
  float largest_difference = 0.0f;
  for (const glm::vec3& a : linear_texels(image))
    for (const glm::vec3& b : linear_texels(image))
      for (int c = 0; c < 3; ++c) largest_difference = std::max(largest_difference, std::abs(a[c] - b[c]));
  const float tolerance = 2.0f * largest_difference * std::ldexp(1.0f, -int(properties.limits.subTexelPrecisionBits));
  EXPECT_GT(compare_with_twin(albedo, image, description, glm::mat3(1.0f), factor, tolerance), 400);
}

TEST(TextureTwin, WrapModesFollowVulkanAddressing) {
  using anim::TextureWrap;
  const int repeat[] = {2, 0, 1, 2, 0, 1, 2};  // i = −1 .. 5 on 3 texels
  const int clamp[] = {0, 0, 1, 2, 2, 2, 2};
  const int mirror[] = {0, 0, 1, 2, 2, 1, 0};  // ... 0 | 0 1 2 | 2 1 0 | ...
  for (int i = -1; i <= 5; ++i) {
    EXPECT_EQ(render::wrap_texel(i, 3, TextureWrap::repeat), repeat[i + 1]) << i;
    EXPECT_EQ(render::wrap_texel(i, 3, TextureWrap::clamp_to_edge), clamp[i + 1]) << i;
    EXPECT_EQ(render::wrap_texel(i, 3, TextureWrap::mirrored_repeat), mirror[i + 1]) << i;
  }
}

TEST(TextureMips, ChainAveragesInLinearSpace) {
  anim::Image image;
  image.width = 2;
  image.height = 1;
  image.rgba = {0, 0, 0, 0, 255, 255, 255, 255};
  const auto levels = srgb_mip_chain(image);
  ASSERT_EQ(levels.size(), 2u);
  ASSERT_EQ(levels[1].size(), 4u);
  // Black and white average to linear 0.5, sRGB code 188 (not 128).
  EXPECT_EQ(int(levels[1][0]), int(std::lround(image::linear_to_srgb(0.5f) * 255.0f)));
  EXPECT_EQ(int(levels[1][0]), 188);
  EXPECT_EQ(int(levels[1][3]), 128);  // alpha is averaged as is
  const auto chain = srgb_mip_chain(test_image());
  ASSERT_EQ(chain.size(), 3u);  // 4×4, 2×2, 1×1
  EXPECT_EQ(chain[2].size(), 4u);
}

}  // namespace
}  // namespace proxygi::gpu
