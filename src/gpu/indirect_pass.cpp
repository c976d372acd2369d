#include "gpu/indirect_pass.h"

#include "shaders/shared/layouts.h"

namespace proxygi::gpu {

using namespace gpu_layout;

Result<IndirectPass> IndirectPass::create(const Context& context, settings::IndirectOperator indirect_operator) {
  const ComputeBinding bindings[] = {{kIndirectBindFrame, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER},
                                     {kIndirectBindReceivers, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
                                     {kIndirectBindProxies, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER},
                                     {kIndirectBindVisibilityTable, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
                                     {kIndirectBindDirect, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
                                     {kIndirectBindIndirect, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
                                     {kIndirectBindShaded, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
                                     {kIndirectBindExactTable, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}};
  auto pipeline =
      make_compute_pipeline(context, "indirect.comp:" + std::string(settings::name_of(indirect_operator)), bindings);
  if (!pipeline) return pipeline.error();
  IndirectPass pass;
  pass.pipeline_ = std::move(*pipeline);
  return pass;
}

std::vector<ResourceAccess> IndirectPass::accesses(const Inputs& in, const Outputs& out) const {
  return {reads(in.constants), reads(in.receivers),   reads(in.proxies),    reads(in.visibility_table),
          reads(in.direct),    reads(in.exact_table), writes(out.indirect), writes(out.shaded)};
}

void IndirectPass::record(const Context& context, VkCommandBuffer commands, const Inputs& in,
                          const Outputs& out) const {
  pipeline_.bind(commands);
  DescriptorPush()
      .uniform_buffer(kIndirectBindFrame, *in.constants)
      .storage_buffer(kIndirectBindReceivers, *in.receivers)
      .uniform_buffer(kIndirectBindProxies, *in.proxies)
      .storage_buffer(kIndirectBindVisibilityTable, *in.visibility_table)
      .storage_buffer(kIndirectBindDirect, *in.direct)
      .storage_buffer(kIndirectBindIndirect, *out.indirect)
      .storage_buffer(kIndirectBindShaded, *out.shaded)
      .storage_buffer(kIndirectBindExactTable, *in.exact_table)
      .push(context, commands, pipeline_);
  dispatch_grid(commands, in.receiver_width, in.receiver_height);
}

}  // namespace proxygi::gpu
