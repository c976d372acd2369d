#pragma once
// Pipelines built from embedded SPIR-V (shaders/embedded_shaders.h) with one push-descriptor set
// (set 0) and an optional push-constant block. Graphics pipelines use dynamic rendering and no
// vertex input: vertex shaders pull their data from storage buffers with gl_VertexIndex.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "base/result.h"
#include "gpu/resources.h"

namespace proxygi::gpu {

class Context;
class Buffer;

struct Binding {
  std::uint32_t binding = 0;
  VkDescriptorType type = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
  VkShaderStageFlags stages = VK_SHADER_STAGE_ALL;
};

// The layout half shared by compute and graphics pipelines.
class PipelineLayout {
 public:
  static Result<PipelineLayout> create(const Context& context, std::span<const Binding> bindings,
                                       std::uint32_t push_constant_bytes);
  PipelineLayout() = default;
  ~PipelineLayout();
  PipelineLayout(PipelineLayout&& other) noexcept;
  PipelineLayout& operator=(PipelineLayout&& other) noexcept;
  PipelineLayout(const PipelineLayout&) = delete;
  PipelineLayout& operator=(const PipelineLayout&) = delete;

  VkPipelineLayout handle() const { return layout_; }
  std::uint32_t push_constant_bytes() const { return push_constant_bytes_; }

 private:
  void release();
  VkDevice device_ = VK_NULL_HANDLE;
  VkDescriptorSetLayout set_layout_ = VK_NULL_HANDLE;
  VkPipelineLayout layout_ = VK_NULL_HANDLE;
  std::uint32_t push_constant_bytes_ = 0;
};

// additive: dst = src + dst on color and alpha; premultiplied_over: dst = src + (1 − src.a) · dst
// on color and alpha (a premultiplied layer over what is there).
enum class BlendMode { none, additive, premultiplied_over };

struct GraphicsPipelineDescription {
  std::string vertex_shader;    // embedded shader file name, e.g. "gbuffer.vert"
  std::string fragment_shader;  // e.g. "gbuffer.frag"
  std::vector<VkFormat> color_formats;
  VkFormat depth_format = VK_FORMAT_UNDEFINED;
  bool depth_test = false;
  bool depth_write = false;
  VkCompareOp depth_compare = VK_COMPARE_OP_LESS;
  BlendMode blend = BlendMode::none;
  VkCullModeFlags cull = VK_CULL_MODE_NONE;
  VkFrontFace front_face = VK_FRONT_FACE_COUNTER_CLOCKWISE;
  VkPrimitiveTopology topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
};

// A compute or graphics pipeline with its layout. Viewport and scissor are dynamic state.
class Pipeline {
 public:
  static Result<Pipeline> compute(const Context& context, const std::string& shader, std::span<const Binding> bindings,
                                  std::uint32_t push_constant_bytes);
  static Result<Pipeline> graphics(const Context& context, const GraphicsPipelineDescription& description,
                                   std::span<const Binding> bindings, std::uint32_t push_constant_bytes);
  Pipeline() = default;
  ~Pipeline();
  Pipeline(Pipeline&& other) noexcept;
  Pipeline& operator=(Pipeline&& other) noexcept;
  Pipeline(const Pipeline&) = delete;
  Pipeline& operator=(const Pipeline&) = delete;

  VkPipeline handle() const { return pipeline_; }
  VkPipelineLayout layout() const { return layout_.handle(); }
  VkPipelineBindPoint bind_point() const { return bind_point_; }

  void bind(VkCommandBuffer commands) const { vkCmdBindPipeline(commands, bind_point_, pipeline_); }
  // Pushes `bytes` (must equal the declared push-constant size) to all stages.
  void push_constants(VkCommandBuffer commands, const void* bytes, std::uint32_t size) const;

 private:
  void release();
  VkDevice device_ = VK_NULL_HANDLE;
  PipelineLayout layout_;
  VkPipeline pipeline_ = VK_NULL_HANDLE;
  VkPipelineBindPoint bind_point_ = VK_PIPELINE_BIND_POINT_COMPUTE;
};

// Collects descriptor writes for set 0 and pushes them (VK_KHR_push_descriptor).
class DescriptorPush {
 public:
  DescriptorPush& storage_buffer(std::uint32_t binding, const Buffer& buffer);
  // Bytes range.offset .. + range.size of the buffer (offset: a multiple of the device's
  // minStorageBufferOffsetAlignment).
  DescriptorPush& storage_buffer(std::uint32_t binding, const Buffer& buffer, const BufferRange& range);
  DescriptorPush& uniform_buffer(std::uint32_t binding, const Buffer& buffer);
  DescriptorPush& sampled_image(std::uint32_t binding, VkImageView view, VkSampler sampler,
                                VkImageLayout layout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
  DescriptorPush& storage_image(std::uint32_t binding, VkImageView view);
  DescriptorPush& uniform_texel_buffer(std::uint32_t binding, VkBufferView view);  // Buffer::texel_view()
  void push(const Context& context, VkCommandBuffer commands, const Pipeline& pipeline) const;

 private:
  struct Write {
    std::uint32_t binding;
    VkDescriptorType type;
    VkDescriptorBufferInfo buffer;
    VkDescriptorImageInfo image;
    VkBufferView texel_view = VK_NULL_HANDLE;
  };
  std::vector<Write> writes_;
};

// Workgroup count for `items` invocations in groups of `group_size`.
inline std::uint32_t group_count(std::uint32_t items, std::uint32_t group_size) {
  return (items + group_size - 1) / group_size;
}

}  // namespace proxygi::gpu
