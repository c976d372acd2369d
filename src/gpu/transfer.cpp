#include "gpu/transfer.h"

#include <cstring>

#include "gpu/context.h"

namespace proxygi::gpu {

void memory_barrier(VkCommandBuffer commands) {
  VkMemoryBarrier2 barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER_2};
  barrier.srcStageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
  barrier.srcAccessMask = VK_ACCESS_2_MEMORY_WRITE_BIT;
  barrier.dstStageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
  barrier.dstAccessMask = VK_ACCESS_2_MEMORY_READ_BIT | VK_ACCESS_2_MEMORY_WRITE_BIT;
  VkDependencyInfo dependency{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
  dependency.memoryBarrierCount = 1;
  dependency.pMemoryBarriers = &barrier;
  vkCmdPipelineBarrier2(commands, &dependency);
}

void transition(VkCommandBuffer commands, VkImage image, VkImageLayout from, VkImageLayout to,
                const BarrierScopes& scopes, VkImageAspectFlags aspect, std::uint32_t mip_levels) {
  VkImageMemoryBarrier2 barrier{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2};
  barrier.srcStageMask = scopes.src_stages;
  barrier.srcAccessMask = scopes.src_access;
  barrier.dstStageMask = scopes.dst_stages;
  barrier.dstAccessMask = scopes.dst_access;
  barrier.oldLayout = from;
  barrier.newLayout = to;
  barrier.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  barrier.image = image;
  barrier.subresourceRange = {aspect, 0, mip_levels, 0, 1};
  VkDependencyInfo dependency{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
  dependency.imageMemoryBarrierCount = 1;
  dependency.pImageMemoryBarriers = &barrier;
  vkCmdPipelineBarrier2(commands, &dependency);
}

void transition(VkCommandBuffer commands, const Image& image, VkImageLayout from, VkImageLayout to) {
  transition(commands, image.handle(), from, to, {}, image.aspect(), image.mip_levels());
}

Status upload(Context& context, const Buffer& destination, std::span<const std::uint8_t> bytes) {
  if (bytes.size() > destination.size())
    return make_error("gpu upload: " + std::to_string(bytes.size()) + " bytes into a buffer of " +
                      std::to_string(destination.size()));
  if (bytes.empty()) return {};
  if (destination.host_visible()) {
    std::memcpy(destination.mapped(), bytes.data(), bytes.size());
    return {};
  }
  auto staging = Buffer::create(context, bytes.size(), VK_BUFFER_USAGE_TRANSFER_SRC_BIT, MemoryKind::host_visible);
  if (!staging) return staging.error();
  std::memcpy(staging->mapped(), bytes.data(), bytes.size());
  return context.submit_and_wait([&](VkCommandBuffer commands) {
    const VkBufferCopy region{0, 0, bytes.size()};
    vkCmdCopyBuffer(commands, staging->handle(), destination.handle(), 1, &region);
  });
}

Result<Buffer> create_buffer_with_data(Context& context, std::span<const std::uint8_t> bytes,
                                       VkBufferUsageFlags usage) {
  auto buffer = Buffer::create(context, bytes.size(), usage, MemoryKind::device_local);
  if (!buffer) return buffer.error();
  Status uploaded = upload(context, *buffer, bytes);
  if (!uploaded) return uploaded.error();
  return std::move(*buffer);
}

Result<std::vector<std::uint8_t>> readback(Context& context, const Buffer& source) {
  std::vector<std::uint8_t> bytes(source.size());
  if (source.host_visible()) {
    std::memcpy(bytes.data(), source.mapped(), bytes.size());
    return bytes;
  }
  auto staging = Buffer::create(context, source.size(), VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryKind::host_visible);
  if (!staging) return staging.error();
  Status copied = context.submit_and_wait([&](VkCommandBuffer commands) {
    const VkBufferCopy region{0, 0, source.size()};
    vkCmdCopyBuffer(commands, source.handle(), staging->handle(), 1, &region);
  });
  if (!copied) return copied.error();
  std::memcpy(bytes.data(), staging->mapped(), bytes.size());
  return bytes;
}

Result<std::vector<std::uint8_t>> readback(Context& context, const Image& source, VkImageLayout layout) {
  auto texel = texel_size(source.format());
  if (!texel) return texel.error();
  const VkDeviceSize size = VkDeviceSize(*texel) * source.width() * source.height();
  auto staging = Buffer::create(context, size, VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryKind::host_visible);
  if (!staging) return staging.error();
  Status copied = context.submit_and_wait([&](VkCommandBuffer commands) {
    transition(commands, source, layout, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);
    VkBufferImageCopy region{};
    region.imageSubresource = {source.aspect(), 0, 0, 1};
    region.imageExtent = {source.width(), source.height(), 1};
    vkCmdCopyImageToBuffer(commands, source.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, staging->handle(), 1,
                           &region);
    if (layout != VK_IMAGE_LAYOUT_UNDEFINED) transition(commands, source, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, layout);
  });
  if (!copied) return copied.error();
  std::vector<std::uint8_t> bytes(size);
  std::memcpy(bytes.data(), staging->mapped(), size);
  return bytes;
}

}  // namespace proxygi::gpu
