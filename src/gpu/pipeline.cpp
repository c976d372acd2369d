#include "gpu/pipeline.h"

#include <utility>

#include "gpu/context.h"
#include "gpu/resources.h"
#include "gpu/vulkan_check.h"
#include "shaders/embedded_shaders.h"

namespace proxygi::gpu {
namespace {

struct ShaderModule {
  VkDevice device = VK_NULL_HANDLE;
  VkShaderModule module = VK_NULL_HANDLE;
  ~ShaderModule() {
    if (module != VK_NULL_HANDLE) vkDestroyShaderModule(device, module, nullptr);
  }
};

Status create_module(const Context& context, const std::string& name, ShaderModule& out) {
  const auto words = shaders::spirv(name);
  if (words.empty()) return make_error("shader '" + name + "' is not embedded in this build");
  VkShaderModuleCreateInfo info{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
  info.codeSize = words.size_bytes();
  info.pCode = words.data();
  out.device = context.device();
  PROXYGI_VK_TRY(vkCreateShaderModule(context.device(), &info, nullptr, &out.module));
  return {};
}

VkPipelineShaderStageCreateInfo stage(VkShaderStageFlagBits which, VkShaderModule module) {
  VkPipelineShaderStageCreateInfo info{VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
  info.stage = which;
  info.module = module;
  info.pName = "main";
  return info;
}

}  // namespace

Result<PipelineLayout> PipelineLayout::create(const Context& context, std::span<const Binding> bindings,
                                              std::uint32_t push_constant_bytes) {
  PipelineLayout layout;
  layout.device_ = context.device();
  layout.push_constant_bytes_ = push_constant_bytes;
  std::vector<VkDescriptorSetLayoutBinding> vulkan_bindings;
  for (const auto& binding : bindings) {
    VkDescriptorSetLayoutBinding entry{};
    entry.binding = binding.binding;
    entry.descriptorType = binding.type;
    entry.descriptorCount = 1;
    entry.stageFlags = binding.stages;
    vulkan_bindings.push_back(entry);
  }
  VkDescriptorSetLayoutCreateInfo set_info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
  set_info.flags = VK_DESCRIPTOR_SET_LAYOUT_CREATE_PUSH_DESCRIPTOR_BIT_KHR;
  set_info.bindingCount = static_cast<std::uint32_t>(vulkan_bindings.size());
  set_info.pBindings = vulkan_bindings.data();
  PROXYGI_VK_TRY(vkCreateDescriptorSetLayout(layout.device_, &set_info, nullptr, &layout.set_layout_));

  VkPushConstantRange range{VK_SHADER_STAGE_ALL, 0, push_constant_bytes};
  VkPipelineLayoutCreateInfo info{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  info.setLayoutCount = 1;
  info.pSetLayouts = &layout.set_layout_;
  info.pushConstantRangeCount = push_constant_bytes > 0 ? 1 : 0;
  info.pPushConstantRanges = &range;
  PROXYGI_VK_TRY(vkCreatePipelineLayout(layout.device_, &info, nullptr, &layout.layout_));
  return layout;
}

void PipelineLayout::release() {
  if (device_ == VK_NULL_HANDLE) return;
  if (layout_ != VK_NULL_HANDLE) vkDestroyPipelineLayout(device_, layout_, nullptr);
  if (set_layout_ != VK_NULL_HANDLE) vkDestroyDescriptorSetLayout(device_, set_layout_, nullptr);
  device_ = VK_NULL_HANDLE;
  layout_ = VK_NULL_HANDLE;
  set_layout_ = VK_NULL_HANDLE;
}

PipelineLayout::~PipelineLayout() { release(); }
PipelineLayout::PipelineLayout(PipelineLayout&& other) noexcept { *this = std::move(other); }
PipelineLayout& PipelineLayout::operator=(PipelineLayout&& other) noexcept {
  if (this != &other) {
    release();
    device_ = std::exchange(other.device_, VK_NULL_HANDLE);
    set_layout_ = std::exchange(other.set_layout_, VK_NULL_HANDLE);
    layout_ = std::exchange(other.layout_, VK_NULL_HANDLE);
    push_constant_bytes_ = other.push_constant_bytes_;
  }
  return *this;
}

Result<Pipeline> Pipeline::compute(const Context& context, const std::string& shader, std::span<const Binding> bindings,
                                   std::uint32_t push_constant_bytes) {
  Pipeline pipeline;
  pipeline.device_ = context.device();
  pipeline.bind_point_ = VK_PIPELINE_BIND_POINT_COMPUTE;
  auto layout = PipelineLayout::create(context, bindings, push_constant_bytes);
  if (!layout) return layout.error();
  pipeline.layout_ = std::move(*layout);
  ShaderModule module;
  if (Status made = create_module(context, shader, module); !made) return made.error();
  VkComputePipelineCreateInfo info{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
  info.stage = stage(VK_SHADER_STAGE_COMPUTE_BIT, module.module);
  info.layout = pipeline.layout_.handle();
  PROXYGI_VK_TRY(vkCreateComputePipelines(pipeline.device_, VK_NULL_HANDLE, 1, &info, nullptr, &pipeline.pipeline_));
  return pipeline;
}

Result<Pipeline> Pipeline::graphics(const Context& context, const GraphicsPipelineDescription& description,
                                    std::span<const Binding> bindings, std::uint32_t push_constant_bytes) {
  Pipeline pipeline;
  pipeline.device_ = context.device();
  pipeline.bind_point_ = VK_PIPELINE_BIND_POINT_GRAPHICS;
  auto layout = PipelineLayout::create(context, bindings, push_constant_bytes);
  if (!layout) return layout.error();
  pipeline.layout_ = std::move(*layout);

  ShaderModule vertex;
  ShaderModule fragment;
  if (Status made = create_module(context, description.vertex_shader, vertex); !made) return made.error();
  if (Status made = create_module(context, description.fragment_shader, fragment); !made) return made.error();
  const VkPipelineShaderStageCreateInfo stages[] = {stage(VK_SHADER_STAGE_VERTEX_BIT, vertex.module),
                                                    stage(VK_SHADER_STAGE_FRAGMENT_BIT, fragment.module)};

  VkPipelineVertexInputStateCreateInfo vertex_input{VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
  VkPipelineInputAssemblyStateCreateInfo assembly{VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO};
  assembly.topology = description.topology;
  VkPipelineViewportStateCreateInfo viewport{VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO};
  viewport.viewportCount = 1;
  viewport.scissorCount = 1;
  VkPipelineRasterizationStateCreateInfo raster{VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO};
  raster.polygonMode = VK_POLYGON_MODE_FILL;
  raster.cullMode = description.cull;
  raster.frontFace = description.front_face;
  raster.lineWidth = 1.0f;
  VkPipelineMultisampleStateCreateInfo multisample{VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO};
  multisample.rasterizationSamples = VK_SAMPLE_COUNT_1_BIT;
  VkPipelineDepthStencilStateCreateInfo depth{VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO};
  depth.depthTestEnable = description.depth_test ? VK_TRUE : VK_FALSE;
  depth.depthWriteEnable = description.depth_write ? VK_TRUE : VK_FALSE;
  depth.depthCompareOp = description.depth_compare;

  VkPipelineColorBlendAttachmentState attachment{};
  attachment.colorWriteMask = VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT | VK_COLOR_COMPONENT_B_BIT |
                              VK_COLOR_COMPONENT_A_BIT;
  if (description.blend == BlendMode::additive) {
    attachment.blendEnable = VK_TRUE;
    attachment.srcColorBlendFactor = attachment.dstColorBlendFactor = VK_BLEND_FACTOR_ONE;
    attachment.srcAlphaBlendFactor = attachment.dstAlphaBlendFactor = VK_BLEND_FACTOR_ONE;
    attachment.colorBlendOp = attachment.alphaBlendOp = VK_BLEND_OP_ADD;
  } else if (description.blend == BlendMode::premultiplied_over) {
    attachment.blendEnable = VK_TRUE;
    attachment.srcColorBlendFactor = attachment.srcAlphaBlendFactor = VK_BLEND_FACTOR_ONE;
    attachment.dstColorBlendFactor = attachment.dstAlphaBlendFactor = VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA;
    attachment.colorBlendOp = attachment.alphaBlendOp = VK_BLEND_OP_ADD;
  }
  const std::vector<VkPipelineColorBlendAttachmentState> attachments(description.color_formats.size(), attachment);
  VkPipelineColorBlendStateCreateInfo blend{VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO};
  blend.attachmentCount = static_cast<std::uint32_t>(attachments.size());
  blend.pAttachments = attachments.data();

  const VkDynamicState dynamic_states[] = {VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR};
  VkPipelineDynamicStateCreateInfo dynamic{VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO};
  dynamic.dynamicStateCount = 2;
  dynamic.pDynamicStates = dynamic_states;

  VkPipelineRenderingCreateInfo rendering{VK_STRUCTURE_TYPE_PIPELINE_RENDERING_CREATE_INFO};
  rendering.colorAttachmentCount = static_cast<std::uint32_t>(description.color_formats.size());
  rendering.pColorAttachmentFormats = description.color_formats.data();
  rendering.depthAttachmentFormat = description.depth_format;

  VkGraphicsPipelineCreateInfo info{VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO};
  info.pNext = &rendering;
  info.stageCount = 2;
  info.pStages = stages;
  info.pVertexInputState = &vertex_input;
  info.pInputAssemblyState = &assembly;
  info.pViewportState = &viewport;
  info.pRasterizationState = &raster;
  info.pMultisampleState = &multisample;
  info.pDepthStencilState = &depth;
  info.pColorBlendState = &blend;
  info.pDynamicState = &dynamic;
  info.layout = pipeline.layout_.handle();
  PROXYGI_VK_TRY(vkCreateGraphicsPipelines(pipeline.device_, VK_NULL_HANDLE, 1, &info, nullptr, &pipeline.pipeline_));
  return pipeline;
}

void Pipeline::push_constants(VkCommandBuffer commands, const void* bytes, std::uint32_t size) const {
  vkCmdPushConstants(commands, layout_.handle(), VK_SHADER_STAGE_ALL, 0, size, bytes);
}

void Pipeline::release() {
  if (device_ != VK_NULL_HANDLE && pipeline_ != VK_NULL_HANDLE) vkDestroyPipeline(device_, pipeline_, nullptr);
  device_ = VK_NULL_HANDLE;
  pipeline_ = VK_NULL_HANDLE;
}

Pipeline::~Pipeline() { release(); }
Pipeline::Pipeline(Pipeline&& other) noexcept { *this = std::move(other); }
Pipeline& Pipeline::operator=(Pipeline&& other) noexcept {
  if (this != &other) {
    release();
    device_ = std::exchange(other.device_, VK_NULL_HANDLE);
    layout_ = std::move(other.layout_);
    pipeline_ = std::exchange(other.pipeline_, VK_NULL_HANDLE);
    bind_point_ = other.bind_point_;
  }
  return *this;
}

DescriptorPush& DescriptorPush::storage_buffer(std::uint32_t binding, const Buffer& buffer) {
  writes_.push_back({binding, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, {buffer.handle(), 0, VK_WHOLE_SIZE}, {}});
  return *this;
}

DescriptorPush& DescriptorPush::storage_buffer(std::uint32_t binding, const Buffer& buffer, const BufferRange& range) {
  writes_.push_back({binding, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, {buffer.handle(), range.offset, range.size}, {}});
  return *this;
}

DescriptorPush& DescriptorPush::uniform_buffer(std::uint32_t binding, const Buffer& buffer) {
  writes_.push_back({binding, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, {buffer.handle(), 0, VK_WHOLE_SIZE}, {}});
  return *this;
}

DescriptorPush& DescriptorPush::sampled_image(std::uint32_t binding, VkImageView view, VkSampler sampler,
                                              VkImageLayout layout) {
  writes_.push_back({binding, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, {}, {sampler, view, layout}});
  return *this;
}

DescriptorPush& DescriptorPush::storage_image(std::uint32_t binding, VkImageView view) {
  writes_.push_back({binding, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, {}, {VK_NULL_HANDLE, view, VK_IMAGE_LAYOUT_GENERAL}});
  return *this;
}

DescriptorPush& DescriptorPush::uniform_texel_buffer(std::uint32_t binding, VkBufferView view) {
  writes_.push_back({binding, VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER, {}, {}, view});
  return *this;
}

void DescriptorPush::push(const Context& context, VkCommandBuffer commands, const Pipeline& pipeline) const {
  std::vector<VkWriteDescriptorSet> vulkan_writes;
  vulkan_writes.reserve(writes_.size());
  for (const auto& write : writes_) {
    VkWriteDescriptorSet entry{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    entry.dstBinding = write.binding;
    entry.descriptorCount = 1;
    entry.descriptorType = write.type;
    const bool is_buffer =
        write.type == VK_DESCRIPTOR_TYPE_STORAGE_BUFFER || write.type == VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
    if (is_buffer) entry.pBufferInfo = &write.buffer;
    else if (write.type == VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER) entry.pTexelBufferView = &write.texel_view;
    else entry.pImageInfo = &write.image;
    vulkan_writes.push_back(entry);
  }
  context.push_descriptor_set(commands, pipeline.bind_point(), pipeline.layout(), 0,
                              static_cast<std::uint32_t>(vulkan_writes.size()), vulkan_writes.data());
}

}  // namespace proxygi::gpu
