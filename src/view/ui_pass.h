#pragma once
// UiPass: draws Dear ImGui over a finished frame. Dear ImGui 1.86's Vulkan backend needs a
// VkRenderPass, so the UI has its own: it loads the target (the frame already written into it,
// in COLOR_ATTACHMENT_OPTIMAL), draws the UI, and leaves the image in `final_layout`
// (PRESENT_SRC_KHR for a swapchain, TRANSFER_SRC_OPTIMAL offscreen). With the UI hidden the
// pass draws nothing, so the pixels are the renderer's, byte for byte.
//
// One command buffer and fence: submit() waits for the previous UI submission first.
#include <map>

#include <vulkan/vulkan.h>

#include "base/result.h"
#include "gpu/context.h"
#include "view/target_image.h"

struct ImDrawData;

namespace proxygi::view {

class UiPass {
 public:
  // Initialises the ImGui Vulkan backend for `format` (the ImGui context must exist).
  static Result<std::unique_ptr<UiPass>> create(gpu::Context& context, VkFormat format, VkImageLayout final_layout,
                                                std::uint32_t image_count);
  ~UiPass();
  UiPass(const UiPass&) = delete;
  UiPass& operator=(const UiPass&) = delete;

  // Records and submits the UI over `target` (draw_data may be null: nothing drawn). Signals
  // `signal` when given (the present waits on it).
  Status submit(const TargetImage& target, ImDrawData* draw_data, VkSemaphore signal = VK_NULL_HANDLE);
  Status wait();  // for the last submission
  // Framebuffers of images that are gone (swapchain recreated).
  void forget_framebuffers();

 private:
  explicit UiPass(gpu::Context& context) : context_(context) {}
  Result<VkFramebuffer> framebuffer(const TargetImage& target);

  gpu::Context& context_;
  VkRenderPass render_pass_ = VK_NULL_HANDLE;
  VkDescriptorPool descriptor_pool_ = VK_NULL_HANDLE;
  VkCommandPool command_pool_ = VK_NULL_HANDLE;
  VkCommandBuffer commands_ = VK_NULL_HANDLE;
  VkFence fence_ = VK_NULL_HANDLE;
  bool pending_ = false;
  bool backend_ = false;
  std::map<VkImageView, VkFramebuffer> framebuffers_;
};

}  // namespace proxygi::view
