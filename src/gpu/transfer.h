#pragma once
// Moving bytes between host and GPU resources. Each call is synchronous (one fenced submit):
// meant for set-up, tests and readback of finished frames, not for per-frame streaming (that
// goes through host-visible ring buffers).
#include <vulkan/vulkan.h>

#include <cstdint>
#include <span>
#include <vector>

#include "base/result.h"
#include "gpu/resources.h"

namespace proxygi::gpu {

class Context;

// Writes bytes at the start of `destination` (through a staging buffer unless host-visible).
Status upload(Context& context, const Buffer& destination, std::span<const std::uint8_t> bytes);

// Makes a device-local buffer with `usage` holding `bytes`.
Result<Buffer> create_buffer_with_data(Context& context, std::span<const std::uint8_t> bytes, VkBufferUsageFlags usage);

// Reads the whole buffer.
Result<std::vector<std::uint8_t>> readback(Context& context, const Buffer& source);

// Reads an image that is in `layout` now (and is left in it), tightly packed rows, top row first.
// The image needs VK_IMAGE_USAGE_TRANSFER_SRC_BIT.
Result<std::vector<std::uint8_t>> readback(Context& context, const Image& source, VkImageLayout layout);

// A full memory barrier: every earlier command's writes (on this queue, in submission order)
// become visible to every later command. The frame uses it between passes: simple and correct
// everywhere, and on lavapipe it costs nothing measurable.
void memory_barrier(VkCommandBuffer commands);

// Records a layout transition of a whole image with a full (conservative) barrier.
void transition(VkCommandBuffer commands, const Image& image, VkImageLayout from, VkImageLayout to);

// The scopes of an image barrier; the defaults are the full barrier transition() records.
struct BarrierScopes {
  VkPipelineStageFlags2 src_stages = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
  VkAccessFlags2 src_access = VK_ACCESS_2_MEMORY_WRITE_BIT;
  VkPipelineStageFlags2 dst_stages = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
  VkAccessFlags2 dst_access = VK_ACCESS_2_MEMORY_READ_BIT | VK_ACCESS_2_MEMORY_WRITE_BIT;
};
// A layout transition of an image the caller owns (a swapchain image: no gpu::Image), colour
// aspect, `mip_levels` levels from 0, one layer.
void transition(VkCommandBuffer commands, VkImage image, VkImageLayout from, VkImageLayout to,
                const BarrierScopes& scopes = {}, VkImageAspectFlags aspect = VK_IMAGE_ASPECT_COLOR_BIT,
                std::uint32_t mip_levels = 1);

template <class T>
std::span<const std::uint8_t> as_bytes(std::span<const T> values) {
  return {reinterpret_cast<const std::uint8_t*>(values.data()), values.size_bytes()};
}

}  // namespace proxygi::gpu
