// The baselines' own passes of SoftGiFrame (frame_settings.h ShadingMethod): the vertex method's
// receivers (mesh vertices gathered into the receiver buffer) and the AO method's occlusion pass.
// Everything else they record is the image-space frame's code in soft_gi_frame.cpp.
#include "gpu/context.h"
#include "gpu/soft_gi_frame.h"
#include "gpu/transfer.h"
#include "shaders/shared/layouts.h"

namespace proxygi::gpu {

std::uint32_t vertex_receiver_count(std::span<const DrawItem> draws) {
  std::uint32_t total = 0;
  for (const DrawItem& draw : draws) total += round_up_to_receiver_group(draw.vertex_count());
  return total;
}

void SoftGiFrame::record_vertex_receivers(VkCommandBuffer commands, std::span<const DrawItem> draws) const {
  context_.begin_label(commands, "vertex receivers");
  // Zero first: padding and any capacity the draws leave unused read as "no receiver" (w = 0).
  vkCmdFillBuffer(commands, receivers_.handle(), 0, VK_WHOLE_SIZE, 0);
  memory_barrier(commands);
  pipelines_.vertex_receivers.bind(commands);
  std::uint32_t offset = 0;
  for (const DrawItem& draw : draws) {
    const std::uint32_t count = draw.vertex_count();
    if (offset + round_up_to_receiver_group(count) > settings_.vertex_receivers) break;  // the G-buffer skips these too
    DescriptorPush()
        .storage_buffer(0, *draw.positions)
        .storage_buffer(1, *draw.normals)
        .storage_buffer(2, receivers_)
        .push(context_, commands, pipelines_.vertex_receivers);
    const gpu_layout::VertexReceiversPush push{count, offset, 0, 0};
    pipelines_.vertex_receivers.push_constants(commands, &push, sizeof(push));
    if (count > 0) vkCmdDispatch(commands, group_count(count, kVertexReceiverGroup), 1, 1);
    offset += round_up_to_receiver_group(count);
  }
  memory_barrier(commands);
  context_.end_label(commands);
}

void SoftGiFrame::record_ambient_occlusion(VkCommandBuffer commands, const Slot& slot) const {
  context_.begin_label(commands, "ambient occlusion");
  pipelines_.ambient_occlusion.bind(commands);
  DescriptorPush()
      .uniform_buffer(0, slot.constants)
      .storage_buffer(1, receivers_)
      .uniform_buffer(2, slot.proxies)
      .storage_buffer(3, lighting_cube_)
      .storage_buffer(4, direct_)
      .storage_buffer(5, indirect_)
      .storage_buffer(6, shaded_)
      .push(context_, commands, pipelines_.ambient_occlusion);
  vkCmdDispatch(commands, group_count(settings_.receiver_width(), gpu_layout::kFrameLocalSize),
                group_count(settings_.receiver_height(), gpu_layout::kFrameLocalSize), 1);
  memory_barrier(commands);
  context_.end_label(commands);
}

}  // namespace proxygi::gpu
