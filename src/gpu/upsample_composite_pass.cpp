#include "gpu/upsample_composite_pass.h"

#include "shaders/shared/layouts.h"

namespace proxygi::gpu {

using namespace gpu_layout;

Result<UpsampleCompositePass> UpsampleCompositePass::create(const Context& context) {
  const ComputeBinding bindings[] = {{kCompositeBindFrame, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER},
                                     {kCompositeBindPositionDepth, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE},
                                     {kCompositeBindNormal, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE},
                                     {kCompositeBindReceivers, VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER},
                                     {kCompositeBindShaded, VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER},
                                     {kCompositeBindIrradiance, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
                                     {kCompositeBindAlbedo, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE},
                                     {kCompositeBindEnvironment, VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER},
                                     {kCompositeBindHdr, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
                                     {kCompositeBindLdr, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
                                     {kCompositeBindDirect, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
                                     {kCompositeBindIndirect, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
                                     {kCompositeBindTileCounts, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}};
  auto pipeline = make_compute_pipeline(context, "upsample_composite.comp", bindings, sizeof(CompositePush));
  if (!pipeline) return pipeline.error();
  auto no_aov = make_compute_pipeline(context, "upsample_composite.comp:no_aov", bindings, sizeof(CompositePush));
  if (!no_aov) return no_aov.error();
  auto ldr_only = make_compute_pipeline(context, "upsample_composite.comp:ldr_only", bindings, sizeof(CompositePush));
  if (!ldr_only) return ldr_only.error();
  auto views = make_compute_pipeline(context, "upsample_composite.comp:views", bindings, sizeof(CompositePush));
  if (!views) return views.error();
  UpsampleCompositePass pass;
  pass.pipeline_ = std::move(*pipeline);
  pass.no_aov_pipeline_ = std::move(*no_aov);
  pass.ldr_only_pipeline_ = std::move(*ldr_only);
  pass.views_pipeline_ = std::move(*views);
  return pass;
}

std::vector<ResourceAccess> UpsampleCompositePass::accesses(const Inputs& in, const Outputs& out) const {
  return {reads(in.constants), reads(in.position_depth), reads(in.normal),     reads(in.albedo),
          reads(in.receivers), reads(in.shaded),         reads(in.environment), reads(in.direct),
          reads(in.indirect),  reads(in.tile_counts),   writes(out.irradiance),
          writes(out.hdr),     writes(out.ldr)};
}

void UpsampleCompositePass::record(const Context& context, VkCommandBuffer commands, const Inputs& in,
                                   const Outputs& out) const {
  const Pipeline& pipeline = in.debug_view                   ? views_pipeline_
                             : in.irradiance_aov               ? pipeline_
                             : in.hdr                          ? no_aov_pipeline_
                                                               : ldr_only_pipeline_;
  pipeline.bind(commands);
  DescriptorPush()
      .uniform_buffer(kCompositeBindFrame, *in.constants)
      .storage_image(kCompositeBindPositionDepth, in.position_depth->view())
      .storage_image(kCompositeBindNormal, in.normal->view())
      .uniform_texel_buffer(kCompositeBindReceivers, in.receivers->texel_view())
      .uniform_texel_buffer(kCompositeBindShaded, in.shaded->texel_view())
      .storage_buffer(kCompositeBindIrradiance, *out.irradiance)
      .storage_image(kCompositeBindAlbedo, in.albedo->view())
      .uniform_texel_buffer(kCompositeBindEnvironment, in.environment->texel_view())
      .storage_buffer(kCompositeBindHdr, *out.hdr)
      .storage_buffer(kCompositeBindLdr, *out.ldr)
      .storage_buffer(kCompositeBindDirect, *in.direct)
      .storage_buffer(kCompositeBindIndirect, *in.indirect)
      .storage_buffer(kCompositeBindTileCounts, *in.tile_counts)
      .push(context, commands, pipeline);
  const CompositePush push{in.environment_width, in.environment_height, in.ldr_bgra ? 1u : 0u, 0};
  pipeline.push_constants(commands, &push, sizeof(push));
  dispatch_grid(commands, in.width, in.height);
}

}  // namespace proxygi::gpu
