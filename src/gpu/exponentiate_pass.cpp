#include "gpu/exponentiate_pass.h"

#include "shaders/shared/layouts.h"
#include "sh/exponential.h"

namespace proxygi::gpu {

using namespace gpu_layout;

static_assert(kHybridBlendStart == sh::kHybridBlendStart, "HYB's blend start is defined in sh/exponential.h");

Result<ExponentiatePass> ExponentiatePass::create(const Context& context, int order, settings::StaticTransfer level) {
  const bool static_transfer = level != settings::StaticTransfer::l0;
  const ComputeBinding bindings[] = {{kExponentiateBindFrame, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER},
                                     {kExponentiateBindReceivers, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
                                     {kExponentiateBindLogOcclusion, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
                                     {kExponentiateBindOptimalLinear, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
                                     {kExponentiateBindLightingCube, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
                                     {kExponentiateBindDirect, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
                                     {kExponentiateBindStaticPositions, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
                                     {kExponentiateBindStaticTriangles, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
                                     {kExponentiateBindStaticGrid, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
                                     {kExponentiateBindStaticRecords, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
                                     {kExponentiateBindStaticVisibility, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}};
  std::string shader = order_variant("exponentiate.comp", order);
  if (static_transfer) shader.append(":").append(settings::name_of(level));
  auto pipeline = make_compute_pipeline(context, shader, std::span(bindings).first(static_transfer ? 11 : 6));
  if (!pipeline) return pipeline.error();
  ExponentiatePass pass;
  pass.pipeline_ = std::move(*pipeline);
  pass.static_transfer_ = static_transfer;
  return pass;
}

std::vector<ResourceAccess> ExponentiatePass::accesses(const Inputs& in, const Outputs& out) const {
  std::vector<ResourceAccess> out_accesses = {reads(in.constants),      reads(in.receivers),     reads(in.log_occlusion),
                                              reads(in.optimal_linear), reads(in.lighting_cube), writes(out.direct)};
  if (static_transfer_)
    for (const Buffer* b : {in.static_positions, in.static_triangles, in.static_grid, in.static_records, in.static_visibility})
      out_accesses.push_back(reads(b));
  return out_accesses;
}

void ExponentiatePass::record(const Context& context, VkCommandBuffer commands, const Inputs& in,
                              const Outputs& out) const {
  pipeline_.bind(commands);
  DescriptorPush push;
  push.uniform_buffer(kExponentiateBindFrame, *in.constants)
      .storage_buffer(kExponentiateBindReceivers, *in.receivers)
      .storage_buffer(kExponentiateBindLogOcclusion, *in.log_occlusion)
      .storage_buffer(kExponentiateBindOptimalLinear, *in.optimal_linear)
      .storage_buffer(kExponentiateBindLightingCube, *in.lighting_cube)
      .storage_buffer(kExponentiateBindDirect, *out.direct);
  if (static_transfer_)
    push.storage_buffer(kExponentiateBindStaticPositions, *in.static_positions)
        .storage_buffer(kExponentiateBindStaticTriangles, *in.static_triangles)
        .storage_buffer(kExponentiateBindStaticGrid, *in.static_grid)
        .storage_buffer(kExponentiateBindStaticRecords, *in.static_records)
        .storage_buffer(kExponentiateBindStaticVisibility, *in.static_visibility);
  push.push(context, commands, pipeline_);
  dispatch_grid(commands, in.receiver_width, in.receiver_height);
}

}  // namespace proxygi::gpu
