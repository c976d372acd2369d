#include "gpu/frame_passes.h"

#include <vector>

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
    case FramePass::count: break;
  }
  return "unknown";
}

std::span<const FramePass> frame_pass_order(settings::ShadingMethod method) {
  static constexpr FramePass kImageSpace[] = {FramePass::gbuffer, FramePass::receivers, FramePass::shadow,
                                              FramePass::exponentiate, FramePass::indirect,
                                              FramePass::upsample_composite};
  // The G-buffer pass interpolates the vertex irradiance, so it follows the shading passes.
  static constexpr FramePass kVertex[] = {FramePass::receivers, FramePass::shadow, FramePass::exponentiate,
                                          FramePass::indirect, FramePass::gbuffer, FramePass::upsample_composite};
  static constexpr FramePass kAmbientOcclusion[] = {FramePass::gbuffer, FramePass::receivers, FramePass::shadow,
                                                    FramePass::upsample_composite};
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

std::string order_variant(const std::string& shader, int order) { return shader + ":order" + std::to_string(order); }

}  // namespace proxygi::gpu
