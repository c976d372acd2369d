#include "gpu/frame_passes.h"

#include <vector>

#include "base/check.h"
#include "gpu/transfer.h"
#include "shaders/shared/layouts.h"

namespace proxygi::gpu {

const char* frame_pass_name(FramePass pass) {
  switch (pass) {
    case FramePass::skin: return "skin";
    case FramePass::gbuffer: return "gbuffer";
    case FramePass::receivers: return "receivers";
    case FramePass::shadow: return "shadow";
    case FramePass::exponentiate: return "exponentiate";
    case FramePass::indirect: return "indirect";
    case FramePass::upsample_composite: return "upsample+composite";
    case FramePass::supersample_resolve: return "supersample_resolve";
    case FramePass::count: break;
  }
  return "unknown";
}

std::span<const FramePass> frame_pass_order(settings::ShadingMethod method) {
  static constexpr FramePass kImageSpace[] = {FramePass::gbuffer, FramePass::receivers, FramePass::shadow,
                                              FramePass::exponentiate, FramePass::indirect,
                                              FramePass::upsample_composite, FramePass::supersample_resolve};
  // The G-buffer pass interpolates the vertex irradiance, so it follows the shading passes.
  static constexpr FramePass kVertex[] = {FramePass::receivers, FramePass::shadow, FramePass::exponentiate,
                                          FramePass::indirect, FramePass::gbuffer, FramePass::upsample_composite,
                                          FramePass::supersample_resolve};
  static constexpr FramePass kAmbientOcclusion[] = {FramePass::gbuffer, FramePass::receivers, FramePass::shadow,
                                                    FramePass::upsample_composite, FramePass::supersample_resolve};
  switch (method) {
    case settings::ShadingMethod::vertex: return kVertex;
    case settings::ShadingMethod::ambient_occlusion: return kAmbientOcclusion;
    case settings::ShadingMethod::image_space: break;
  }
  return kImageSpace;
}

Result<Pipeline> make_compute_pipeline(const Context& context, const std::string& shader,
                                       std::span<const ComputeBinding> bindings, std::uint32_t push_bytes) {
  std::vector<Binding> layout;
  for (const ComputeBinding& binding : bindings) layout.push_back({binding.binding, binding.type, VK_SHADER_STAGE_COMPUTE_BIT});
  auto pipeline = Pipeline::compute(context, shader, layout, push_bytes);
  if (!pipeline) return make_error(shader + ": " + pipeline.message());
  return pipeline;
}

void dispatch_grid(VkCommandBuffer commands, std::uint32_t width, std::uint32_t height) {
  vkCmdDispatch(commands, group_count(width, gpu_layout::kFrameLocalSize), group_count(height, gpu_layout::kFrameLocalSize),
                1);
}

VkRenderingAttachmentInfo attachment_info(const Image& image, VkImageLayout layout, VkAttachmentLoadOp load) {
  VkRenderingAttachmentInfo info{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
  info.imageView = image.view();
  info.imageLayout = layout;
  info.loadOp = load;
  info.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
  return info;
}

void begin_cleared_rendering(VkCommandBuffer commands, std::span<const Image* const> colors, const Image& depth,
                             std::uint32_t width, std::uint32_t height) {
  VkRenderingAttachmentInfo color_attachments[4];
  PROXYGI_CHECK(colors.size() <= std::size(color_attachments), "at most 4 colour targets");
  for (std::size_t i = 0; i < colors.size(); ++i) {
    transition(commands, *colors[i], VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL);
    color_attachments[i] = attachment_info(*colors[i], VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_ATTACHMENT_LOAD_OP_CLEAR);
    color_attachments[i].clearValue.color = {{0.0f, 0.0f, 0.0f, 0.0f}};
  }
  transition(commands, depth, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL);
  VkRenderingAttachmentInfo depth_attachment =
      attachment_info(depth, VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL, VK_ATTACHMENT_LOAD_OP_CLEAR);
  depth_attachment.storeOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
  depth_attachment.clearValue.depthStencil = {1.0f, 0};
  VkRenderingInfo rendering{VK_STRUCTURE_TYPE_RENDERING_INFO};
  rendering.renderArea = {{0, 0}, {width, height}};
  rendering.layerCount = 1;
  rendering.colorAttachmentCount = std::uint32_t(colors.size());
  rendering.pColorAttachments = color_attachments;
  rendering.pDepthAttachment = &depth_attachment;
  vkCmdBeginRendering(commands, &rendering);
  const VkViewport viewport{0, 0, float(width), float(height), 0, 1};
  const VkRect2D scissor{{0, 0}, {width, height}};
  vkCmdSetViewport(commands, 0, 1, &viewport);
  vkCmdSetScissor(commands, 0, 1, &scissor);
}

std::string order_variant(const std::string& shader, int order) { return shader + ":order" + std::to_string(order); }

}  // namespace proxygi::gpu
