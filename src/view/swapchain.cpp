#include "view/swapchain.h"

#include <algorithm>

#include "gpu/vulkan_check.h"

namespace proxygi::view {

Result<std::unique_ptr<Swapchain>> Swapchain::create(gpu::Context& context, std::uint32_t width,
                                                     std::uint32_t height, bool vsync) {
  if (context.surface() == VK_NULL_HANDLE) return make_error("swapchain: the context has no surface");
  std::unique_ptr<Swapchain> swapchain(new Swapchain(context));
  swapchain->vsync_ = vsync;
  VkFenceCreateInfo fence{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
  PROXYGI_VK_TRY(vkCreateFence(context.device(), &fence, nullptr, &swapchain->acquire_fence_));
  if (Status s = swapchain->build(width, height); !s) return s.error();
  return swapchain;
}

Swapchain::~Swapchain() {
  (void)drop_started();
  vkDeviceWaitIdle(context_.device());
  destroy_images();
  if (swapchain_) vkDestroySwapchainKHR(context_.device(), swapchain_, nullptr);
  if (acquire_fence_) vkDestroyFence(context_.device(), acquire_fence_, nullptr);
}

void Swapchain::destroy_images() {
  for (const TargetImage& image : images_) vkDestroyImageView(context_.device(), image.view, nullptr);
  for (VkSemaphore semaphore : render_done_) vkDestroySemaphore(context_.device(), semaphore, nullptr);
  images_.clear();
  render_done_.clear();
}

Status Swapchain::wait_for_started() {
  started_.reset();
  PROXYGI_VK_TRY(vkWaitForFences(context_.device(), 1, &acquire_fence_, VK_TRUE, UINT64_MAX));
  PROXYGI_VK_TRY(vkResetFences(context_.device(), 1, &acquire_fence_));
  return {};
}

Status Swapchain::drop_started() { return started_ ? wait_for_started() : Status{}; }

Status Swapchain::recreate(std::uint32_t width, std::uint32_t height) {
  if (Status s = drop_started(); !s) return s;
  PROXYGI_VK_TRY(vkDeviceWaitIdle(context_.device()));
  ++recreations_;
  return build(width, height);
}

Status Swapchain::build(std::uint32_t width, std::uint32_t height) {
  const VkPhysicalDevice physical = context_.physical_device();
  const VkSurfaceKHR surface = context_.surface();
  VkSurfaceCapabilitiesKHR capabilities{};
  PROXYGI_VK_TRY(vkGetPhysicalDeviceSurfaceCapabilitiesKHR(physical, surface, &capabilities));

  std::uint32_t count = 0;
  PROXYGI_VK_TRY(vkGetPhysicalDeviceSurfaceFormatsKHR(physical, surface, &count, nullptr));
  std::vector<VkSurfaceFormatKHR> formats(count);
  PROXYGI_VK_TRY(vkGetPhysicalDeviceSurfaceFormatsKHR(physical, surface, &count, formats.data()));
  const VkFormat preferred[] = {VK_FORMAT_B8G8R8A8_UNORM, VK_FORMAT_R8G8B8A8_UNORM, VK_FORMAT_B8G8R8A8_SRGB,
                                VK_FORMAT_R8G8B8A8_SRGB};
  std::optional<VkSurfaceFormatKHR> chosen;
  for (VkFormat want : preferred) {
    for (const auto& format : formats)
      if (format.format == want && format.colorSpace == VK_COLOR_SPACE_SRGB_NONLINEAR_KHR) chosen = format;
    if (chosen) break;
  }
  if (!chosen) return make_error("swapchain: the surface offers no 8-bit RGBA/BGRA sRGB-nonlinear format");
  format_ = chosen->format;

  PROXYGI_VK_TRY(vkGetPhysicalDeviceSurfacePresentModesKHR(physical, surface, &count, nullptr));
  std::vector<VkPresentModeKHR> modes(count);
  PROXYGI_VK_TRY(vkGetPhysicalDeviceSurfacePresentModesKHR(physical, surface, &count, modes.data()));
  present_mode_ = VK_PRESENT_MODE_FIFO_KHR;  // always supported
  if (!vsync_)
    for (VkPresentModeKHR want : {VK_PRESENT_MODE_MAILBOX_KHR, VK_PRESENT_MODE_IMMEDIATE_KHR})
      if (std::find(modes.begin(), modes.end(), want) != modes.end()) {
        present_mode_ = want;
        break;
      }

  if (capabilities.currentExtent.width != 0xFFFFFFFFu) extent_ = capabilities.currentExtent;
  else extent_ = {width, height};
  extent_.width = std::clamp(extent_.width, capabilities.minImageExtent.width, capabilities.maxImageExtent.width);
  extent_.height = std::clamp(extent_.height, capabilities.minImageExtent.height, capabilities.maxImageExtent.height);
  if (extent_.width == 0 || extent_.height == 0) return make_error("swapchain: zero-size surface (minimized)");

  std::uint32_t image_count = std::max(capabilities.minImageCount + 1, 2u);
  if (capabilities.maxImageCount > 0) image_count = std::min(image_count, capabilities.maxImageCount);
  const VkImageUsageFlags usage =
      VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
  if ((capabilities.supportedUsageFlags & usage) != usage)
    return make_error("swapchain: images cannot be copied into and read back on this surface");

  VkSwapchainCreateInfoKHR info{VK_STRUCTURE_TYPE_SWAPCHAIN_CREATE_INFO_KHR};
  info.surface = surface;
  info.minImageCount = image_count;
  info.imageFormat = chosen->format;
  info.imageColorSpace = chosen->colorSpace;
  info.imageExtent = extent_;
  info.imageArrayLayers = 1;
  info.imageUsage = usage;
  info.imageSharingMode = VK_SHARING_MODE_EXCLUSIVE;
  info.preTransform = capabilities.currentTransform;
  info.compositeAlpha = VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR;
  info.presentMode = present_mode_;
  info.clipped = VK_TRUE;
  const VkSwapchainKHR old = swapchain_;
  info.oldSwapchain = old;
  VkSwapchainKHR created = VK_NULL_HANDLE;
  PROXYGI_VK_TRY(vkCreateSwapchainKHR(context_.device(), &info, nullptr, &created));
  destroy_images();
  if (old) vkDestroySwapchainKHR(context_.device(), old, nullptr);
  swapchain_ = created;

  PROXYGI_VK_TRY(vkGetSwapchainImagesKHR(context_.device(), swapchain_, &count, nullptr));
  std::vector<VkImage> images(count);
  PROXYGI_VK_TRY(vkGetSwapchainImagesKHR(context_.device(), swapchain_, &count, images.data()));
  for (VkImage image : images) {
    VkImageViewCreateInfo view{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    view.image = image;
    view.viewType = VK_IMAGE_VIEW_TYPE_2D;
    view.format = format_;
    view.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    TargetImage target{image, VK_NULL_HANDLE, format_, extent_.width, extent_.height};
    PROXYGI_VK_TRY(vkCreateImageView(context_.device(), &view, nullptr, &target.view));
    images_.push_back(target);
    VkSemaphoreCreateInfo semaphore{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
    VkSemaphore done = VK_NULL_HANDLE;
    PROXYGI_VK_TRY(vkCreateSemaphore(context_.device(), &semaphore, nullptr, &done));
    render_done_.push_back(done);
  }
  return {};
}

Result<bool> Swapchain::start_acquire() {
  if (started_) return true;
  std::uint32_t index = 0;
  const VkResult result =
      vkAcquireNextImageKHR(context_.device(), swapchain_, UINT64_MAX, VK_NULL_HANDLE, acquire_fence_, &index);
  if (result == VK_ERROR_OUT_OF_DATE_KHR) return false;  // the fence is not signalled
  if (result != VK_SUCCESS && result != VK_SUBOPTIMAL_KHR) return gpu::vulkan_error("vkAcquireNextImageKHR", result);
  started_ = Acquired{index, result == VK_SUBOPTIMAL_KHR};
  return true;
}

Result<std::optional<Swapchain::Acquired>> Swapchain::acquire() {
  auto started = start_acquire();
  if (!started) return started.error();
  if (!*started) return std::optional<Acquired>();
  const Acquired acquired = *started_;
  if (Status s = wait_for_started(); !s) return s.error();
  return std::optional<Acquired>(acquired);
}

Result<bool> Swapchain::present(std::uint32_t index, VkSemaphore wait) {
  VkPresentInfoKHR info{VK_STRUCTURE_TYPE_PRESENT_INFO_KHR};
  info.waitSemaphoreCount = wait ? 1 : 0;
  info.pWaitSemaphores = &wait;
  info.swapchainCount = 1;
  info.pSwapchains = &swapchain_;
  info.pImageIndices = &index;
  const VkResult result = vkQueuePresentKHR(context_.queue(), &info);
  if (result == VK_ERROR_OUT_OF_DATE_KHR || result == VK_SUBOPTIMAL_KHR) return false;
  if (result != VK_SUCCESS) return gpu::vulkan_error("vkQueuePresentKHR", result);
  return true;
}

}  // namespace proxygi::view
