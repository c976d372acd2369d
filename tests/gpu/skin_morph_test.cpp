// GPU morph targets + skinning against the CPU twins (anim::MorphJob, then anim::SkinningJob)
// on the mannequin mid-walk with synthetic targets: every vertex within 1e-5 × the model's
// bounding-box diagonal, normals within 1e-5 (as SkinPassTest).
#include <algorithm>
#include <cmath>
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

using SkinMorphTest = testing::GpuTest;

using testing::read_vec4s;

// Target 0 moves positions and normals, target 1 positions only (its normal deltas are absent,
// so the GPU reads zeros there), target 2 normals only.
std::vector<anim::MorphTarget> synthetic_targets(std::size_t vertices) {
  std::vector<anim::MorphTarget> targets(3);
  for (std::size_t v = 0; v < vertices; ++v) {
    const float x = float(v);
    targets[0].position_deltas.emplace_back(0.03f * std::sin(x), 0.02f * std::cos(0.7f * x), 0.01f);
    targets[0].normal_deltas.emplace_back(0.2f * std::cos(x), 0.0f, 0.1f * std::sin(1.3f * x));
    targets[1].position_deltas.emplace_back(-0.01f, 0.04f * std::sin(0.3f * x), 0.02f * std::cos(x));
    targets[2].normal_deltas.emplace_back(0.0f, 0.3f * std::sin(0.5f * x), -0.1f);
  }
  return targets;
}

TEST_F(SkinMorphTest, MatchesCpuMorphThenSkinning) {
  const anim::Character mannequin = anim::build_mannequin();
  auto walk = anim::find_clip(mannequin, "walk");
  ASSERT_TRUE(walk.ok()) << walk.message();
  anim::PoseBuffers pose;
  ASSERT_TRUE(anim::evaluate_pose(mannequin, *walk, 0.37f, anim::WrapMode::loop, pose).ok());
  auto pass = SkinPass::create(context());
  ASSERT_TRUE(pass.ok()) << pass.message();
  const std::vector<float> morph_weights = {0.7f, -0.4f, 1.5f};
  auto weight_buffer = create_buffer_with_data(context(), as_bytes(std::span<const float>(morph_weights)),
                                               VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
  ASSERT_TRUE(weight_buffer.ok());

  std::size_t primitives_checked = 0;
  glm::vec3 low(1e30f), high(-1e30f);  // over the primitives so far, as SkinPassTest
  for (const auto& node : mannequin.nodes) {
    if (node.mesh < 0 || node.skin < 0) continue;
    const auto& palette = pose.skin_matrices[std::size_t(node.skin)];
    const auto& normal_palette = pose.normal_matrices[std::size_t(node.skin)];
    auto skin_buffer = create_buffer_with_data(context(), as_bytes(std::span<const glm::mat4>(palette)),
                                               SkinPass::kPaletteUsage);
    auto normal_buffer = create_buffer_with_data(context(), as_bytes(std::span<const glm::mat4>(normal_palette)),
                                                 SkinPass::kPaletteUsage);
    ASSERT_TRUE(skin_buffer.ok() && normal_buffer.ok());
    for (anim::Primitive primitive : mannequin.meshes[std::size_t(node.mesh)].primitives) {
      ASSERT_EQ(primitive.normals.size(), primitive.positions.size());
      primitive.morph_targets = synthetic_targets(primitive.positions.size());
      const std::size_t vertices = primitive.positions.size();

      std::vector<glm::vec3> morphed_positions(vertices), morphed_normals(vertices);
      anim::MorphJob morph{primitive.morph_targets, morph_weights, primitive.positions, primitive.normals,
                           morphed_positions, morphed_normals};
      ASSERT_TRUE(morph.run().ok());
      std::vector<glm::vec3> cpu_positions(vertices), cpu_normals(vertices);
      anim::SkinningJob job;
      job.influences_per_vertex = primitive.influences_per_vertex;
      job.skin_matrices = palette;
      job.normal_matrices = normal_palette;
      job.joints = primitive.joints;
      job.weights = primitive.weights;
      job.positions = morphed_positions;
      job.normals = morphed_normals;
      job.out_positions = cpu_positions;
      job.out_normals = cpu_normals;
      ASSERT_TRUE(job.run().ok());
      // The morph must move the result, or the comparison would not test it.
      std::vector<glm::vec3> unmorphed(vertices), unmorphed_normals(vertices);
      job.positions = primitive.positions;
      job.normals = primitive.normals;
      job.out_positions = unmorphed;
      job.out_normals = unmorphed_normals;
      ASSERT_TRUE(job.run().ok());

      for (const auto& p : cpu_positions) {
        low = glm::min(low, p);
        high = glm::max(high, p);
      }
      auto uploaded = SkinPass::upload(context(), primitive);
      ASSERT_TRUE(uploaded.ok()) << uploaded.message();
      ASSERT_EQ(uploaded->morph_targets, 3u);
      ASSERT_TRUE(context()
                      .submit_and_wait([&](VkCommandBuffer commands) {
                        pass->record(context(), commands, *uploaded,
                                     SkinPalette{&*skin_buffer, &*normal_buffer, std::uint32_t(palette.size())},
                                     &*weight_buffer);
                        SkinPass::record_outputs_barrier(commands);
                      })
                      .ok());
      const auto gpu_positions = read_vec4s(context(), uploaded->world_positions, vertices);
      const auto gpu_normals = read_vec4s(context(), uploaded->world_normals, vertices);
      const float diagonal = glm::length(high - low);
      ASSERT_GT(diagonal, 0.0f);
      float worst_position = 0.0f, worst_normal = 0.0f, largest_morph = 0.0f;
      for (std::size_t i = 0; i < vertices; ++i) {
        worst_position = std::max(worst_position, glm::length(glm::vec3(gpu_positions[i]) - cpu_positions[i]));
        worst_normal = std::max(worst_normal, glm::length(glm::vec3(gpu_normals[i]) - cpu_normals[i]));
        largest_morph = std::max(largest_morph, glm::length(cpu_positions[i] - unmorphed[i]));
      }
      EXPECT_GT(largest_morph, 0.01f);
      EXPECT_LE(worst_position, 1e-5f * diagonal) << "primitive with " << vertices << " vertices";
      EXPECT_LE(worst_normal, 1e-5f);
      ++primitives_checked;
    }
  }
  EXPECT_GE(primitives_checked, 4u);
}

}  // namespace
}  // namespace proxygi::gpu
