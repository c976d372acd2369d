// skin.comp's two palette variants (shaders/shared/skin_palette.h): a palette of exactly
// kSkinUniformPaletteJoints joints skinned through the uniform and the storage variant gives the
// same bytes, and one joint more takes the storage variant; both against the CPU twin
// (anim::SkinningJob) within 1e-5 × the bounding-box diagonal. Every joint, the last included,
// moves some vertex, so a palette read short or shifted fails the comparison. Also: two
// instances of one uploaded primitive share its bind pose and, skinned in one submit with one
// barrier after both dispatches, each get their own palette's result.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "anim/skinning.h"
#include "gpu/skin_pass.h"
#include "gpu/transfer.h"
#include "gpu_test_context.h"
#include "shaders/shared/skin_palette.h"

namespace proxygi::gpu {
namespace {

using SkinPaletteTest = testing::GpuTest;
using gpu_layout::kSkinUniformPaletteJoints;
using testing::read_vec4s;

// Joint j: a rotation about a joint-dependent axis, a uniform scale and a translation, all
// distinct per joint.
std::vector<glm::mat4> synthetic_palette(std::uint32_t joints) {
  std::vector<glm::mat4> palette(joints);
  for (std::uint32_t j = 0; j < joints; ++j) {
    const float x = float(j);
    const glm::vec3 axis = glm::normalize(glm::vec3(std::sin(0.7f * x) + 1.5f, std::cos(1.3f * x), std::sin(0.3f * x)));
    glm::mat4 m = glm::translate(glm::mat4(1.0f), glm::vec3(std::sin(x), 0.01f * x, std::cos(2.0f * x)));
    m = glm::rotate(m, 0.37f * x, axis);
    palette[j] = glm::scale(m, glm::vec3(0.5f + 0.001f * x));
  }
  return palette;
}

// Two vertices per joint, four influences each: vertex v leans on joint v / 2 and three others.
anim::Primitive synthetic_primitive(std::uint32_t joints) {
  anim::Primitive primitive;
  primitive.influences_per_vertex = 4;
  for (std::uint32_t v = 0; v < 2 * joints; ++v) {
    const float x = float(v);
    primitive.positions.emplace_back(std::sin(x), std::cos(0.5f * x), 0.1f * std::sin(3.0f * x));
    primitive.normals.push_back(glm::normalize(glm::vec3(std::cos(x), 1.0f, std::sin(0.2f * x))));
    const std::uint32_t first = v / 2;
    for (std::uint32_t k = 0; k < 4; ++k) primitive.joints.push_back(std::uint16_t((first + 97u * k) % joints));
    for (const float w : {0.55f, 0.25f, 0.15f, 0.05f}) primitive.weights.push_back(w);
  }
  return primitive;
}

struct Skinned {
  std::vector<glm::vec4> positions, normals;
};

Skinned skin_on_gpu(Context& context, const SkinPass& pass, const SkinnedPrimitive& uploaded,
                    const std::vector<glm::mat4>& palette, std::optional<PaletteBinding> binding) {
  auto buffer = create_buffer_with_data(context, as_bytes(std::span<const glm::mat4>(palette)), SkinPass::kPaletteUsage);
  EXPECT_TRUE(buffer.ok());
  if (!buffer.ok()) return {};
  EXPECT_TRUE(context
                  .submit_and_wait([&](VkCommandBuffer commands) {
                    pass.record(context, commands, uploaded, SkinPalette{&*buffer, nullptr, std::uint32_t(palette.size())},
                                nullptr, binding);
                    SkinPass::record_outputs_barrier(commands);
                  })
                  .ok());
  return {read_vec4s(context, uploaded.world_positions, uploaded.vertex_count),
          read_vec4s(context, uploaded.world_normals, uploaded.vertex_count)};
}

void expect_matches_cpu(const anim::Primitive& primitive, const std::vector<glm::mat4>& palette, const Skinned& gpu) {
  const std::size_t vertices = primitive.positions.size();
  std::vector<glm::vec3> positions(vertices), normals(vertices);
  anim::SkinningJob job;
  job.influences_per_vertex = primitive.influences_per_vertex;
  job.skin_matrices = palette;
  job.joints = primitive.joints;
  job.weights = primitive.weights;
  job.positions = primitive.positions;
  job.normals = primitive.normals;
  job.out_positions = positions;
  job.out_normals = normals;
  ASSERT_TRUE(job.run().ok());
  glm::vec3 low(1e30f), high(-1e30f);
  for (const auto& p : positions) {
    low = glm::min(low, p);
    high = glm::max(high, p);
  }
  const float diagonal = glm::length(high - low);
  ASSERT_GT(diagonal, 0.5f);
  ASSERT_EQ(gpu.positions.size(), vertices);
  float worst_position = 0.0f, worst_normal = 0.0f;
  for (std::size_t i = 0; i < vertices; ++i) {
    worst_position = std::max(worst_position, glm::length(glm::vec3(gpu.positions[i]) - positions[i]));
    worst_normal = std::max(worst_normal, glm::length(glm::vec3(gpu.normals[i]) - normals[i]));
  }
  EXPECT_LE(worst_position, 1e-5f * diagonal) << palette.size() << " joints";
  EXPECT_LE(worst_normal, 1e-5f) << palette.size() << " joints";
}

TEST_F(SkinPaletteTest, UniformAndStorageVariantsAgreeAtTheLimit) {
  auto pass = SkinPass::create(context());
  ASSERT_TRUE(pass.ok()) << pass.message();
  const bool device_holds_limit =
      context().limits().maxUniformBufferRange >= gpu_layout::kSkinUniformPaletteBytes;
  EXPECT_EQ(pass->binding_for(kSkinUniformPaletteJoints),
            device_holds_limit ? PaletteBinding::uniform : PaletteBinding::storage);
  EXPECT_EQ(pass->binding_for(kSkinUniformPaletteJoints + 1), PaletteBinding::storage);
  if (!device_holds_limit) GTEST_SKIP() << "device's maxUniformBufferRange is below one uniform palette";

  const std::vector<glm::mat4> palette = synthetic_palette(kSkinUniformPaletteJoints);
  const anim::Primitive primitive = synthetic_primitive(kSkinUniformPaletteJoints);
  auto uploaded = SkinPass::upload(context(), primitive);
  ASSERT_TRUE(uploaded.ok()) << uploaded.message();
  const Skinned uniform = skin_on_gpu(context(), *pass, *uploaded, palette, PaletteBinding::uniform);
  const Skinned storage = skin_on_gpu(context(), *pass, *uploaded, palette, PaletteBinding::storage);
  ASSERT_EQ(uniform.positions.size(), storage.positions.size());
  EXPECT_EQ(std::memcmp(uniform.positions.data(), storage.positions.data(), uniform.positions.size() * sizeof(glm::vec4)), 0);
  EXPECT_EQ(std::memcmp(uniform.normals.data(), storage.normals.data(), uniform.normals.size() * sizeof(glm::vec4)), 0);
  expect_matches_cpu(primitive, palette, uniform);
}

TEST_F(SkinPaletteTest, OneJointOverTheLimitTakesTheStorageVariant) {
  auto pass = SkinPass::create(context());
  ASSERT_TRUE(pass.ok()) << pass.message();
  const std::vector<glm::mat4> palette = synthetic_palette(kSkinUniformPaletteJoints + 1);
  const anim::Primitive primitive = synthetic_primitive(kSkinUniformPaletteJoints + 1);
  auto uploaded = SkinPass::upload(context(), primitive);
  ASSERT_TRUE(uploaded.ok()) << uploaded.message();
  ASSERT_EQ(pass->binding_for(std::uint32_t(palette.size())), PaletteBinding::storage);
  expect_matches_cpu(primitive, palette, skin_on_gpu(context(), *pass, *uploaded, palette, std::nullopt));
}

TEST_F(SkinPaletteTest, InstancesShareTheBindPoseAndSkinIndependently) {
  auto pass = SkinPass::create(context());
  ASSERT_TRUE(pass.ok()) << pass.message();
  constexpr std::uint32_t kJoints = 40;
  const anim::Primitive primitive = synthetic_primitive(kJoints);
  auto first = SkinPass::upload(context(), primitive);
  ASSERT_TRUE(first.ok()) << first.message();
  auto second = SkinPass::instantiate(context(), first->bind_pose);
  ASSERT_TRUE(second.ok()) << second.message();
  EXPECT_EQ(first->bind_pose.get(), second->bind_pose.get());
  EXPECT_NE(first->world_positions.handle(), second->world_positions.handle());
  std::vector<glm::mat4> palette_a = synthetic_palette(kJoints), palette_b = palette_a;
  for (glm::mat4& m : palette_b) m = glm::translate(glm::mat4(1.0f), glm::vec3(2.0f, -1.0f, 0.5f)) * m;
  auto buffer_a = create_buffer_with_data(context(), as_bytes(std::span<const glm::mat4>(palette_a)), SkinPass::kPaletteUsage);
  auto buffer_b = create_buffer_with_data(context(), as_bytes(std::span<const glm::mat4>(palette_b)), SkinPass::kPaletteUsage);
  ASSERT_TRUE(buffer_a.ok() && buffer_b.ok());
  ASSERT_TRUE(context()
                  .submit_and_wait([&](VkCommandBuffer commands) {
                    pass->record(context(), commands, *first, SkinPalette{&*buffer_a, nullptr, kJoints});
                    pass->record(context(), commands, *second, SkinPalette{&*buffer_b, nullptr, kJoints});
                    SkinPass::record_outputs_barrier(commands);
                  })
                  .ok());
  for (const auto& [uploaded, palette] : {std::pair{&*first, &palette_a}, std::pair{&*second, &palette_b}})
    expect_matches_cpu(primitive, *palette,
                       {read_vec4s(context(), uploaded->world_positions, uploaded->vertex_count),
                        read_vec4s(context(), uploaded->world_normals, uploaded->vertex_count)});
}

}  // namespace
}  // namespace proxygi::gpu
