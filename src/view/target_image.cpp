#include "view/target_image.h"

#include <cstring>

#include "gpu/resources.h"
#include "gpu/transfer.h"

namespace proxygi::view {

Result<std::vector<std::uint8_t>> read_target(gpu::Context& context, const TargetImage& target, VkImageLayout layout) {
  const VkDeviceSize size = VkDeviceSize(target.width) * target.height * 4;
  auto buffer = gpu::Buffer::create(context, size, VK_BUFFER_USAGE_TRANSFER_DST_BIT, gpu::MemoryKind::host_visible);
  if (!buffer) return buffer.error();
  Status copied = context.submit_and_wait([&](VkCommandBuffer commands) {
    gpu::transition(commands, target.image, layout, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {target.width, target.height, 1};
    vkCmdCopyImageToBuffer(commands, target.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, buffer->handle(), 1, &region);
    gpu::transition(commands, target.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, layout);
  });
  if (!copied) return copied.error();
  std::vector<std::uint8_t> bytes(size);
  std::memcpy(bytes.data(), buffer->mapped(), size);
  const bool bgra = target.format == VK_FORMAT_B8G8R8A8_UNORM || target.format == VK_FORMAT_B8G8R8A8_SRGB;
  if (bgra)
    for (std::size_t i = 0; i < bytes.size(); i += 4) std::swap(bytes[i], bytes[i + 2]);
  return bytes;
}

Status clear_target(gpu::Context& context, const TargetImage& target) {
  return context.submit_and_wait([&](VkCommandBuffer commands) {
    gpu::transition(commands, target.image, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL);
    const VkClearColorValue gray{{0.08f, 0.08f, 0.09f, 1.0f}};
    const VkImageSubresourceRange range{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    vkCmdClearColorImage(commands, target.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &gray, 1, &range);
    gpu::transition(commands, target.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                    VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL);
  });
}

}  // namespace proxygi::view
