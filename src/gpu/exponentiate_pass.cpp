#include "gpu/exponentiate_pass.h"

#include "shaders/shared/layouts.h"

namespace proxygi::gpu {

using namespace gpu_layout;

Result<ExponentiatePass> ExponentiatePass::create(const Context& context, int order) {
  const ComputeBinding bindings[] = {{kExponentiateBindFrame, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER},
                                     {kExponentiateBindReceivers, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
                                     {kExponentiateBindLogOcclusion, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
                                     {kExponentiateBindOptimalLinear, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
                                     {kExponentiateBindLightingCube, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
                                     {kExponentiateBindDirect, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}};
  auto pipeline = make_compute_pipeline(context, order_variant("exponentiate.comp", order), bindings);
  if (!pipeline) return pipeline.error();
  ExponentiatePass pass;
  pass.pipeline_ = std::move(*pipeline);
  return pass;
}

std::vector<ResourceAccess> ExponentiatePass::accesses(const Inputs& in, const Outputs& out) const {
  return {reads(in.constants),      reads(in.receivers),     reads(in.log_occlusion),
          reads(in.optimal_linear), reads(in.lighting_cube), writes(out.direct)};
}

void ExponentiatePass::record(const Context& context, VkCommandBuffer commands, const Inputs& in,
                              const Outputs& out) const {
  pipeline_.bind(commands);
  DescriptorPush()
      .uniform_buffer(kExponentiateBindFrame, *in.constants)
      .storage_buffer(kExponentiateBindReceivers, *in.receivers)
      .storage_buffer(kExponentiateBindLogOcclusion, *in.log_occlusion)
      .storage_buffer(kExponentiateBindOptimalLinear, *in.optimal_linear)
      .storage_buffer(kExponentiateBindLightingCube, *in.lighting_cube)
      .storage_buffer(kExponentiateBindDirect, *out.direct)
      .push(context, commands, pipeline_);
  dispatch_grid(commands, in.receiver_width, in.receiver_height);
}

}  // namespace proxygi::gpu
