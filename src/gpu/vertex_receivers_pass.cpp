#include "gpu/vertex_receivers_pass.h"

#include "gpu/frame_config.h"
#include "shaders/shared/layouts.h"

namespace proxygi::gpu {

using namespace gpu_layout;

std::uint32_t vertex_receiver_count(std::span<const DrawItem> draws) {
  std::uint32_t total = 0;
  for (const DrawItem& draw : draws) total += round_up_to_receiver_group(draw.vertex_count());
  return total;
}

Result<VertexReceiversPass> VertexReceiversPass::create(const Context& context) {
  const ComputeBinding bindings[] = {{kVertexReceiversBindPositions, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
                                     {kVertexReceiversBindNormals, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
                                     {kVertexReceiversBindReceivers, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}};
  auto pipeline = make_compute_pipeline(context, "vertex_receivers.comp", bindings, sizeof(VertexReceiversPush));
  if (!pipeline) return pipeline.error();
  VertexReceiversPass pass;
  pass.pipeline_ = std::move(*pipeline);
  return pass;
}

std::vector<ResourceAccess> VertexReceiversPass::accesses(const Inputs& in, const Outputs& out) const {
  std::vector<ResourceAccess> out_accesses = {
      writes(out.receivers, VK_PIPELINE_STAGE_2_CLEAR_BIT | VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT)};
  for (const DrawItem& draw : in.draws) {
    out_accesses.push_back(reads(draw.positions));
    out_accesses.push_back(reads(draw.normals));
  }
  return out_accesses;
}

void VertexReceiversPass::record(const Context& context, VkCommandBuffer commands, const Inputs& in,
                                 const Outputs& out) const {
  // Zero first: padding and any capacity the draws leave unused read as "no receiver" (w = 0).
  vkCmdFillBuffer(commands, out.receivers->handle(), 0, VK_WHOLE_SIZE, 0);
  PassBarriers fill;  // the fill, then the dispatches writing over it
  const ResourceAccess cleared[] = {writes(out.receivers, VK_PIPELINE_STAGE_2_CLEAR_BIT)};
  const ResourceAccess written[] = {writes(out.receivers)};
  fill.before(commands, cleared);
  fill.before(commands, written);
  pipeline_.bind(commands);
  std::uint32_t offset = 0;
  for (const DrawItem& draw : in.draws) {
    const std::uint32_t count = draw.vertex_count();
    if (offset + round_up_to_receiver_group(count) > in.receiver_capacity) break;  // the G-buffer skips these too
    DescriptorPush()
        .storage_buffer(kVertexReceiversBindPositions, *draw.positions, draw.vertex_bytes())
        .storage_buffer(kVertexReceiversBindNormals, *draw.normals, draw.vertex_bytes())
        .storage_buffer(kVertexReceiversBindReceivers, *out.receivers)
        .push(context, commands, pipeline_);
    const VertexReceiversPush push{count, offset, 0, 0};
    pipeline_.push_constants(commands, &push, sizeof(push));
    if (count > 0) vkCmdDispatch(commands, group_count(count, kVertexReceiverGroup), 1, 1);
    offset += round_up_to_receiver_group(count);
  }
}

}  // namespace proxygi::gpu
