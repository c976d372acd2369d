#include "gpu/frame_passes.h"

#include <string>
#include <vector>

#include "shaders/shared/layouts.h"

namespace proxygi::gpu {
namespace {

constexpr VkDescriptorType kUniform = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
constexpr VkDescriptorType kStorage = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
constexpr VkDescriptorType kImage = VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;

Result<Pipeline> compute(const Context& context, const std::string& shader, std::vector<VkDescriptorType> types,
                         std::uint32_t push_bytes = 0) {
  std::vector<Binding> bindings;
  for (std::uint32_t i = 0; i < types.size(); ++i) bindings.push_back({i, types[i], VK_SHADER_STAGE_COMPUTE_BIT});
  return Pipeline::compute(context, shader, bindings, push_bytes);
}

}  // namespace

const char* frame_pass_name(FramePass pass) {
  switch (pass) {
    case FramePass::skin: return "skin";
    case FramePass::gbuffer: return "gbuffer";
    case FramePass::receivers: return "receivers";
    case FramePass::shadow: return "shadow";
    case FramePass::exponentiate: return "exponentiate";
    case FramePass::indirect: return "indirect";
    case FramePass::upsample_composite: return "upsample+composite";
    case FramePass::count: break;
  }
  return "unknown";
}

Result<FramePipelines> FramePipelines::create(const Context& context, int order,
                                              render::IndirectOperator indirect_operator) {
  if (order < 3 || order > 6) return make_error("frame: SH order " + std::to_string(order) + " is not in 3..6");
  const std::string suffix = ":order" + std::to_string(order);
  FramePipelines out;

  GraphicsPipelineDescription gbuffer;
  gbuffer.vertex_shader = "gbuffer.vert";
  gbuffer.fragment_shader = "gbuffer.frag";
  gbuffer.color_formats = {kGbufferFormat, kGbufferFormat, kGbufferFormat};
  gbuffer.depth_format = kDepthFormat;
  gbuffer.depth_test = gbuffer.depth_write = true;
  const Binding gbuffer_bindings[] = {{0, kUniform, VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT},
                                      {1, kStorage, VK_SHADER_STAGE_VERTEX_BIT},
                                      {2, kStorage, VK_SHADER_STAGE_VERTEX_BIT}};
  auto made = Pipeline::graphics(context, gbuffer, gbuffer_bindings, sizeof(gpu_layout::GbufferPush));
  if (!made) return made.error();
  out.gbuffer = std::move(*made);

  struct ComputeSpec {
    Pipeline* target;
    std::string shader;
    std::vector<VkDescriptorType> types;
    std::uint32_t push_bytes;
  };
  const ComputeSpec specs[] = {
      {&out.receivers, "receivers.comp", {kUniform, kImage, kImage, kStorage}, 0},
      {&out.shadow, "shadow_gather.comp" + suffix, {kUniform, kStorage, kUniform, kStorage, kStorage}, 0},
      {&out.exponentiate, "exponentiate.comp" + suffix, {kUniform, kStorage, kStorage, kStorage, kStorage, kStorage}, 0},
      {&out.indirect, std::string("indirect.comp:") + render::indirect_operator_name(indirect_operator),
       {kUniform, kStorage, kUniform, kStorage, kStorage, kStorage, kStorage, kStorage}, 0},
      {&out.upsample_composite, "upsample_composite.comp",
       {kUniform, kImage, kImage, kStorage, kStorage, kStorage, kImage, kStorage, kStorage, kStorage},
       sizeof(gpu_layout::CompositePush)},
  };
  for (const auto& spec : specs) {
    auto pipeline = compute(context, spec.shader, spec.types, spec.push_bytes);
    if (!pipeline) return make_error(spec.shader + ": " + pipeline.message());
    *spec.target = std::move(*pipeline);
  }
  return out;
}

}  // namespace proxygi::gpu
