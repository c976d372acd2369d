#include "gpu/indirect_pass.h"

#include "shaders/shared/layouts.h"

namespace proxygi::gpu {

using namespace gpu_layout;

Result<IndirectPass> IndirectPass::create(const Context& context, const settings::RenderSettings& render) {
  const ComputeBinding bindings[] = {{kIndirectBindFrame, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER},
                                     {kIndirectBindReceivers, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
                                     {kIndirectBindProxies, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER},
                                     {kIndirectBindVisibilityTable, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
                                     {kIndirectBindDirect, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
                                     {kIndirectBindIndirect, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
                                     {kIndirectBindShaded, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
                                     {kIndirectBindExactTable, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
                                     {kIndirectBindVsglLights, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
                                     {kIndirectBindSenderLight, VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER}};
  const std::string variant = render.indirect_method == settings::IndirectMethod::vsgl
                                  ? std::string("vsgl")
                                  : std::string(settings::name_of(render.indirect_operator));
  auto pipeline = make_compute_pipeline(context, "indirect.comp:" + variant, bindings);
  if (!pipeline) return pipeline.error();
  IndirectPass pass;
  pass.pipeline_ = std::move(*pipeline);
  return pass;
}

std::vector<ResourceAccess> IndirectPass::accesses(const Inputs& in, const Outputs& out) const {
  return {reads(in.constants), reads(in.receivers),   reads(in.proxies),    reads(in.visibility_table),
          reads(in.direct),    reads(in.exact_table), reads(in.vsgl_lights), reads(in.sender_light),
          writes(out.indirect), writes(out.shaded)};
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
      .storage_buffer(kIndirectBindVsglLights, *in.vsgl_lights)
      .uniform_texel_buffer(kIndirectBindSenderLight, in.sender_light->texel_view())
      .push(context, commands, pipeline_);
  dispatch_grid(commands, in.receiver_width, in.receiver_height);
}

}  // namespace proxygi::gpu
