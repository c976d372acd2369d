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

std::span<const FramePass> frame_pass_order(ShadingMethod method) {
  static constexpr FramePass kImageSpace[] = {FramePass::gbuffer, FramePass::receivers, FramePass::shadow,
                                              FramePass::exponentiate, FramePass::indirect,
                                              FramePass::upsample_composite};
  // The G-buffer pass interpolates the vertex irradiance, so it follows the shading passes.
  static constexpr FramePass kVertex[] = {FramePass::receivers, FramePass::shadow, FramePass::exponentiate,
                                          FramePass::indirect, FramePass::gbuffer, FramePass::upsample_composite};
  static constexpr FramePass kAmbientOcclusion[] = {FramePass::gbuffer, FramePass::receivers, FramePass::shadow,
                                                    FramePass::upsample_composite};
  switch (method) {
    case ShadingMethod::vertex: return kVertex;
    case ShadingMethod::ambient_occlusion: return kAmbientOcclusion;
    case ShadingMethod::image_space: break;
  }
  return kImageSpace;
}

Result<FramePipelines> FramePipelines::create(const Context& context, int order,
                                              render::IndirectOperator indirect_operator, ShadingMethod method) {
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
                                      {2, kStorage, VK_SHADER_STAGE_VERTEX_BIT},
                                      {4, kStorage, VK_SHADER_STAGE_VERTEX_BIT},  // uvs
                                      {5, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_SHADER_STAGE_FRAGMENT_BIT}};
  auto made = Pipeline::graphics(context, gbuffer, gbuffer_bindings, sizeof(gpu_layout::GbufferPush));
  if (!made) return made.error();
  out.gbuffer = std::move(*made);
  if (method == ShadingMethod::vertex) {
    gbuffer.vertex_shader = "gbuffer.vert:vertex_irradiance";
    gbuffer.fragment_shader = "gbuffer.frag:vertex_irradiance";
    const Binding vertex_bindings[] = {gbuffer_bindings[0], gbuffer_bindings[1], gbuffer_bindings[2],
                                       gbuffer_bindings[3], gbuffer_bindings[4], {3, kStorage, VK_SHADER_STAGE_VERTEX_BIT}};
    auto vertex = Pipeline::graphics(context, gbuffer, vertex_bindings, sizeof(gpu_layout::GbufferPush));
    if (!vertex) return make_error("gbuffer (vertex irradiance): " + vertex.message());
    out.vertex_gbuffer = std::move(*vertex);
  }

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
  std::vector<ComputeSpec> baselines;
  if (method == ShadingMethod::vertex)
    baselines.push_back({&out.vertex_receivers, "vertex_receivers.comp", {kStorage, kStorage, kStorage},
                         sizeof(gpu_layout::VertexReceiversPush)});
  if (method == ShadingMethod::ambient_occlusion)
    baselines.push_back({&out.ambient_occlusion, "ambient_occlusion.comp" + suffix,
                         {kUniform, kStorage, kUniform, kStorage, kStorage, kStorage, kStorage}, 0});
  for (const auto& spec : baselines) {
    auto pipeline = compute(context, spec.shader, spec.types, spec.push_bytes);
    if (!pipeline) return make_error(spec.shader + ": " + pipeline.message());
    *spec.target = std::move(*pipeline);
  }
  for (const auto& spec : specs) {
    auto pipeline = compute(context, spec.shader, spec.types, spec.push_bytes);
    if (!pipeline) return make_error(spec.shader + ": " + pipeline.message());
    *spec.target = std::move(*pipeline);
  }
  return out;
}

}  // namespace proxygi::gpu
