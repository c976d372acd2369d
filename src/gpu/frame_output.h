#pragma once
// Where a finished frame goes (DESIGN.md "One frame", step 9): the ring slot's host-visible
// readback buffers (record, bench, tests), or an image the caller owns (a swapchain image for the
// viewer, an offscreen image for scripted tests), written in the same submission.
#include <cstdint>
#include <optional>

#include <vulkan/vulkan.h>

namespace proxygi::gpu {

// A caller's 2-D color image. Formats: R8G8B8A8 or B8G8R8A8, UNORM or SRGB (the sRGB-encoded bytes
// of the frame land unchanged in either encoding). Needs VK_IMAGE_USAGE_TRANSFER_DST_BIT. At the
// frame's size one buffer-to-image copy (the frame is composited in the image's channel order);
// another size (the viewer's lower internal resolution) is filled by a linear-filtered blit.
struct ImageOutput {
  VkImage image = VK_NULL_HANDLE;
  VkFormat format = VK_FORMAT_R8G8B8A8_UNORM;
  std::uint32_t width = 0, height = 0;
  VkImageLayout layout_before = VK_IMAGE_LAYOUT_UNDEFINED;  // UNDEFINED: its contents are discarded
  VkImageLayout layout_after = VK_IMAGE_LAYOUT_GENERAL;     // e.g. PRESENT_SRC_KHR
};

struct FrameOutput {
  bool readback_ldr = true;   // copy the RGBA8 frame into the slot's readback buffer
  bool readback_hdr = true;   // copy the linear radiance too (skip it when no EXR is written)
  std::optional<ImageOutput> image;
  // Keep the frame's float targets for SoftGiFrame::read_hdr and read_irradiance (tests, AOVs,
  // regression checks). false: the composite writes only what this output copies (the HDR only
  // when read back or supersampled, never the irradiance AOV); lavapipe then spends about 20 %
  // (HDR kept) to 40 % (neither) less on upsample+composite. record, the viewer and the
  // benchmarks' frame loops turn it off.
  bool float_targets = true;

  static FrameOutput readback(bool hdr = true) { return {true, hdr, std::nullopt}; }
  static FrameOutput into(const ImageOutput& image) { return {false, false, image}; }
};

// Whether frames can be written into images of this format.
bool is_output_format(VkFormat format);
bool is_srgb_format(VkFormat format);

}  // namespace proxygi::gpu
