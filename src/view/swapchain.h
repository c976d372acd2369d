#pragma once
// Swapchain on the context's surface. FIFO by default (vsync); without vsync MAILBOX, else
// IMMEDIATE, else FIFO. Prefers a UNORM 8-bit format: the frame's bytes are already sRGB-encoded
// (they land unchanged) and Dear ImGui's colors are meant for a UNORM target.
//
// acquire() waits on a fence instead of a semaphore: the renderer's submissions take no wait
// semaphores, and on a CPU device the wait costs nothing measurable. start_acquire() asks for
// the next image early (while the previous frame still renders and waits to be presented), so
// that acquire() later only collects it: on a software swapchain the acquisition's own work
// then overlaps the device's instead of delaying the next submit. Out-of-date and
// suboptimal results come back as `stale` so the caller recreates at the window's new size; a
// zero-size (minimized) window is never given a swapchain.
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include <vulkan/vulkan.h>

#include "base/result.h"
#include "gpu/context.h"
#include "view/target_image.h"

namespace proxygi::view {

class Swapchain {
 public:
  static Result<std::unique_ptr<Swapchain>> create(gpu::Context& context, std::uint32_t width, std::uint32_t height,
                                                   bool vsync);
  ~Swapchain();
  Swapchain(const Swapchain&) = delete;
  Swapchain& operator=(const Swapchain&) = delete;

  // Rebuilds for a new size (waits for the device first). Counts recreations for the HUD/tests.
  Status recreate(std::uint32_t width, std::uint32_t height);

  struct Acquired {
    std::uint32_t index = 0;
    bool stale = false;  // suboptimal: usable now, recreate after presenting
  };
  // Nothing when the swapchain is out of date (recreate and try again). Collects the image
  // start_acquire asked for, if any.
  Result<std::optional<Acquired>> acquire();
  // Asks for the next image without waiting for it (at most one at a time; the swapchain has one
  // image more than the surface's minimum, so this may run while one image waits to be
  // presented). False when out of date.
  Result<bool> start_acquire();
  // Presents image `index` after `wait`; returns false when the swapchain went stale.
  Result<bool> present(std::uint32_t index, VkSemaphore wait);

  const TargetImage& image(std::uint32_t index) const { return images_[index]; }
  std::uint32_t image_count() const { return std::uint32_t(images_.size()); }
  VkSemaphore render_done(std::uint32_t index) const { return render_done_[index]; }
  VkFormat format() const { return format_; }
  VkPresentModeKHR present_mode() const { return present_mode_; }
  std::uint32_t width() const { return extent_.width; }
  std::uint32_t height() const { return extent_.height; }
  int recreations() const { return recreations_; }

 private:
  explicit Swapchain(gpu::Context& context) : context_(context) {}
  Status build(std::uint32_t width, std::uint32_t height);
  void destroy_images();

  gpu::Context& context_;
  bool vsync_ = true;
  VkSwapchainKHR swapchain_ = VK_NULL_HANDLE;
  VkFormat format_ = VK_FORMAT_UNDEFINED;
  VkPresentModeKHR present_mode_ = VK_PRESENT_MODE_FIFO_KHR;
  VkExtent2D extent_{};
  std::vector<TargetImage> images_;
  std::vector<VkSemaphore> render_done_;
  VkFence acquire_fence_ = VK_NULL_HANDLE;
  std::optional<Acquired> started_;  // start_acquire's image, its fence not yet waited for
  Status wait_for_started();         // waits for its fence and forgets it
  Status drop_started();             // the same when there is one (before a rebuild)
  int recreations_ = 0;
};

}  // namespace proxygi::view
