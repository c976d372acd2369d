#include "view/overlay_blend_pass.h"

#include "gpu/vulkan_check.h"
#include "shaders/shared/overlay_layouts.h"

namespace proxygi::view {

Result<std::unique_ptr<OverlayBlendPass>> OverlayBlendPass::create(const gpu::Context& context, VkFormat format) {
  std::unique_ptr<OverlayBlendPass> pass(new OverlayBlendPass());
  pass->device_ = context.device();
  const gpu::Binding bindings[] = {
      {PROXYGI_OVERLAY_BIND_OVERLAY, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_SHADER_STAGE_FRAGMENT_BIT}};
  gpu::GraphicsPipelineDescription description;
  description.vertex_shader = "fullscreen.vert";
  description.fragment_shader = "overlay_blend.frag";
  description.color_formats = {format};
  description.blend = gpu::BlendMode::premultiplied_over;
  auto pipeline = gpu::Pipeline::graphics(context, description, bindings, 0);
  if (!pipeline) return pipeline.error();
  pass->pipeline_ = std::move(*pipeline);
  VkSamplerCreateInfo sampler{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};  // texelFetch: no filtering used
  sampler.magFilter = sampler.minFilter = VK_FILTER_NEAREST;
  sampler.addressModeU = sampler.addressModeV = sampler.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
  PROXYGI_VK_TRY(vkCreateSampler(pass->device_, &sampler, nullptr, &pass->sampler_));
  return pass;
}

OverlayBlendPass::~OverlayBlendPass() {
  if (sampler_) vkDestroySampler(device_, sampler_, nullptr);
}

void OverlayBlendPass::record(const gpu::Context& context, VkCommandBuffer commands, const Inputs& in,
                              const Outputs& out) const {
  if (in.rects.empty()) return;
  const TargetImage& target = *out.target;
  VkRenderingAttachmentInfo color{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
  color.imageView = target.view;
  color.imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
  color.loadOp = VK_ATTACHMENT_LOAD_OP_LOAD;
  color.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
  VkRenderingInfo rendering{VK_STRUCTURE_TYPE_RENDERING_INFO};
  rendering.renderArea = {{0, 0}, {target.width, target.height}};
  rendering.layerCount = 1;
  rendering.colorAttachmentCount = 1;
  rendering.pColorAttachments = &color;
  vkCmdBeginRendering(commands, &rendering);
  pipeline_.bind(commands);
  gpu::DescriptorPush().sampled_image(PROXYGI_OVERLAY_BIND_OVERLAY, in.overlay, sampler_).push(context, commands, pipeline_);
  const VkViewport viewport{0, 0, float(target.width), float(target.height), 0, 1};
  vkCmdSetViewport(commands, 0, 1, &viewport);
  for (const PixelRect& rect : in.rects) {
    const VkRect2D scissor{{rect.x0, rect.y0}, {std::uint32_t(rect.x1 - rect.x0), std::uint32_t(rect.y1 - rect.y0)}};
    vkCmdSetScissor(commands, 0, 1, &scissor);
    vkCmdDraw(commands, 3, 1, 0, 0);
  }
  vkCmdEndRendering(commands);
}

}  // namespace proxygi::view
