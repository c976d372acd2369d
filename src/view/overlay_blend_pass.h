#pragma once
// OverlayBlendPass (overlay_blend.frag over fullscreen.vert): the cached UI overlay over the
// frame in the target, frame ← P + (1 − A) · frame (overlay_cache.h), drawn only in the given
// disjoint rectangles (covering_rects: outside them the overlay is transparent black).
// CPU twin: view::blend_overlay.
#include <memory>
#include <span>

#include <vulkan/vulkan.h>

#include "base/result.h"
#include "gpu/context.h"
#include "gpu/pipeline.h"
#include "view/overlay_cache.h"
#include "view/target_image.h"

namespace proxygi::view {

class OverlayBlendPass {
 public:
  struct Inputs {
    VkImageView overlay = VK_NULL_HANDLE;  // premultiplied, the target's size and format, SHADER_READ_ONLY_OPTIMAL
    std::span<const PixelRect> rects;      // disjoint, inside the target
  };
  struct Outputs {
    const TargetImage* target = nullptr;   // COLOR_ATTACHMENT_OPTIMAL before and after
  };

  static Result<std::unique_ptr<OverlayBlendPass>> create(const gpu::Context& context, VkFormat format);
  ~OverlayBlendPass();
  OverlayBlendPass(const OverlayBlendPass&) = delete;
  OverlayBlendPass& operator=(const OverlayBlendPass&) = delete;

  // Records the blend (dynamic rendering, load and store); nothing when `rects` is empty. The
  // caller orders the frame's and the overlay's writes before it.
  void record(const gpu::Context& context, VkCommandBuffer commands, const Inputs& in, const Outputs& out) const;

 private:
  OverlayBlendPass() = default;
  VkDevice device_ = VK_NULL_HANDLE;
  gpu::Pipeline pipeline_;
  VkSampler sampler_ = VK_NULL_HANDLE;
};

}  // namespace proxygi::view
