// Context options for live use: extra instance and device extensions, and a surface made by a
// factory that the chosen queue must present to. Headless (no options) stays the default. Each
// test makes its own Context with validation on and requires zero validation messages.
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "gpu/context.h"
#include "gpu/transfer.h"

namespace proxygi::gpu {
namespace {

void expect_no_validation_messages(const Context& context) {
  EXPECT_EQ(context.validation_message_count(), 0u)
      << "first message: " << (context.validation_messages().empty() ? "" : context.validation_messages().front());
}

Result<VkSurfaceKHR> create_headless_surface(VkInstance instance) {
  auto create =
      reinterpret_cast<PFN_vkCreateHeadlessSurfaceEXT>(vkGetInstanceProcAddr(instance, "vkCreateHeadlessSurfaceEXT"));
  if (!create) return make_error("vkCreateHeadlessSurfaceEXT is not available");
  VkHeadlessSurfaceCreateInfoEXT info{VK_STRUCTURE_TYPE_HEADLESS_SURFACE_CREATE_INFO_EXT};
  VkSurfaceKHR surface = VK_NULL_HANDLE;
  if (create(instance, &info, nullptr, &surface) != VK_SUCCESS) return make_error("vkCreateHeadlessSurfaceEXT failed");
  return surface;
}

TEST(ContextOptions, HeadlessByDefault) {
  auto context = Context::create({.device_request = "", .validation = Validation::on});
  ASSERT_TRUE(context.ok()) << context.message();
  EXPECT_EQ((*context)->surface(), VK_NULL_HANDLE);
  EXPECT_FALSE((*context)->report().needs_present);
  EXPECT_EQ(static_cast<int>((*context)->queue_family()), (*context)->report().queue_family);
  EXPECT_NE((*context)->queue(), VK_NULL_HANDLE);
  ASSERT_NE((*context)->push_descriptor_set, nullptr);
  EXPECT_TRUE((*context)->submit_and_wait([](VkCommandBuffer) {}).ok());
  expect_no_validation_messages(**context);
}

TEST(ContextOptions, RepeatedExtensionsAreEnabledOnce) {
  auto context =
      Context::create({.device_request = "",
                       .validation = Validation::on,
                       .instance_extensions = {VK_EXT_DEBUG_UTILS_EXTENSION_NAME, VK_KHR_SURFACE_EXTENSION_NAME,
                                               VK_KHR_SURFACE_EXTENSION_NAME},
                       .device_extensions = {VK_KHR_SWAPCHAIN_EXTENSION_NAME, VK_KHR_SWAPCHAIN_EXTENSION_NAME,
                                             VK_KHR_PUSH_DESCRIPTOR_EXTENSION_NAME}});
  ASSERT_TRUE(context.ok()) << context.message();
  EXPECT_EQ((*context)->surface(), VK_NULL_HANDLE);
  EXPECT_NE(vkGetDeviceProcAddr((*context)->device(), "vkCreateSwapchainKHR"), nullptr);
  expect_no_validation_messages(**context);
}

TEST(ContextOptions, UnknownInstanceExtensionFailsNamingIt) {
  auto context = Context::create({.device_request = "",
                                  .validation = Validation::on,
                                  .instance_extensions = {"VK_PROXYGI_no_such_instance_extension"}});
  ASSERT_FALSE(context.ok());
  EXPECT_NE(context.message().find("VK_PROXYGI_no_such_instance_extension"), std::string::npos) << context.message();
  EXPECT_NE(context.message().find("the loader offers: "), std::string::npos) << context.message();
  EXPECT_NE(context.message().find(VK_KHR_SURFACE_EXTENSION_NAME), std::string::npos) << context.message();
}

TEST(ContextOptions, UnknownDeviceExtensionFailsNamingIt) {
  auto context = Context::create({.device_request = "",
                                  .validation = Validation::on,
                                  .device_extensions = {"VK_PROXYGI_no_such_device_extension"}});
  ASSERT_FALSE(context.ok());
  EXPECT_NE(context.message().find("lacks VK_PROXYGI_no_such_device_extension"), std::string::npos)
      << context.message();
}

TEST(ContextOptions, SurfaceFactoryErrorFailsCreation) {
  VkInstance seen = VK_NULL_HANDLE;
  auto context = Context::create({.device_request = "",
                                  .validation = Validation::on,
                                  .create_surface = [&](VkInstance instance) -> Result<VkSurfaceKHR> {
                                    seen = instance;
                                    return make_error("window 'viewer' is gone");
                                  }});
  ASSERT_FALSE(context.ok());
  EXPECT_NE(seen, VK_NULL_HANDLE);
  EXPECT_NE(context.message().find("window 'viewer' is gone"), std::string::npos) << context.message();
}

// A surface without a window system (VK_EXT_headless_surface): the queue presents to it, and a
// small swapchain acquires, clears and presents one image.
TEST(ContextOptions, HeadlessSurfaceSwapchainPresentsOneImage) {
  if (!missing_extensions({VK_EXT_HEADLESS_SURFACE_EXTENSION_NAME}, instance_extensions()).empty())
    GTEST_SKIP() << "the Vulkan loader and drivers here do not offer " VK_EXT_HEADLESS_SURFACE_EXTENSION_NAME
                    " (vkEnumerateInstanceExtensionProperties), so there is no surface without a window system";
  auto created = Context::create({.device_request = "",
                                  .validation = Validation::on,
                                  .instance_extensions = {VK_EXT_HEADLESS_SURFACE_EXTENSION_NAME},
                                  .device_extensions = {VK_KHR_SWAPCHAIN_EXTENSION_NAME},
                                  .create_surface = create_headless_surface});
  ASSERT_TRUE(created.ok()) << created.message();
  Context& context = **created;
  const VkSurfaceKHR surface = context.surface();
  ASSERT_NE(surface, VK_NULL_HANDLE);
  EXPECT_TRUE(context.report().present_queue);
  VkBool32 presents = VK_FALSE;
  ASSERT_EQ(vkGetPhysicalDeviceSurfaceSupportKHR(context.physical_device(), context.queue_family(), surface, &presents),
            VK_SUCCESS);
  EXPECT_EQ(presents, VK_TRUE);

  VkSurfaceCapabilitiesKHR capabilities{};
  ASSERT_EQ(vkGetPhysicalDeviceSurfaceCapabilitiesKHR(context.physical_device(), surface, &capabilities), VK_SUCCESS);
  ASSERT_TRUE(capabilities.supportedUsageFlags & VK_IMAGE_USAGE_TRANSFER_DST_BIT);
  std::uint32_t format_count = 0;
  vkGetPhysicalDeviceSurfaceFormatsKHR(context.physical_device(), surface, &format_count, nullptr);
  std::vector<VkSurfaceFormatKHR> formats(format_count);
  vkGetPhysicalDeviceSurfaceFormatsKHR(context.physical_device(), surface, &format_count, formats.data());
  ASSERT_FALSE(formats.empty());

  VkExtent2D extent = capabilities.currentExtent;
  if (extent.width == 0xFFFFFFFFu) {
    extent.width = std::clamp(64u, capabilities.minImageExtent.width, capabilities.maxImageExtent.width);
    extent.height = std::clamp(64u, capabilities.minImageExtent.height, capabilities.maxImageExtent.height);
  }
  std::uint32_t image_count = std::max(2u, capabilities.minImageCount);
  if (capabilities.maxImageCount != 0) image_count = std::min(image_count, capabilities.maxImageCount);
  VkCompositeAlphaFlagBitsKHR alpha = VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR;
  for (auto candidate : {VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR, VK_COMPOSITE_ALPHA_INHERIT_BIT_KHR,
                         VK_COMPOSITE_ALPHA_PRE_MULTIPLIED_BIT_KHR, VK_COMPOSITE_ALPHA_POST_MULTIPLIED_BIT_KHR}) {
    if (capabilities.supportedCompositeAlpha & candidate) {
      alpha = candidate;
      break;
    }
  }

  VkSwapchainCreateInfoKHR info{VK_STRUCTURE_TYPE_SWAPCHAIN_CREATE_INFO_KHR};
  info.surface = surface;
  info.minImageCount = image_count;
  info.imageFormat = formats[0].format;
  info.imageColorSpace = formats[0].colorSpace;
  info.imageExtent = extent;
  info.imageArrayLayers = 1;
  info.imageUsage = VK_IMAGE_USAGE_TRANSFER_DST_BIT;
  info.imageSharingMode = VK_SHARING_MODE_EXCLUSIVE;
  info.preTransform = capabilities.currentTransform;
  info.compositeAlpha = alpha;
  info.presentMode = VK_PRESENT_MODE_FIFO_KHR;
  info.clipped = VK_TRUE;
  VkSwapchainKHR swapchain = VK_NULL_HANDLE;
  ASSERT_EQ(vkCreateSwapchainKHR(context.device(), &info, nullptr, &swapchain), VK_SUCCESS);

  std::uint32_t count = 0;
  vkGetSwapchainImagesKHR(context.device(), swapchain, &count, nullptr);
  std::vector<VkImage> images(count);
  vkGetSwapchainImagesKHR(context.device(), swapchain, &count, images.data());
  ASSERT_GE(count, 1u);

  // Acquired with a fence (waited on), so the clear's submit and the present need no semaphores.
  VkFenceCreateInfo fence_info{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
  VkFence acquired = VK_NULL_HANDLE;
  ASSERT_EQ(vkCreateFence(context.device(), &fence_info, nullptr, &acquired), VK_SUCCESS);
  std::uint32_t index = 0;
  const VkResult acquire =
      vkAcquireNextImageKHR(context.device(), swapchain, UINT64_MAX, VK_NULL_HANDLE, acquired, &index);
  EXPECT_TRUE(acquire == VK_SUCCESS || acquire == VK_SUBOPTIMAL_KHR) << acquire;
  EXPECT_EQ(vkWaitForFences(context.device(), 1, &acquired, VK_TRUE, UINT64_MAX), VK_SUCCESS);
  ASSERT_LT(index, count);

  const VkImage image = images[index];
  const Status cleared = context.submit_and_wait([&](VkCommandBuffer commands) {
    transition(commands, image, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL);
    const VkClearColorValue color{{0.25f, 0.5f, 0.75f, 1.0f}};
    const VkImageSubresourceRange range{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    vkCmdClearColorImage(commands, image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &color, 1, &range);
    transition(commands, image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_PRESENT_SRC_KHR);
  });
  EXPECT_TRUE(cleared.ok()) << cleared.message();

  VkPresentInfoKHR present{VK_STRUCTURE_TYPE_PRESENT_INFO_KHR};
  present.swapchainCount = 1;
  present.pSwapchains = &swapchain;
  present.pImageIndices = &index;
  const VkResult presented = vkQueuePresentKHR(context.queue(), &present);
  EXPECT_TRUE(presented == VK_SUCCESS || presented == VK_SUBOPTIMAL_KHR) << presented;
  EXPECT_EQ(vkQueueWaitIdle(context.queue()), VK_SUCCESS);

  vkDestroyFence(context.device(), acquired, nullptr);
  vkDestroySwapchainKHR(context.device(), swapchain, nullptr);
  expect_no_validation_messages(context);
}

}  // namespace
}  // namespace proxygi::gpu
