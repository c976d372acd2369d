#include "gpu/skin_pass.h"

#include <algorithm>
#include <cstring>
#include <string>
#include <vector>

#include "gpu/context.h"
#include "gpu/transfer.h"
#include "shaders/shared/layouts.h"
#include "shaders/shared/skin_palette.h"

namespace proxygi::gpu {
namespace {

constexpr VkBufferUsageFlags kStorage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;

template <class T>
std::span<const std::uint8_t> bytes_of(const std::vector<T>& values) {
  return {reinterpret_cast<const std::uint8_t*>(values.data()), values.size() * sizeof(T)};
}

// Dense target-major delta arrays (zeros where a target has none), as skin.comp reads them.
Status upload_morph_targets(Context& context, const anim::Primitive& primitive, bool has_normals, SkinBindPose& out) {
  const std::size_t vertices = primitive.positions.size(), targets = primitive.morph_targets.size();
  if (targets == 0) return {};
  std::vector<glm::vec3> positions(targets * vertices, glm::vec3(0.0f)), normals;
  if (has_normals) normals.assign(targets * vertices, glm::vec3(0.0f));
  for (std::size_t t = 0; t < targets; ++t) {
    const anim::MorphTarget& target = primitive.morph_targets[t];
    const std::string what = "skin pass: morph target " + std::to_string(t);
    if (!target.position_deltas.empty() && target.position_deltas.size() != vertices)
      return make_error(what + ": " + std::to_string(target.position_deltas.size()) + " position deltas, expected " +
                        std::to_string(vertices));
    if (!target.normal_deltas.empty() && target.normal_deltas.size() != vertices)
      return make_error(what + ": " + std::to_string(target.normal_deltas.size()) + " normal deltas, expected " +
                        std::to_string(vertices));
    std::copy(target.position_deltas.begin(), target.position_deltas.end(), positions.begin() + std::ptrdiff_t(t * vertices));
    if (has_normals)
      std::copy(target.normal_deltas.begin(), target.normal_deltas.end(), normals.begin() + std::ptrdiff_t(t * vertices));
  }
  auto position_buffer = create_buffer_with_data(context, bytes_of(positions), kStorage);
  if (!position_buffer) return position_buffer.error();
  out.position_deltas = std::move(*position_buffer);
  if (has_normals) {
    auto normal_buffer = create_buffer_with_data(context, bytes_of(normals), kStorage);
    if (!normal_buffer) return normal_buffer.error();
    out.normal_deltas = std::move(*normal_buffer);
  }
  return {};
}

}  // namespace

Result<SkinPass> SkinPass::create(const Context& context) {
  using namespace gpu_layout;
  SkinPass pass;
  for (const PaletteBinding binding : {PaletteBinding::uniform, PaletteBinding::storage}) {
    const VkDescriptorType palette_type =
        binding == PaletteBinding::uniform ? VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER : VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    std::vector<Binding> bindings;
    for (std::uint32_t slot : {kSkinBindBindPositions, kSkinBindBindNormals, kSkinBindJoints, kSkinBindWeights,
                               kSkinBindSkinMatrices, kSkinBindNormalMatrices, kSkinBindOutPositions,
                               kSkinBindOutNormals, kSkinBindPositionDeltas, kSkinBindNormalDeltas,
                               kSkinBindMorphWeights}) {
      const bool palette = slot == kSkinBindSkinMatrices || slot == kSkinBindNormalMatrices;
      bindings.push_back({slot, palette ? palette_type : VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_COMPUTE_BIT});
    }
    const char* shader = binding == PaletteBinding::uniform ? "skin.comp" : "skin.comp:storage_palette";
    auto pipeline = Pipeline::compute(context, shader, bindings, sizeof(gpu_layout::SkinPush));
    if (!pipeline) return pipeline.error();
    (binding == PaletteBinding::uniform ? pass.uniform_pipeline_ : pass.storage_pipeline_) = std::move(*pipeline);
  }
  const std::uint32_t device_joints = context.limits().maxUniformBufferRange / std::uint32_t(sizeof(glm::mat4));
  pass.uniform_joints_ = device_joints >= kSkinUniformPaletteJoints ? kSkinUniformPaletteJoints : 0u;
  return pass;
}

Result<SkinnedPrimitive> SkinPass::upload(Context& context, const anim::Primitive& primitive) {
  auto bind_pose = upload_bind_pose(context, primitive);
  if (!bind_pose) return bind_pose.error();
  return instantiate(context, std::move(*bind_pose));
}

Result<std::shared_ptr<const SkinBindPose>> SkinPass::upload_bind_pose(Context& context,
                                                                      const anim::Primitive& primitive) {
  if (primitive.influences_per_vertex < 1) return make_error("skin pass: primitive has no skin influences");
  if (primitive.positions.empty()) return make_error("skin pass: primitive has no vertices");
  auto bind_pose = std::make_shared<SkinBindPose>();
  SkinBindPose& out = *bind_pose;
  out.vertex_count = static_cast<std::uint32_t>(primitive.positions.size());
  out.influences = static_cast<std::uint32_t>(primitive.influences_per_vertex);
  out.has_normals = primitive.normals.size() == primitive.positions.size();

  std::vector<std::uint16_t> joints = primitive.joints;
  if (joints.size() % 2) joints.push_back(0);  // whole uints
  const std::vector<float> dummy_normal = {0.0f};

  struct Upload {
    Buffer* target;
    std::span<const std::uint8_t> bytes;
  };
  const Upload uploads[] = {
      {&out.positions, bytes_of(primitive.positions)},
      {&out.normals, out.has_normals ? bytes_of(primitive.normals) : bytes_of(dummy_normal)},
      {&out.joints, bytes_of(joints)},
      {&out.weights, bytes_of(primitive.weights)},
  };
  for (const auto& item : uploads) {
    auto buffer = create_buffer_with_data(context, item.bytes, kStorage);
    if (!buffer) return buffer.error();
    *item.target = std::move(*buffer);
  }
  if (Status morphs = upload_morph_targets(context, primitive, out.has_normals, out); !morphs) return morphs.error();
  out.morph_targets = std::uint32_t(primitive.morph_targets.size());
  return std::shared_ptr<const SkinBindPose>(std::move(bind_pose));
}

Result<SkinnedPrimitive> SkinPass::instantiate(const Context& context, std::shared_ptr<const SkinBindPose> bind_pose) {
  SkinnedPrimitive out;
  out.vertex_count = bind_pose->vertex_count;
  out.influences = bind_pose->influences;
  out.has_normals = bind_pose->has_normals;
  out.morph_targets = bind_pose->morph_targets;
  out.bind_pose = std::move(bind_pose);
  const VkDeviceSize output_bytes = VkDeviceSize(out.vertex_count) * sizeof(float) * 4;
  const VkBufferUsageFlags output_usage = kStorage | VK_BUFFER_USAGE_TRANSFER_SRC_BIT;
  auto positions = Buffer::create(context, output_bytes, output_usage, MemoryKind::device_local);
  if (!positions) return positions.error();
  auto normals = Buffer::create(context, output_bytes, output_usage, MemoryKind::device_local);
  if (!normals) return normals.error();
  out.world_positions = std::move(*positions);
  out.world_normals = std::move(*normals);
  return out;
}

PaletteBinding SkinPass::binding_for(std::uint32_t joints) const {
  return joints <= uniform_joints_ ? PaletteBinding::uniform : PaletteBinding::storage;
}

std::uint32_t SkinPass::instance_stride(const Context& context, std::uint32_t vertex_count) {
  const VkDeviceSize alignment = std::max<VkDeviceSize>(context.limits().minStorageBufferOffsetAlignment, 16);
  const std::uint32_t per = std::uint32_t((alignment + 15) / 16);  // vertices (vec4) per alignment unit
  return (vertex_count + per - 1) / per * per;
}

void SkinPass::record(const Context& context, VkCommandBuffer commands, const SkinnedPrimitive& primitive,
                      const SkinPalette& palette, const Buffer* morph_weights,
                      std::optional<PaletteBinding> binding) const {
  SkinBatch batch;
  batch.bind_pose = primitive.bind_pose.get();
  batch.instances = 1;
  batch.instance_stride = primitive.vertex_count;
  batch.world_positions = &primitive.world_positions;
  batch.world_normals = &primitive.world_normals;
  batch.palette = palette;
  batch.morph_weights = morph_weights;
  record(context, commands, batch, binding);
}

void SkinPass::record(const Context& context, VkCommandBuffer commands, const SkinBatch& batch,
                      std::optional<PaletteBinding> binding) const {
  const SkinBindPose& bind = *batch.bind_pose;
  // Without morphing the delta and weight bindings are never read: any buffer fills them.
  const bool morphing = batch.morph_weights != nullptr && bind.morph_targets > 0;
  const Buffer& position_deltas = morphing ? bind.position_deltas : bind.positions;
  const Buffer& normal_deltas = morphing && bind.has_normals ? bind.normal_deltas : bind.normals;
  const SkinPalette& palette = batch.palette;
  const bool uniform = binding.value_or(binding_for(batch.instances * palette.joints)) == PaletteBinding::uniform;
  const Pipeline& pipeline = uniform ? uniform_pipeline_ : storage_pipeline_;
  const Buffer& skin_matrices = *palette.skin_matrices;
  const Buffer& normal_matrices = palette.normal_matrices ? *palette.normal_matrices : skin_matrices;
  context.begin_label(commands, kName);
  pipeline.bind(commands);
  DescriptorPush descriptors;
  descriptors.storage_buffer(gpu_layout::kSkinBindBindPositions, bind.positions)
      .storage_buffer(gpu_layout::kSkinBindBindNormals, bind.normals)
      .storage_buffer(gpu_layout::kSkinBindJoints, bind.joints)
      .storage_buffer(gpu_layout::kSkinBindWeights, bind.weights)
      .storage_buffer(gpu_layout::kSkinBindOutPositions, *batch.world_positions)
      .storage_buffer(gpu_layout::kSkinBindOutNormals, *batch.world_normals)
      .storage_buffer(gpu_layout::kSkinBindPositionDeltas, position_deltas)
      .storage_buffer(gpu_layout::kSkinBindNormalDeltas, normal_deltas)
      .storage_buffer(gpu_layout::kSkinBindMorphWeights, morphing ? *batch.morph_weights : bind.weights);
  if (uniform)
    descriptors.uniform_buffer(gpu_layout::kSkinBindSkinMatrices, skin_matrices)
        .uniform_buffer(gpu_layout::kSkinBindNormalMatrices, normal_matrices);
  else
    descriptors.storage_buffer(gpu_layout::kSkinBindSkinMatrices, skin_matrices)
        .storage_buffer(gpu_layout::kSkinBindNormalMatrices, normal_matrices);
  descriptors.push(context, commands, pipeline);
  const gpu_layout::SkinPush push{bind.vertex_count,
                                  bind.influences,
                                  bind.has_normals ? 1u : 0u,
                                  palette.normal_matrices ? 1u : 0u,
                                  morphing ? bind.morph_targets : 0u,
                                  palette.joints,
                                  batch.instance_stride,
                                  0u};
  pipeline.push_constants(commands, &push, sizeof(push));
  vkCmdDispatch(commands, group_count(bind.vertex_count, gpu_layout::kSkinLocalSize), batch.instances, 1);
  context.end_label(commands);
}

void SkinPass::record_outputs_barrier(VkCommandBuffer commands) { memory_barrier(commands); }

}  // namespace proxygi::gpu
