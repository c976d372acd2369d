// GPU skinning against its CPU twin (anim::SkinningJob) on the mannequin mid-walk: every
// vertex within 1e-5 × the model's bounding-box diagonal, normals within 1e-5.
#include <algorithm>
#include <cstring>
#include <vector>

#include "anim/mannequin.h"
#include "anim/posed_character.h"
#include "anim/skinning.h"
#include "gpu/skin_pass.h"
#include "gpu/transfer.h"
#include "gpu_test_context.h"

namespace proxygi::gpu {
namespace {

using SkinPassTest = testing::GpuTest;

using testing::read_vec4s;

Result<Buffer> matrices_buffer(Context& context, const std::vector<glm::mat4>& matrices) {
  return create_buffer_with_data(context, as_bytes(std::span<const glm::mat4>(matrices)), SkinPass::kPaletteUsage);
}

void compare_pose(Context& context, const anim::Character& character, int clip, float time, bool normal_matrices) {
  anim::PoseBuffers pose;
  ASSERT_TRUE(anim::evaluate_pose(character, clip, time, anim::WrapMode::loop, pose).ok());
  auto pass = SkinPass::create(context);
  ASSERT_TRUE(pass.ok()) << pass.message();

  glm::vec3 low(1e30f), high(-1e30f);
  std::size_t primitives_checked = 0;
  for (const auto& node : character.nodes) {
    if (node.mesh < 0 || node.skin < 0) continue;
    const auto& palette = pose.skin_matrices[std::size_t(node.skin)];
    const auto& normal_palette = pose.normal_matrices[std::size_t(node.skin)];
    auto skin_buffer = matrices_buffer(context, palette);
    auto normal_buffer = matrices_buffer(context, normal_palette);
    ASSERT_TRUE(skin_buffer.ok() && normal_buffer.ok());
    for (const auto& primitive : character.meshes[std::size_t(node.mesh)].primitives) {
      std::vector<glm::vec3> cpu_positions(primitive.positions.size()), cpu_normals(primitive.normals.size());
      anim::SkinningJob job;
      job.influences_per_vertex = primitive.influences_per_vertex;
      job.skin_matrices = palette;
      if (normal_matrices) job.normal_matrices = normal_palette;
      job.joints = primitive.joints;
      job.weights = primitive.weights;
      job.positions = primitive.positions;
      job.normals = primitive.normals;
      job.out_positions = cpu_positions;
      job.out_normals = cpu_normals;
      ASSERT_TRUE(job.run().ok());
      for (const auto& p : cpu_positions) {
        low = glm::min(low, p);
        high = glm::max(high, p);
      }

      auto uploaded = SkinPass::upload(context, primitive);
      ASSERT_TRUE(uploaded.ok()) << uploaded.message();
      ASSERT_TRUE(context
                      .submit_and_wait([&](VkCommandBuffer commands) {
                        pass->record(context, commands, *uploaded,
                                     SkinPalette{&*skin_buffer, normal_matrices ? &*normal_buffer : nullptr,
                                                 std::uint32_t(palette.size())});
                        SkinPass::record_outputs_barrier(commands);
                      })
                      .ok());
      const auto gpu_positions = read_vec4s(context, uploaded->world_positions, cpu_positions.size());
      const auto gpu_normals = read_vec4s(context, uploaded->world_normals, cpu_normals.size());
      const float diagonal = glm::length(high - low);
      ASSERT_GT(diagonal, 0.5f);
      float worst_position = 0.0f, worst_normal = 0.0f;
      for (std::size_t i = 0; i < cpu_positions.size(); ++i)
        worst_position = std::max(worst_position, glm::length(glm::vec3(gpu_positions[i]) - cpu_positions[i]));
      for (std::size_t i = 0; i < cpu_normals.size(); ++i)
        worst_normal = std::max(worst_normal, glm::length(glm::vec3(gpu_normals[i]) - cpu_normals[i]));
      EXPECT_LE(worst_position, 1e-5f * diagonal) << "primitive with " << cpu_positions.size() << " vertices";
      EXPECT_LE(worst_normal, 1e-5f);
      ++primitives_checked;
    }
  }
  EXPECT_GE(primitives_checked, 4u);
}

TEST_F(SkinPassTest, MatchesCpuSkinningOnMannequinWalk) {
  const anim::Character mannequin = anim::build_mannequin();
  auto walk = anim::find_clip(mannequin, "walk");
  ASSERT_TRUE(walk.ok()) << walk.message();
  compare_pose(context(), mannequin, *walk, 0.37f, /*normal_matrices=*/false);
}

TEST_F(SkinPassTest, MatchesCpuSkinningWithNormalMatrices) {
  const anim::Character mannequin = anim::build_mannequin();
  auto wave = anim::find_clip(mannequin, "wave");
  ASSERT_TRUE(wave.ok()) << wave.message();
  compare_pose(context(), mannequin, *wave, 1.1f, /*normal_matrices=*/true);
}

}  // namespace
}  // namespace proxygi::gpu
