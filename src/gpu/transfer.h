#pragma once
// Moving bytes between host and GPU resources. Each call is synchronous (one fenced submit):
// meant for set-up, tests and readback of finished frames, not for per-frame streaming (that
// goes through host-visible ring buffers).
#include <cstdint>
#include <span>
#include <vector>

#include <vulkan/vulkan.h>

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

template <class T>
std::span<const std::uint8_t> as_bytes(std::span<const T> values) {
  return {reinterpret_cast<const std::uint8_t*>(values.data()), values.size_bytes()};
}

}  // namespace proxygi::gpu
