#include "gpu/ambient_occlusion_pass.h"

#include "shaders/shared/layouts.h"

namespace proxygi::gpu {

using namespace gpu_layout;

Result<AmbientOcclusionPass> AmbientOcclusionPass::create(const Context& context, int order) {
  const ComputeBinding bindings[] = {{kAoBindFrame, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER},
                                     {kAoBindReceivers, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
                                     {kAoBindProxies, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER},
                                     {kAoBindLightingCube, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
                                     {kAoBindDirect, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
                                     {kAoBindIndirect, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
                                     {kAoBindShaded, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
                                     {kAoBindTileCounts, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}};
  auto pipeline = make_compute_pipeline(context, order_variant("ambient_occlusion.comp", order), bindings);
  if (!pipeline) return pipeline.error();
  AmbientOcclusionPass pass;
  pass.pipeline_ = std::move(*pipeline);
  return pass;
}

std::vector<ResourceAccess> AmbientOcclusionPass::accesses(const Inputs& in, const Outputs& out) const {
  return {reads(in.constants),   reads(in.receivers),    reads(in.proxies),  reads(in.lighting_cube),
          writes(out.direct),    writes(out.indirect),   writes(out.shaded), writes(out.tile_counts)};
}

void AmbientOcclusionPass::record(const Context& context, VkCommandBuffer commands, const Inputs& in,
                                  const Outputs& out) const {
  pipeline_.bind(commands);
  DescriptorPush()
      .uniform_buffer(kAoBindFrame, *in.constants)
      .storage_buffer(kAoBindReceivers, *in.receivers)
      .uniform_buffer(kAoBindProxies, *in.proxies)
      .storage_buffer(kAoBindLightingCube, *in.lighting_cube)
      .storage_buffer(kAoBindDirect, *out.direct)
      .storage_buffer(kAoBindIndirect, *out.indirect)
      .storage_buffer(kAoBindShaded, *out.shaded)
      .storage_buffer(kAoBindTileCounts, *out.tile_counts)
      .push(context, commands, pipeline_);
  dispatch_grid(commands, in.receiver_width, in.receiver_height);
}

}  // namespace proxygi::gpu
