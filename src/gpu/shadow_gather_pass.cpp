#include "gpu/shadow_gather_pass.h"

#include "shaders/shared/layouts.h"

namespace proxygi::gpu {

using namespace gpu_layout;

Result<ShadowGatherPass> ShadowGatherPass::create(const Context& context, int order) {
  const ComputeBinding bindings[] = {{kShadowBindFrame, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER},
                                     {kShadowBindReceivers, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
                                     {kShadowBindProxies, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER},
                                     {kShadowBindLogTable, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
                                     {kShadowBindLogOcclusion, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
                                     {kShadowBindTileCounts, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}};
  auto pipeline = make_compute_pipeline(context, order_variant("shadow_gather.comp", order), bindings);
  if (!pipeline) return pipeline.error();
  ShadowGatherPass pass;
  pass.pipeline_ = std::move(*pipeline);
  return pass;
}

std::vector<ResourceAccess> ShadowGatherPass::accesses(const Inputs& in, const Outputs& out) const {
  return {reads(in.constants), reads(in.receivers), reads(in.proxies), reads(in.log_table), writes(out.log_occlusion), writes(out.tile_counts)};
}

void ShadowGatherPass::record(const Context& context, VkCommandBuffer commands, const Inputs& in,
                              const Outputs& out) const {
  pipeline_.bind(commands);
  DescriptorPush()
      .uniform_buffer(kShadowBindFrame, *in.constants)
      .storage_buffer(kShadowBindReceivers, *in.receivers)
      .uniform_buffer(kShadowBindProxies, *in.proxies)
      .storage_buffer(kShadowBindLogTable, *in.log_table)
      .storage_buffer(kShadowBindLogOcclusion, *out.log_occlusion)
      .storage_buffer(kShadowBindTileCounts, *out.tile_counts)
      .push(context, commands, pipeline_);
  dispatch_grid(commands, in.receiver_width, in.receiver_height);
}

}  // namespace proxygi::gpu
