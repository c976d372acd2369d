#include "gpu/gbuffer_pass.h"

#include <vector>

#include "gpu/context.h"
#include "gpu/frame_config.h"
#include "gpu/transfer.h"
#include "shaders/shared/layouts.h"

namespace proxygi::gpu {

using namespace gpu_layout;

namespace {

constexpr VkPipelineStageFlags2 kVertexStage = VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT;
constexpr VkPipelineStageFlags2 kColorStage = VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT;


}  // namespace

Result<GbufferPass> GbufferPass::create(const Context& context, bool vertex_irradiance) {
  GraphicsPipelineDescription description;
  description.color_formats = {kGbufferFormat, kGbufferFormat, kGbufferFormat};
  description.depth_format = kDepthFormat;
  description.depth_test = description.depth_write = true;
  description.vertex_shader = vertex_irradiance ? "gbuffer.vert:vertex_irradiance" : "gbuffer.vert";
  GbufferPass pass;
  pass.vertex_irradiance_ = vertex_irradiance;
  for (const bool textured : {false, true}) {
    std::vector<Binding> bindings = {
        {kGbufferBindFrame, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT},
        {kGbufferBindPositions, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_VERTEX_BIT},
        {kGbufferBindNormals, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_VERTEX_BIT},
        {kGbufferBindUvs, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_VERTEX_BIT}};
    if (textured)
      bindings.push_back(
          {kGbufferBindBaseColorTexture, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_SHADER_STAGE_FRAGMENT_BIT});
    if (vertex_irradiance)
      bindings.push_back({kGbufferBindShaded, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_VERTEX_BIT});
    description.fragment_shader = std::string("gbuffer.frag") +
                                  (vertex_irradiance ? (textured ? ":vertex_irradiance_textured" : ":vertex_irradiance")
                                                     : (textured ? ":textured" : ""));
    auto made = Pipeline::graphics(context, description, bindings, sizeof(GbufferPush));
    if (!made) return make_error(description.fragment_shader + ": " + made.message());
    (textured ? pass.textured_ : pass.untextured_) = std::move(*made);
  }
  return pass;
}

std::vector<ResourceAccess> GbufferPass::accesses(const Inputs& in, const Outputs& out) const {
  std::vector<ResourceAccess> list = {
      reads(in.constants, kVertexStage | VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT),
      writes(out.position_depth, kColorStage), writes(out.normal, kColorStage), writes(out.albedo, kColorStage),
      writes(out.depth, VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT)};
  if (vertex_irradiance_) list.push_back(reads(in.shaded, kVertexStage));
  for (const DrawItem& draw : in.draws) {
    list.push_back(reads(draw.positions, kVertexStage));
    list.push_back(reads(draw.normals, kVertexStage));
    if (draw.uvs) list.push_back(reads(draw.uvs, kVertexStage));
  }
  return list;
}

void GbufferPass::record(const Context& context, VkCommandBuffer commands, const Inputs& in, const Outputs& out) const {
  const Image* colors[] = {out.position_depth, out.normal, out.albedo};
  begin_cleared_rendering(commands, colors, *out.depth, in.width, in.height);

  // Each draw's first receiver (vertex method) follows the draws' order, whatever order they
  // are recorded in.
  std::vector<std::uint32_t> first_receiver(in.draws.size());
  std::uint32_t receiver_offset = 0;
  std::size_t shaded_draws = in.draws.size();
  for (std::size_t i = 0; i < in.draws.size(); ++i) {
    first_receiver[i] = receiver_offset;
    receiver_offset += round_up_to_receiver_group(in.draws[i].vertex_count());
    if (vertex_irradiance_ && receiver_offset > in.receiver_capacity) {  // beyond the capacity: not drawn
      shaded_draws = i;
      break;
    }
  }
  for (const bool textured : {false, true}) {
    const Pipeline& pipeline = textured ? textured_ : untextured_;
    bool bound = false;
    for (std::size_t i = 0; i < shaded_draws; ++i) {
      const DrawItem& draw = in.draws[i];
      if (draw.textured() != textured) continue;
      if (!bound) pipeline.bind(commands);
      bound = true;
      DescriptorPush descriptors;
      descriptors.uniform_buffer(kGbufferBindFrame, *in.constants)
          .storage_buffer(kGbufferBindPositions, *draw.positions, draw.vertex_bytes())
          .storage_buffer(kGbufferBindNormals, *draw.normals, draw.vertex_bytes())
          .storage_buffer(kGbufferBindUvs, draw.uvs ? *draw.uvs : *draw.positions);  // not read without uvs
      if (textured) descriptors.sampled_image(kGbufferBindBaseColorTexture, draw.texture.view, draw.texture.sampler);
      if (vertex_irradiance_) descriptors.storage_buffer(kGbufferBindShaded, *in.shaded);
      descriptors.push(context, commands, pipeline);
      GbufferPush push{};
      push.base_color = draw.base_color;
      push.receiver_offset = first_receiver[i];
      const glm::mat3& m = draw.texture.uv_transform;  // column-major: m[column][row]
      push.uv_transform_u = glm::vec4(m[0][0], m[1][0], m[2][0], 0.0f);
      push.uv_transform_v = glm::vec4(m[0][1], m[1][1], m[2][1], 0.0f);
      push.has_uvs = draw.uvs ? 1u : 0u;
      pipeline.push_constants(commands, &push, sizeof(push));
      vkCmdBindIndexBuffer(commands, draw.indices->handle(), 0, VK_INDEX_TYPE_UINT32);
      vkCmdDrawIndexed(commands, draw.index_count, 1, 0, 0, 0);
    }
  }
  vkCmdEndRendering(commands);
  for (const Image* image : colors)
    transition(commands, *image, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_IMAGE_LAYOUT_GENERAL);
}

}  // namespace proxygi::gpu
