#include "gpu/pass_barriers.h"

namespace proxygi::gpu {
namespace {

constexpr VkPipelineStageFlags2 kShaderStages = VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT |
                                               VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT |
                                               VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT;
constexpr VkPipelineStageFlags2 kDepthStages =
    VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT;

}  // namespace

VkAccessFlags2 access_mask(VkPipelineStageFlags2 stages, Use use) {
  const bool write = use == Use::write;
  VkAccessFlags2 mask = 0;
  if (stages & kShaderStages) mask |= write ? VK_ACCESS_2_SHADER_WRITE_BIT : VK_ACCESS_2_SHADER_READ_BIT;
  if (stages & VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT)
    mask |= write ? VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT : VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT;
  if (stages & kDepthStages)
    mask |= write ? VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT : VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT;
  if (stages & (VK_PIPELINE_STAGE_2_COPY_BIT | VK_PIPELINE_STAGE_2_CLEAR_BIT | VK_PIPELINE_STAGE_2_BLIT_BIT))
    mask |= write ? VK_ACCESS_2_TRANSFER_WRITE_BIT : VK_ACCESS_2_TRANSFER_READ_BIT;
  if (stages & VK_PIPELINE_STAGE_2_INDEX_INPUT_BIT && !write) mask |= VK_ACCESS_2_INDEX_READ_BIT;
  return mask;
}

void PassBarriers::before(VkCommandBuffer commands, std::span<const ResourceAccess> accesses) {
  VkMemoryBarrier2 barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER_2};
  for (const ResourceAccess& access : accesses) {
    const auto found = states_.find(access.resource);
    if (found == states_.end()) continue;
    const State& state = found->second;
    if (state.write_stages != 0) {  // read or write after write: make the write visible
      barrier.srcStageMask |= state.write_stages;
      barrier.srcAccessMask |= access_mask(state.write_stages, Use::write);
      barrier.dstStageMask |= access.stages;
      barrier.dstAccessMask |= access_mask(access.stages, access.use);
    }
    if (access.use == Use::write && state.read_stages != 0) {  // write after read: execution order only
      barrier.srcStageMask |= state.read_stages;
      barrier.dstStageMask |= access.stages;
    }
  }
  if (barrier.srcStageMask != 0) {
    VkDependencyInfo dependency{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
    dependency.memoryBarrierCount = 1;
    dependency.pMemoryBarriers = &barrier;
    vkCmdPipelineBarrier2(commands, &dependency);
    ++barriers_;
  }
  for (const ResourceAccess& access : accesses) {
    State& state = states_[access.resource];
    if (access.use == Use::write) state = {access.stages, 0};
  }
  for (const ResourceAccess& access : accesses)
    if (access.use == Use::read) states_[access.resource].read_stages |= access.stages;
}

}  // namespace proxygi::gpu
