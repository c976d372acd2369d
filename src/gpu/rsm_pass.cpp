#include "gpu/rsm_pass.h"

#include <algorithm>

#include "gpu/context.h"
#include "gpu/transfer.h"
#include "gpu/vsgl_lights_pass.h"
#include "shaders/shared/layouts.h"

namespace proxygi::gpu {

using namespace gpu_layout;

namespace {
constexpr VkPipelineStageFlags2 kVertexStage = VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT;
constexpr VkPipelineStageFlags2 kColorStage = VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT;
}  // namespace

std::uint32_t RsmPass::partial_count(std::span<const DrawItem> draws, std::uint32_t lights_per_sender) {
  return std::min(vsgl_light_count(draws, lights_per_sender) * kRsmGroupsPerLight, kVsglMaxPartials);
}

Result<RsmPass> RsmPass::create(const Context& context) {
  GraphicsPipelineDescription description;
  description.color_formats = {kGbufferFormat, kGbufferFormat, kGbufferFormat};
  description.depth_format = kDepthFormat;
  description.depth_test = description.depth_write = true;
  description.vertex_shader = "rsm.vert";
  description.fragment_shader = "rsm.frag";
  const Binding bindings[] = {
      {kRsmBindFrame, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT},
      {kRsmBindPositions, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_VERTEX_BIT},
      {kRsmBindNormals, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_VERTEX_BIT}};
  auto raster = Pipeline::graphics(context, description, bindings, sizeof(RsmPush));
  if (!raster) return make_error("rsm.frag: " + raster.message());
  const ComputeBinding sum_bindings[] = {{kRsmSumsBindFrame, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER},
                                         {kRsmSumsBindPosition, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE},
                                         {kRsmSumsBindNormal, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE},
                                         {kRsmSumsBindFlux, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE},
                                         {kRsmSumsBindPartials, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}};
  auto sums = make_compute_pipeline(context, "rsm_sums.comp", sum_bindings, sizeof(RsmSumsPush));
  if (!sums) return sums.error();
  RsmPass pass;
  pass.raster_ = std::move(*raster);
  pass.sums_ = std::move(*sums);
  return pass;
}

std::vector<ResourceAccess> RsmPass::accesses(const Inputs& in, const Outputs& out) const {
  std::vector<ResourceAccess> list = {
      reads(in.constants, kVertexStage | VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT),
      writes(out.position, kColorStage), writes(out.normal, kColorStage), writes(out.flux, kColorStage),
      writes(out.depth, VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT),
      writes(out.partials)};
  for (const DrawItem& draw : in.draws) {
    if (draw.vsgl_light < 0) continue;
    list.push_back(reads(draw.positions, kVertexStage));
    list.push_back(reads(draw.normals, kVertexStage));
  }
  return list;
}

void RsmPass::record(const Context& context, VkCommandBuffer commands, const Inputs& in, const Outputs& out) const {
  const Image* colors[] = {out.position, out.normal, out.flux};  // position.w 0: no sender
  begin_cleared_rendering(commands, colors, *out.depth, kRsmSize, kRsmSize);
  raster_.bind(commands);
  const auto ranges = vsgl_light_ranges(in.draws, in.lights_per_sender);
  for (const VsglLightRange& range : ranges) {
    if (range.last <= range.first) continue;
    const DrawItem& draw = in.draws[range.draw];
    DescriptorPush()
        .uniform_buffer(kRsmBindFrame, *in.constants)
        .storage_buffer(kRsmBindPositions, *draw.positions, draw.vertex_bytes())
        .storage_buffer(kRsmBindNormals, *draw.normals, draw.vertex_bytes())
        .push(context, commands, raster_);
    RsmPush push{};
    push.base_color = draw.base_color;
    push.light = range.light;
    raster_.push_constants(commands, &push, sizeof(push));
    vkCmdBindIndexBuffer(commands, range.indices->handle(), 0, VK_INDEX_TYPE_UINT32);
    vkCmdDrawIndexed(commands, 3 * (range.last - range.first), 1, 3 * range.first, 0, 0);
  }
  vkCmdEndRendering(commands);
  for (const Image* image : colors)  // a full barrier: the attachments' writes, then the sums' reads
    transition(commands, *image, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_IMAGE_LAYOUT_GENERAL);

  sums_.bind(commands);
  const std::uint32_t lights = vsgl_light_count(in.draws, in.lights_per_sender);
  for (std::uint32_t light = 0; light < lights; ++light) {
    const std::uint32_t offset = light * kRsmGroupsPerLight;
    if (offset + kRsmGroupsPerLight > kVsglMaxPartials) break;  // (kVsglMaxLights × 16 fits)
    DescriptorPush()
        .uniform_buffer(kRsmSumsBindFrame, *in.constants)
        .storage_image(kRsmSumsBindPosition, out.position->view())
        .storage_image(kRsmSumsBindNormal, out.normal->view())
        .storage_image(kRsmSumsBindFlux, out.flux->view())
        .storage_buffer(kRsmSumsBindPartials, *out.partials)
        .push(context, commands, sums_);
    RsmSumsPush push{};
    push.light = light;
    push.partial_offset = offset;
    sums_.push_constants(commands, &push, sizeof(push));
    vkCmdDispatch(commands, kRsmGroupsPerLight, 1, 1);
  }
}

}  // namespace proxygi::gpu
