// Step 9 of the frame: the finished 8-bit frame into the slot's readback buffers, or into a
// caller's image: at the frame's size one buffer-to-image copy (the composite wrote the image's
// channel order), else through a staging image and a linear blit. Copies, not blits, where they
// can: on lavapipe a swizzling vkCmdBlitImage at 512² took 8× an image copy.
#include "gpu/frame_output.h"

#include "gpu/context.h"
#include "gpu/soft_gi_frame.h"
#include "gpu/transfer.h"
#include "gpu/vulkan_check.h"

namespace proxygi::gpu {
namespace {

bool is_bgra(VkFormat format) { return format == VK_FORMAT_B8G8R8A8_UNORM || format == VK_FORMAT_B8G8R8A8_SRGB; }

}  // namespace

bool is_output_format(VkFormat format) {
  return format == VK_FORMAT_R8G8B8A8_UNORM || format == VK_FORMAT_R8G8B8A8_SRGB || is_bgra(format);
}

bool is_srgb_format(VkFormat format) { return format == VK_FORMAT_R8G8B8A8_SRGB || format == VK_FORMAT_B8G8R8A8_SRGB; }

Status SoftGiFrame::prepare_output(const FrameOutput& output) {
  ldr_bgra_ = output.image && !output.readback_ldr && is_bgra(output.image->format);
  if (!output.image) return {};
  const ImageOutput& target = *output.image;
  if (target.image == VK_NULL_HANDLE || target.width == 0 || target.height == 0)
    return make_error("frame output: no image or an empty size");
  if (!is_output_format(target.format))
    return make_error("frame output: image format " + std::to_string(int(target.format)) +
                      " is not R8G8B8A8 or B8G8R8A8 (UNORM or SRGB)");
  if (target.width == config_.width && target.height == config_.height && is_bgra(target.format) == ldr_bgra_)
    return {};  // one copy, no staging image
  const VkFormat format = ldr_bgra_                        ? target.format
                          : is_srgb_format(target.format) ? VK_FORMAT_R8G8B8A8_SRGB
                                                          : VK_FORMAT_R8G8B8A8_UNORM;
  if (output_staging_.handle() != VK_NULL_HANDLE && output_staging_.format() == format) return {};
  // Another format: frames on the queue may still read the old staging image.
  if (output_staging_.handle() != VK_NULL_HANDLE) PROXYGI_VK_TRY(vkQueueWaitIdle(context_.queue()));
  auto made = Image::create(context_, config_.width, config_.height, format,
                            VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_SAMPLED_BIT);
  if (!made) return made.error();
  output_staging_ = std::move(*made);
  return {};
}

void SoftGiFrame::record_output(VkCommandBuffer commands, std::uint32_t slot_index, const FrameOutput& output) const {
  const Slot& slot = slots_[slot_index];
  if (output.readback_ldr || output.readback_hdr) {
    if (output.readback_ldr) {
      const VkBufferCopy copy{0, 0, targets_.ldr.size()};
      vkCmdCopyBuffer(commands, targets_.ldr.handle(), slot.ldr_readback.handle(), 1, &copy);
    }
    if (output.readback_hdr) {
      const VkBufferCopy copy{0, 0, targets_.hdr.size()};
      vkCmdCopyBuffer(commands, targets_.hdr.handle(), slot.hdr_readback.handle(), 1, &copy);
    }
    VkMemoryBarrier2 to_host{VK_STRUCTURE_TYPE_MEMORY_BARRIER_2};
    to_host.srcStageMask = VK_PIPELINE_STAGE_2_COPY_BIT;
    to_host.srcAccessMask = VK_ACCESS_2_TRANSFER_WRITE_BIT;
    to_host.dstStageMask = VK_PIPELINE_STAGE_2_HOST_BIT;
    to_host.dstAccessMask = VK_ACCESS_2_HOST_READ_BIT;
    VkDependencyInfo dependency{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
    dependency.memoryBarrierCount = 1;
    dependency.pMemoryBarriers = &to_host;
    vkCmdPipelineBarrier2(commands, &dependency);
  }
  if (!output.image) return;
  const ImageOutput& target = *output.image;
  constexpr VkPipelineStageFlags2 kTransfer = VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT;
  const bool direct = target.width == config_.width && target.height == config_.height && is_bgra(target.format) == ldr_bgra_;
  if (!direct && output_staging_.handle() == VK_NULL_HANDLE) return;  // prepare_output was not called
  VkBufferImageCopy region{};
  region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  region.imageExtent = {config_.width, config_.height, 1};
  if (!direct) {
    transition(commands, output_staging_.handle(), VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
               {kTransfer, 0, kTransfer, VK_ACCESS_2_TRANSFER_WRITE_BIT});
    vkCmdCopyBufferToImage(commands, targets_.ldr.handle(), output_staging_.handle(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                           1, &region);
    transition(commands, output_staging_.handle(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
               VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
               {kTransfer, VK_ACCESS_2_TRANSFER_WRITE_BIT, kTransfer, VK_ACCESS_2_TRANSFER_READ_BIT});
  }
  // The caller's image: whatever it was used for before completes first (all commands).
  transition(commands, target.image, target.layout_before, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
             {VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, VK_ACCESS_2_MEMORY_READ_BIT | VK_ACCESS_2_MEMORY_WRITE_BIT,
              kTransfer, VK_ACCESS_2_TRANSFER_WRITE_BIT});
  if (direct) {
    // The bytes are already in the image's order: they land unchanged, sRGB or not.
    vkCmdCopyBufferToImage(commands, targets_.ldr.handle(), target.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1,
                           &region);
  } else {
    VkImageBlit blit{};
    blit.srcSubresource = blit.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    blit.srcOffsets[1] = {int(config_.width), int(config_.height), 1};
    blit.dstOffsets[1] = {int(target.width), int(target.height), 1};
    const bool scaled = target.width != config_.width || target.height != config_.height;
    vkCmdBlitImage(commands, output_staging_.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, target.image,
                   VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &blit, scaled ? VK_FILTER_LINEAR : VK_FILTER_NEAREST);
  }
  transition(commands, target.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, target.layout_after,
             {kTransfer, VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT,
              VK_ACCESS_2_MEMORY_READ_BIT | VK_ACCESS_2_MEMORY_WRITE_BIT});
}

}  // namespace proxygi::gpu
