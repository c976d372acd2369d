#pragma once
// An image a viewer frame ends in: a swapchain image or the offscreen presenter's image.
// The frame is written into it (gpu::FrameOutput::into), the UI pass draws over it, and a
// screenshot reads it back.
#include <cstdint>
#include <vector>

#include <vulkan/vulkan.h>

#include "base/result.h"
#include "gpu/context.h"

namespace proxygi::view {

struct TargetImage {
  VkImage image = VK_NULL_HANDLE;
  VkImageView view = VK_NULL_HANDLE;
  VkFormat format = VK_FORMAT_UNDEFINED;
  std::uint32_t width = 0, height = 0;
};

// RGBA8 bytes (row 0 on top) of `target`, which is in `layout` now and stays in it. Waits for
// the queue. BGRA formats are swizzled; sRGB-encoded bytes stay as they are.
Result<std::vector<std::uint8_t>> read_target(gpu::Context& context, const TargetImage& target, VkImageLayout layout);

// Clears `target` to a dark gray and leaves it in COLOR_ATTACHMENT_OPTIMAL (the layout the UI
// pass expects): what shows before the first scene is loaded. Waits for the queue.
Status clear_target(gpu::Context& context, const TargetImage& target);

}  // namespace proxygi::view
