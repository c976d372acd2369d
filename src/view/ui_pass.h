#pragma once
// UiPass: draws Dear ImGui over a finished frame. Dear ImGui 1.86's Vulkan backend needs a
// VkRenderPass, so the UI has its own: it loads the target (the frame already written into it,
// in COLOR_ATTACHMENT_OPTIMAL), draws the UI, and leaves the image in `final_layout`
// (PRESENT_SRC_KHR for a swapchain, TRANSFER_SRC_OPTIMAL offscreen). With the UI hidden the
// pass draws nothing, so the pixels are the renderer's, byte for byte.
//
// The UI is drawn either straight onto the frame (UiDraw::direct) or through a cached overlay
// (overlay_cache.h): ImGui into an overlay image of the target's size (UiDraw::redraw_overlay),
// then OverlayBlendPass over the frame; UiDraw::reuse_overlay blends the overlay drawn last
// without rasterizing ImGui again.
//
// One command buffer and fence: submit() waits for the previous UI submission first.
#include <map>
#include <optional>
#include <vector>

#include <vulkan/vulkan.h>

#include "base/result.h"
#include "gpu/context.h"
#include "gpu/resources.h"
#include "view/overlay_blend_pass.h"
#include "view/overlay_cache.h"
#include "view/target_image.h"

struct ImDrawData;
struct ImDrawList;

namespace proxygi::view {

enum class UiDraw { direct, redraw_overlay, reuse_overlay };

// The pixels ImGui's draw lists can touch: per draw command, its vertices' bounds within its
// clip rectangle, one pixel wider on each side (display coordinates, row 0 on top).
std::vector<PixelRect> touched_rects(const ImDrawData& draw_data);

// The bytes that decide what ImGui's draw lists rasterize to (display size, vertices, indices,
// commands), split into the scene overlays (`scene_list`, ImGui's background list: they follow
// the frame) and the panels (every other list). Equal bytes: equal pixels.
struct DrawSignature {
  std::vector<std::uint8_t> scene, panels;
};
void draw_signature(const ImDrawData& draw_data, const ImDrawList* scene_list, DrawSignature& out);

class UiPass {
 public:
  // Initialises the ImGui Vulkan backend for `format` (the ImGui context must exist).
  static Result<std::unique_ptr<UiPass>> create(gpu::Context& context, VkFormat format, VkImageLayout final_layout,
                                                std::uint32_t image_count);
  ~UiPass();
  UiPass(const UiPass&) = delete;
  UiPass& operator=(const UiPass&) = delete;

  // Records and submits the UI over `target` (draw_data may be null: nothing drawn; `how` is
  // then unused). reuse_overlay needs overlay_cached() for the target's size. Signals `signal`
  // when given (the present waits on it).
  Status submit(const TargetImage& target, ImDrawData* draw_data, UiDraw how = UiDraw::direct,
                VkSemaphore signal = VK_NULL_HANDLE);
  Status wait();  // for the last submission
  // Framebuffers of images that are gone (swapchain recreated); the overlay goes with them.
  void forget_framebuffers();
  // An overlay drawn for a target of this size exists.
  bool overlay_cached(std::uint32_t width, std::uint32_t height) const;
  // The rectangles the cached overlay is blended in (covering_rects of what it touched).
  const std::vector<PixelRect>& overlay_rects() const { return overlay_rects_; }

 private:
  explicit UiPass(gpu::Context& context) : context_(context) {}
  Result<VkFramebuffer> framebuffer(const TargetImage& target);
  Status make_overlay(const TargetImage& target);
  void record_overlay(const TargetImage& target, ImDrawData* draw_data, UiDraw how, VkImageLayout final_layout);

  gpu::Context& context_;
  VkRenderPass render_pass_ = VK_NULL_HANDLE;          // loads the frame, ends in final_layout_
  VkRenderPass overlay_render_pass_ = VK_NULL_HANDLE;  // clears the overlay, ends shader-readable
  VkImageLayout final_layout_ = VK_IMAGE_LAYOUT_UNDEFINED;
  std::unique_ptr<OverlayBlendPass> blend_;
  std::optional<gpu::Image> overlay_;
  VkFramebuffer overlay_framebuffer_ = VK_NULL_HANDLE;
  bool overlay_drawn_ = false;
  std::vector<PixelRect> overlay_rects_;
  VkDescriptorPool descriptor_pool_ = VK_NULL_HANDLE;
  VkCommandPool command_pool_ = VK_NULL_HANDLE;
  VkCommandBuffer commands_ = VK_NULL_HANDLE;
  VkFence fence_ = VK_NULL_HANDLE;
  bool pending_ = false;
  bool backend_ = false;
  std::map<VkImageView, VkFramebuffer> framebuffers_;
};

}  // namespace proxygi::view
