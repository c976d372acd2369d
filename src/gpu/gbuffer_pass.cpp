// The G-buffer pass of SoftGiFrame (frame step 2): every draw rasterized at display resolution
// into world position + eye depth, normal (or, for the vertex method, the interpolated vertex
// irradiance) and albedo. Untextured draws go through the untextured pipeline, textured ones
// after them through the textured pipeline (frame_passes.h says why the two are kept apart).
#include <vector>

#include "gpu/context.h"
#include "gpu/soft_gi_frame.h"
#include "gpu/transfer.h"
#include "shaders/shared/layouts.h"

namespace proxygi::gpu {
namespace {

bool is_textured(const DrawItem& draw) {
  return draw.texture.view != VK_NULL_HANDLE && draw.texture.sampler != VK_NULL_HANDLE;
}

}  // namespace

void SoftGiFrame::record_gbuffer(VkCommandBuffer commands, const Slot& slot, std::span<const DrawItem> draws) const {
  context_.begin_label(commands, frame_pass_name(FramePass::gbuffer));
  for (const Image* image : {&position_depth_, &normal_, &albedo_})
    transition(commands, *image, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL);
  transition(commands, depth_, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL);
  VkRenderingAttachmentInfo colors[3];
  const Image* color_images[3] = {&position_depth_, &normal_, &albedo_};
  for (int i = 0; i < 3; ++i) {
    colors[i] = VkRenderingAttachmentInfo{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
    colors[i].imageView = color_images[i]->view();
    colors[i].imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    colors[i].loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
    colors[i].storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    colors[i].clearValue.color = {{0.0f, 0.0f, 0.0f, 0.0f}};
  }
  VkRenderingAttachmentInfo depth{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
  depth.imageView = depth_.view();
  depth.imageLayout = VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL;
  depth.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
  depth.storeOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
  depth.clearValue.depthStencil = {1.0f, 0};
  VkRenderingInfo rendering{VK_STRUCTURE_TYPE_RENDERING_INFO};
  rendering.renderArea = {{0, 0}, {settings_.width, settings_.height}};
  rendering.layerCount = 1;
  rendering.colorAttachmentCount = 3;
  rendering.pColorAttachments = colors;
  rendering.pDepthAttachment = &depth;
  vkCmdBeginRendering(commands, &rendering);
  const VkViewport viewport{0, 0, float(settings_.width), float(settings_.height), 0, 1};
  const VkRect2D scissor{{0, 0}, {settings_.width, settings_.height}};
  vkCmdSetViewport(commands, 0, 1, &viewport);
  vkCmdSetScissor(commands, 0, 1, &scissor);

  // Each draw's first receiver (vertex method) follows the draws' order, whatever order they
  // are recorded in.
  const bool vertex = settings_.method == ShadingMethod::vertex;
  std::vector<std::uint32_t> first_receiver(draws.size());
  std::uint32_t receiver_offset = 0;
  std::size_t shaded_draws = draws.size();
  for (std::size_t i = 0; i < draws.size(); ++i) {
    first_receiver[i] = receiver_offset;
    receiver_offset += round_up_to_receiver_group(draws[i].vertex_count());
    if (vertex && receiver_offset > settings_.vertex_receivers) {  // beyond the capacity: not drawn
      shaded_draws = i;
      break;
    }
  }
  for (const bool textured : {false, true}) {
    const Pipeline& pipeline = vertex ? (textured ? pipelines_.vertex_gbuffer_textured : pipelines_.vertex_gbuffer)
                                      : (textured ? pipelines_.gbuffer_textured : pipelines_.gbuffer);
    bool bound = false;
    for (std::size_t i = 0; i < shaded_draws; ++i) {
      const DrawItem& draw = draws[i];
      if (is_textured(draw) != textured) continue;
      if (!bound) pipeline.bind(commands);
      bound = true;
      DescriptorPush descriptors;
      descriptors.uniform_buffer(0, slot.constants)
          .storage_buffer(1, *draw.positions)
          .storage_buffer(2, *draw.normals)
          .storage_buffer(4, draw.uvs ? *draw.uvs : *draw.positions);  // not read without uvs
      if (textured) descriptors.sampled_image(5, draw.texture.view, draw.texture.sampler);
      if (vertex) descriptors.storage_buffer(3, shaded_);
      descriptors.push(context_, commands, pipeline);
      gpu_layout::GbufferPush push{};
      push.base_color = draw.base_color;
      push.receiver_offset = first_receiver[i];
      const glm::mat3& m = draw.texture.uv_transform;  // column-major: m[column][row]
      push.uv_transform_u = glm::vec4(m[0][0], m[1][0], m[2][0], 0.0f);
      push.uv_transform_v = glm::vec4(m[0][1], m[1][1], m[2][1], 0.0f);
      push.has_uvs = draw.uvs ? 1u : 0u;
      pipeline.push_constants(commands, &push, sizeof(push));
      vkCmdBindIndexBuffer(commands, draw.indices->handle(), 0, VK_INDEX_TYPE_UINT32);
      vkCmdDrawIndexed(commands, draw.index_count, 1, 0, 0, 0);
    }
  }
  vkCmdEndRendering(commands);
  for (const Image* image : {&position_depth_, &normal_, &albedo_})
    transition(commands, *image, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_IMAGE_LAYOUT_GENERAL);
  context_.end_label(commands);
}

}  // namespace proxygi::gpu
