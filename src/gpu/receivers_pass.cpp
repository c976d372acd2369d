#include "gpu/receivers_pass.h"

#include "shaders/shared/layouts.h"

namespace proxygi::gpu {

using namespace gpu_layout;

Result<ReceiversPass> ReceiversPass::create(const Context& context) {
  const ComputeBinding bindings[] = {{kReceiversBindFrame, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER},
                                     {kReceiversBindPositionDepth, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE},
                                     {kReceiversBindNormal, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE},
                                     {kReceiversBindReceivers, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}};
  auto pipeline = make_compute_pipeline(context, "receivers.comp", bindings);
  if (!pipeline) return pipeline.error();
  ReceiversPass pass;
  pass.pipeline_ = std::move(*pipeline);
  return pass;
}

std::vector<ResourceAccess> ReceiversPass::accesses(const Inputs& in, const Outputs& out) const {
  return {reads(in.constants), reads(in.position_depth), reads(in.normal), writes(out.receivers)};
}

void ReceiversPass::record(const Context& context, VkCommandBuffer commands, const Inputs& in,
                           const Outputs& out) const {
  pipeline_.bind(commands);
  DescriptorPush()
      .uniform_buffer(kReceiversBindFrame, *in.constants)
      .storage_image(kReceiversBindPositionDepth, in.position_depth->view())
      .storage_image(kReceiversBindNormal, in.normal->view())
      .storage_buffer(kReceiversBindReceivers, *out.receivers)
      .push(context, commands, pipeline_);
  dispatch_grid(commands, in.receiver_width, in.receiver_height);
}

}  // namespace proxygi::gpu
