// Step 9 of the frame: the finished RGBA8 frame into the slot's readback buffers, or into a
// caller's image: a buffer-to-image copy of the frame itself when the image has its size and
// channel order, else frame_output.comp's resampled, reordered texels and a copy of those.
// (vkCmdBlitImage, the obvious tool, runs per texel on the CPU on lavapipe: 512² took 8× a copy.)
#include "gpu/frame_output.h"

#include "gpu/context.h"
#include "gpu/frame_passes.h"
#include "gpu/soft_gi_frame.h"
#include "gpu/transfer.h"
#include "gpu/vulkan_check.h"
#include "shaders/shared/layouts.h"
#include "shaders/shared/frame_output.h"

namespace proxygi::gpu {
namespace {

bool is_bgra(VkFormat format) { return format == VK_FORMAT_B8G8R8A8_UNORM || format == VK_FORMAT_B8G8R8A8_SRGB; }

}  // namespace

bool is_output_format(VkFormat format) {
  return format == VK_FORMAT_R8G8B8A8_UNORM || format == VK_FORMAT_R8G8B8A8_SRGB || is_bgra(format);
}

bool is_srgb_format(VkFormat format) { return format == VK_FORMAT_R8G8B8A8_SRGB || format == VK_FORMAT_B8G8R8A8_SRGB; }

Status SoftGiFrame::prepare_output(const FrameOutput& output) {
  if (!output.image) return {};
  const ImageOutput& target = *output.image;
  if (target.image == VK_NULL_HANDLE || target.width == 0 || target.height == 0)
    return make_error("frame output: no image or an empty size");
  if (!is_output_format(target.format))
    return make_error("frame output: image format " + std::to_string(int(target.format)) +
                      " is not R8G8B8A8 or B8G8R8A8 (UNORM or SRGB)");
  if (output_pipeline_.handle() == VK_NULL_HANDLE) {
    const ComputeBinding bindings[] = {{gpu_layout::kOutputBindLdr, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
                                       {gpu_layout::kOutputBindPixels, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}};
    auto pipeline = make_compute_pipeline(context_, "frame_output.comp", bindings, sizeof(gpu_layout::FrameOutputPush));
    if (!pipeline) return pipeline.error();
    output_pipeline_ = std::move(*pipeline);
  }
  const VkDeviceSize bytes = VkDeviceSize(target.width) * target.height * sizeof(std::uint32_t);
  if (output_pixels_.size() >= bytes) return {};
  // A larger image (a resized window): frames on the queue may still copy from the old buffer.
  if (output_pixels_.handle() != VK_NULL_HANDLE) PROXYGI_VK_TRY(vkQueueWaitIdle(context_.queue()));
  auto made = Buffer::create(context_, bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                             MemoryKind::device_local);
  if (!made) return made.error();
  output_pixels_ = std::move(*made);
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
  if (output_pipeline_.handle() == VK_NULL_HANDLE || output_pixels_.size() < VkDeviceSize(target.width) * target.height * 4)
    return;  // prepare_output was not called: nothing to write with
  const bool same = target.width == config_.width && target.height == config_.height && !is_bgra(target.format);
  const Buffer* source = &targets_.ldr;
  if (!same) {
    gpu_layout::FrameOutputPush push{};
    push.source_width = config_.width, push.source_height = config_.height;
    push.target_width = target.width, push.target_height = target.height;
    push.swap_red_blue = is_bgra(target.format) ? 1u : 0u;
    push.linear_filtering = is_srgb_format(target.format) ? 1u : 0u;
    output_pipeline_.bind(commands);
    DescriptorPush()
        .storage_buffer(gpu_layout::kOutputBindLdr, targets_.ldr)
        .storage_buffer(gpu_layout::kOutputBindPixels, output_pixels_)
        .push(context_, commands, output_pipeline_);
    output_pipeline_.push_constants(commands, &push, sizeof push);
    dispatch_grid(commands, target.width, target.height);
    VkMemoryBarrier2 to_copy{VK_STRUCTURE_TYPE_MEMORY_BARRIER_2};
    to_copy.srcStageMask = VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT;
    to_copy.srcAccessMask = VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT;
    to_copy.dstStageMask = VK_PIPELINE_STAGE_2_COPY_BIT;
    to_copy.dstAccessMask = VK_ACCESS_2_TRANSFER_READ_BIT;
    VkDependencyInfo dependency{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
    dependency.memoryBarrierCount = 1;
    dependency.pMemoryBarriers = &to_copy;
    vkCmdPipelineBarrier2(commands, &dependency);
    source = &output_pixels_;
  }
  constexpr VkPipelineStageFlags2 kTransfer = VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT;
  // The caller's image: whatever it was used for before completes first (all commands).
  transition(commands, target.image, target.layout_before, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
             {VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, VK_ACCESS_2_MEMORY_READ_BIT | VK_ACCESS_2_MEMORY_WRITE_BIT,
              kTransfer, VK_ACCESS_2_TRANSFER_WRITE_BIT});
  // Packed texels in the image's own byte order: the copy lands them unchanged, sRGB or not.
  VkBufferImageCopy region{};
  region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  region.imageExtent = {target.width, target.height, 1};
  vkCmdCopyBufferToImage(commands, source->handle(), target.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
  transition(commands, target.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, target.layout_after,
             {kTransfer, VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT,
              VK_ACCESS_2_MEMORY_READ_BIT | VK_ACCESS_2_MEMORY_WRITE_BIT});
}

}  // namespace proxygi::gpu
