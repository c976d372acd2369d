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
  gbuffer.color_formats = {kGbufferFormat, kGbufferFormat, kGbufferFormat};
  gbuffer.depth_format = kDepthFormat;
  gbuffer.depth_test = gbuffer.depth_write = true;
  const Binding gbuffer_bindings[] = {{0, kUniform, VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT},
                                      {1, kStorage, VK_SHADER_STAGE_VERTEX_BIT},
                                      {2, kStorage, VK_SHADER_STAGE_VERTEX_BIT},
                                      {4, kStorage, VK_SHADER_STAGE_VERTEX_BIT},  // uvs
                                      {5, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_SHADER_STAGE_FRAGMENT_BIT},
                                      {3, kStorage, VK_SHADER_STAGE_VERTEX_BIT}};  // vertex irradiance
  // Variant (vertex irradiance or not) × (textured or not): shader names and binding lists.
  const bool vertex_method = method == ShadingMethod::vertex;
  for (int variant = 0; variant < (vertex_method ? 4 : 2); ++variant) {
    const bool textured = variant % 2 == 1;
    const bool vertex = variant >= 2;
    gbuffer.vertex_shader = vertex ? "gbuffer.vert:vertex_irradiance" : "gbuffer.vert";
    gbuffer.fragment_shader = std::string("gbuffer.frag") +
                              (vertex ? (textured ? ":vertex_irradiance_textured" : ":vertex_irradiance")
                                      : (textured ? ":textured" : ""));
    std::vector<Binding> bindings(gbuffer_bindings, gbuffer_bindings + 4);
    if (textured) bindings.push_back(gbuffer_bindings[4]);
    if (vertex) bindings.push_back(gbuffer_bindings[5]);
    auto made = Pipeline::graphics(context, gbuffer, bindings, sizeof(gpu_layout::GbufferPush));
    if (!made) return make_error(gbuffer.fragment_shader + ": " + made.message());
    Pipeline* targets[] = {&out.gbuffer, &out.gbuffer_textured, &out.vertex_gbuffer, &out.vertex_gbuffer_textured};
    *targets[variant] = std::move(*made);
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
