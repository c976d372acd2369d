// Foundation GPU tests: a compute pattern read back exactly, and a rasterized triangle in an
// RGBA16F image with inside/outside pixels checked. Validation on; zero messages allowed.
#include <cstring>
#include <vector>

#include <glm/gtc/packing.hpp>

#include "gpu/pipeline.h"
#include "gpu/resources.h"
#include "gpu/transfer.h"
#include "gpu_test_context.h"
#include "shaders/shared/layouts.h"

namespace proxygi::gpu {
namespace {

using testing::GpuTest;
using ComputePatternTest = GpuTest;
using RasterTriangleTest = GpuTest;
using TexelViewTest = GpuTest;

// Buffer::add_texel_view: one view over the whole buffer; a second one, a format without a
// known texel size, or a buffer without uniform texel usage is an error that names the cause, and
// the first view stays.
TEST_F(TexelViewTest, AddsOneViewAndRefusesASecond) {
  auto buffer = Buffer::create(context(), 64 * sizeof(float[4]), VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT,
                               MemoryKind::device_local);
  ASSERT_TRUE(buffer.ok()) << buffer.message();
  EXPECT_EQ(buffer->texel_view(), VkBufferView(VK_NULL_HANDLE));
  ASSERT_TRUE(buffer->add_texel_view(context(), VK_FORMAT_R32G32B32A32_SFLOAT).ok());
  const VkBufferView first = buffer->texel_view();
  EXPECT_NE(first, VkBufferView(VK_NULL_HANDLE));
  Status again = buffer->add_texel_view(context(), VK_FORMAT_R32G32B32A32_SFLOAT);
  ASSERT_FALSE(again.ok());
  EXPECT_NE(again.message().find("twice"), std::string::npos) << again.message();
  EXPECT_EQ(buffer->texel_view(), first);
  Buffer moved = std::move(*buffer);
  EXPECT_EQ(moved.texel_view(), first);

  auto other = Buffer::create(context(), 256, VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT, MemoryKind::device_local);
  ASSERT_TRUE(other.ok()) << other.message();
  Status unknown = other->add_texel_view(context(), VK_FORMAT_R8_UNORM);
  ASSERT_FALSE(unknown.ok());
  EXPECT_NE(unknown.message().find("VkFormat"), std::string::npos) << unknown.message();

  // A buffer created without uniform texel usage gets no view (an error, not a validation message).
  auto storage = Buffer::create(context(), 256, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, MemoryKind::device_local);
  ASSERT_TRUE(storage.ok()) << storage.message();
  EXPECT_EQ(storage->usage() & VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT, 0u);
  Status without = storage->add_texel_view(context(), VK_FORMAT_R32G32B32A32_SFLOAT);
  ASSERT_FALSE(without.ok());
  EXPECT_NE(without.message().find("UNIFORM_TEXEL_BUFFER"), std::string::npos) << without.message();
  EXPECT_EQ(storage->texel_view(), VkBufferView(VK_NULL_HANDLE));
}

TEST_F(ComputePatternTest, WritesKnownIntegersExactly) {
  constexpr std::uint32_t kCount = 1000;  // not a multiple of the workgroup size on purpose
  auto buffer = Buffer::create(context(), (kCount + 24) * sizeof(std::uint32_t), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                               MemoryKind::device_local);
  ASSERT_TRUE(buffer.ok()) << buffer.message();
  const std::vector<std::uint32_t> sentinel(kCount + 24, 0xDEADBEEFu);
  ASSERT_TRUE(upload(context(), *buffer, as_bytes(std::span<const std::uint32_t>(sentinel))).ok());

  const Binding bindings[] = {{0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_COMPUTE_BIT}};
  auto pipeline = Pipeline::compute(context(), "test_pattern.comp", bindings, sizeof(gpu_layout::TestPatternPush));
  ASSERT_TRUE(pipeline.ok()) << pipeline.message();

  const gpu_layout::TestPatternPush push{kCount, 7u, 12345u, 0u};
  Status ran = context().submit_and_wait([&](VkCommandBuffer commands) {
    pipeline->bind(commands);
    DescriptorPush().storage_buffer(0, *buffer).push(context(), commands, *pipeline);
    pipeline->push_constants(commands, &push, sizeof(push));
    vkCmdDispatch(commands, group_count(kCount, gpu_layout::kTestPatternLocalSize), 1, 1);
  });
  ASSERT_TRUE(ran.ok()) << ran.message();

  auto bytes = readback(context(), *buffer);
  ASSERT_TRUE(bytes.ok()) << bytes.message();
  std::vector<std::uint32_t> values(bytes->size() / sizeof(std::uint32_t));
  std::memcpy(values.data(), bytes->data(), bytes->size());
  for (std::uint32_t i = 0; i < kCount; ++i) ASSERT_EQ(values[i], i * 7u + 12345u) << "element " << i;
  for (std::uint32_t i = kCount; i < values.size(); ++i) ASSERT_EQ(values[i], 0xDEADBEEFu) << "guard " << i;
}

TEST_F(RasterTriangleTest, FillsInsideAndLeavesOutsideClear) {
  constexpr std::uint32_t kSize = 64;
  auto image = Image::create(context(), kSize, kSize, VK_FORMAT_R16G16B16A16_SFLOAT,
                             VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT);
  ASSERT_TRUE(image.ok()) << image.message();
  GraphicsPipelineDescription description;
  description.vertex_shader = "test_triangle.vert";
  description.fragment_shader = "test_triangle.frag";
  description.color_formats = {VK_FORMAT_R16G16B16A16_SFLOAT};
  auto pipeline = Pipeline::graphics(context(), description, {}, 0);
  ASSERT_TRUE(pipeline.ok()) << pipeline.message();

  Status drawn = context().submit_and_wait([&](VkCommandBuffer commands) {
    transition(commands, *image, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL);
    VkRenderingAttachmentInfo color{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
    color.imageView = image->view();
    color.imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    color.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
    color.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    color.clearValue.color = {{0.0f, 0.0f, 0.0f, 0.0f}};
    VkRenderingInfo rendering{VK_STRUCTURE_TYPE_RENDERING_INFO};
    rendering.renderArea = {{0, 0}, {kSize, kSize}};
    rendering.layerCount = 1;
    rendering.colorAttachmentCount = 1;
    rendering.pColorAttachments = &color;
    vkCmdBeginRendering(commands, &rendering);
    const VkViewport viewport{0, 0, float(kSize), float(kSize), 0, 1};
    const VkRect2D scissor{{0, 0}, {kSize, kSize}};
    vkCmdSetViewport(commands, 0, 1, &viewport);
    vkCmdSetScissor(commands, 0, 1, &scissor);
    pipeline->bind(commands);
    vkCmdDraw(commands, 3, 1, 0, 0);
    vkCmdEndRendering(commands);
  });
  ASSERT_TRUE(drawn.ok()) << drawn.message();

  auto bytes = readback(context(), *image, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL);
  ASSERT_TRUE(bytes.ok()) << bytes.message();
  auto pixel = [&](std::uint32_t x, std::uint32_t y) {
    std::uint16_t half[4];
    std::memcpy(half, bytes->data() + (std::size_t(y) * kSize + x) * 8, 8);
    return glm::vec4(glm::unpackHalf1x16(half[0]), glm::unpackHalf1x16(half[1]), glm::unpackHalf1x16(half[2]),
                     glm::unpackHalf1x16(half[3]));
  };
  // NDC corners (-0.5,-0.5), (0.5,-0.5), (0,0.5); Vulkan y points down, so the apex is at the
  // bottom: pixel rows 16..48, the base at row 16.
  const glm::vec4 inside_color(0.25f, 0.5f, 0.75f, 1.0f);
  for (auto [x, y] : {std::pair{32u, 40u}, {32u, 20u}, {22u, 18u}, {42u, 18u}}) EXPECT_EQ(pixel(x, y), inside_color) << x << "," << y;
  for (auto [x, y] : {std::pair{2u, 2u}, {32u, 10u}, {32u, 52u}, {18u, 44u}, {46u, 44u}, {63u, 63u}})
    EXPECT_EQ(pixel(x, y), glm::vec4(0.0f)) << x << "," << y;
}

}  // namespace
}  // namespace proxygi::gpu
