#include "gpu/supersample_resolve_pass.h"

#include "shaders/shared/layouts.h"

namespace proxygi::gpu {

using namespace gpu_layout;

Result<SupersampleResolvePass> SupersampleResolvePass::create(const Context& context) {
  const ComputeBinding bindings[] = {{kSupersampleBindSampleHdr, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
                                     {kSupersampleBindSampleLdr, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
                                     {kSupersampleBindHdr, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
                                     {kSupersampleBindLdr, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}};
  auto pipeline = make_compute_pipeline(context, "supersample_resolve.comp", bindings, sizeof(SupersamplePush));
  if (!pipeline) return pipeline.error();
  SupersampleResolvePass pass;
  pass.pipeline_ = std::move(*pipeline);
  return pass;
}

std::vector<ResourceAccess> SupersampleResolvePass::accesses(const Inputs& in, const Outputs& out) const {
  return {reads(in.sample_hdr), reads(in.sample_ldr), writes(out.hdr), writes(out.ldr)};
}

void SupersampleResolvePass::record(const Context& context, VkCommandBuffer commands, const Inputs& in,
                                    const Outputs& out) const {
  pipeline_.bind(commands);
  DescriptorPush()
      .storage_buffer(kSupersampleBindSampleHdr, *in.sample_hdr)
      .storage_buffer(kSupersampleBindSampleLdr, *in.sample_ldr)
      .storage_buffer(kSupersampleBindHdr, *out.hdr)
      .storage_buffer(kSupersampleBindLdr, *out.ldr)
      .push(context, commands, pipeline_);
  const SupersamplePush push{in.width, in.height, in.factor, in.ldr_bgra ? 1u : 0u};
  pipeline_.push_constants(commands, &push, sizeof(push));
  dispatch_grid(commands, in.width, in.height);
}

}  // namespace proxygi::gpu
