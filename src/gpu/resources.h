#pragma once
// Buffers and 2-D images with their memory. Each resource gets its own VkDeviceMemory: proxygi
// holds a few dozen long-lived resources per frame graph, far below maxMemoryAllocationCount, so
// a sub-allocator buys nothing here. (Vulkan Memory Allocator would be the library for it, but
// Debian 12 does not package it.)
#include <cstdint>
#include <span>

#include <vulkan/vulkan.h>

#include "base/result.h"

namespace proxygi::gpu {

class Context;

enum class MemoryKind {
  device_local,  // fastest for the GPU; filled through staging
  host_visible,  // mapped, coherent: per-frame uploads (ring buffers) and readback
};

// Bytes offset .. offset + size of a buffer (VK_WHOLE_SIZE: to its end).
struct BufferRange {
  VkDeviceSize offset = 0;
  VkDeviceSize size = VK_WHOLE_SIZE;
};

class Buffer {
 public:
  static Result<Buffer> create(const Context& context, VkDeviceSize size, VkBufferUsageFlags usage, MemoryKind memory);
  Buffer() = default;
  ~Buffer();
  Buffer(Buffer&& other) noexcept;
  Buffer& operator=(Buffer&& other) noexcept;
  Buffer(const Buffer&) = delete;
  Buffer& operator=(const Buffer&) = delete;

  VkBuffer handle() const { return buffer_; }
  VkDeviceSize size() const { return size_; }
  VkBufferUsageFlags usage() const { return usage_; }  // as created (device_local adds transfer src/dst)
  // Persistently mapped pointer for host_visible buffers, nullptr otherwise.
  void* mapped() const { return mapped_; }
  bool host_visible() const { return mapped_ != nullptr; }

  // Adds a view of the whole buffer as texels of `format` (a uniform texel buffer: the buffer
  // needs VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT). Shaders on lavapipe read
  // texels with vector gathers, where a storage-buffer read is a loop over the SIMD lanes.
  // Fails when the buffer was created without that usage, or holds more texels than the
  // device's maxTexelBufferElements.
  Status add_texel_view(const Context& context, VkFormat format);
  VkBufferView texel_view() const { return texel_view_; }  // VK_NULL_HANDLE until added

 private:
  void release();
  VkDevice device_ = VK_NULL_HANDLE;
  VkBuffer buffer_ = VK_NULL_HANDLE;
  VkBufferView texel_view_ = VK_NULL_HANDLE;
  VkDeviceMemory memory_ = VK_NULL_HANDLE;
  VkDeviceSize size_ = 0;
  VkBufferUsageFlags usage_ = 0;
  void* mapped_ = nullptr;
};

// A 2-D, single-layer image in optimal tiling with one view covering all its mip levels.
class Image {
 public:
  static Result<Image> create(const Context& context, std::uint32_t width, std::uint32_t height, VkFormat format,
                              VkImageUsageFlags usage, std::uint32_t mip_levels = 1);
  Image() = default;
  ~Image();
  Image(Image&& other) noexcept;
  Image& operator=(Image&& other) noexcept;
  Image(const Image&) = delete;
  Image& operator=(const Image&) = delete;

  VkImage handle() const { return image_; }
  VkImageView view() const { return view_; }
  VkFormat format() const { return format_; }
  std::uint32_t width() const { return width_; }
  std::uint32_t height() const { return height_; }
  std::uint32_t mip_levels() const { return mip_levels_; }
  VkImageAspectFlags aspect() const;

 private:
  void release();
  VkDevice device_ = VK_NULL_HANDLE;
  VkImage image_ = VK_NULL_HANDLE;
  VkImageView view_ = VK_NULL_HANDLE;
  VkDeviceMemory memory_ = VK_NULL_HANDLE;
  VkFormat format_ = VK_FORMAT_UNDEFINED;
  std::uint32_t width_ = 0;
  std::uint32_t height_ = 0;
  std::uint32_t mip_levels_ = 1;
};

// Bytes per texel of the formats proxygi reads back.
Result<std::uint32_t> texel_size(VkFormat format);

}  // namespace proxygi::gpu
