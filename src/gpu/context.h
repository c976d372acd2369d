#pragma once
// Context: a Vulkan device ready for proxygi's passes, headless by default or presenting to a
// surface. It owns the instance (with the validation layer when asked), the surface when one is
// made, the chosen physical device, one queue that does graphics, compute and transfer (and
// presents to the surface, when there is one), and a command pool for one-shot submissions.
//
//   auto context = gpu::Context::create({.device_request = "llvmpipe", .validation = Validation::on});
//   if (!context) return context.error();
//   (*context)->submit_and_wait([&](VkCommandBuffer commands) { ... });
//
// A viewer adds its window system's needs:
//   options.instance_extensions = {names from glfwGetRequiredInstanceExtensions};
//   options.device_extensions = {VK_KHR_SWAPCHAIN_EXTENSION_NAME};
//   options.create_surface = [&](VkInstance instance) -> Result<VkSurfaceKHR> { glfwCreateWindowSurface(...) };
//
// Options:
// - instance_extensions are enabled beside VK_EXT_debug_utils (validation) and VK_KHR_surface
//   (added when create_surface is set); duplicates are dropped. One the loader does not offer
//   fails creation with "Vulkan instance extension NAME is not available (the loader offers: ...)".
// - device_extensions are enabled beside VK_KHR_push_descriptor. A device lacking one is rejected
//   ("NAME: lacks VK_KHR_swapchain"); when no device is left, creation fails with that reason.
// - create_surface is called once, right after the instance exists. Its error fails creation. The
//   surface it returns belongs to the Context from then on: it is destroyed after the device and
//   before the instance (also when creation fails later); callers must not destroy it. Swapchains
//   on it are the caller's, and go before the Context does.
//
// Device choice: ContextOptions::device_request, else $PROXYGI_DEVICE, else automatic
// (discrete > integrated > virtual > CPU), among devices meeting the requirements
// (missing_requirements in device_report.h: with a surface, a queue family that does graphics
// and compute and presents to it, per vkGetPhysicalDeviceSurfaceSupportKHR). The choice and
// every rejection are logged. The queue is the first family of the chosen device that does
// graphics and compute (and presents, with a surface). Without these options the Context is
// headless: no surface extensions, surface() is VK_NULL_HANDLE.
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "base/result.h"
#include "gpu/device_report.h"
#include "gpu/instance.h"

namespace proxygi::gpu {

struct ContextOptions {
  std::string device_request;  // name substring or index; empty: $PROXYGI_DEVICE, then automatic
  Validation validation = Validation::build_default;
  std::vector<std::string> instance_extensions;  // e.g. glfwGetRequiredInstanceExtensions()
  std::vector<std::string> device_extensions;    // e.g. VK_KHR_swapchain
  // Makes the surface to present to (e.g. with glfwCreateWindowSurface); empty: headless.
  std::function<Result<VkSurfaceKHR>(VkInstance)> create_surface;
};

class Context {
 public:
  static Result<std::unique_ptr<Context>> create(const ContextOptions& options);
  ~Context();
  Context(const Context&) = delete;
  Context& operator=(const Context&) = delete;

  VkInstance instance() const { return instance_->handle(); }
  VkSurfaceKHR surface() const { return surface_; }  // VK_NULL_HANDLE when headless
  VkPhysicalDevice physical_device() const { return physical_device_; }
  VkDevice device() const { return device_; }
  VkQueue queue() const { return queue_; }
  std::uint32_t queue_family() const { return queue_family_; }
  const DeviceReport& report() const { return report_; }
  const VkPhysicalDeviceLimits& limits() const { return limits_; }

  bool validation_enabled() const { return instance_->validation(); }
  // Validation-layer warnings and errors seen so far (tests require zero).
  std::size_t validation_message_count() const { return instance_->validation_log().count(); }
  std::vector<std::string> validation_messages() const { return instance_->validation_log().messages(); }

  // Records into a fresh primary command buffer, submits it, and waits for the fence.
  Status submit_and_wait(const std::function<void(VkCommandBuffer)>& record);

  // A command buffer and fence for work that runs while the CPU goes on (frames in flight).
  class InFlight {
   public:
    InFlight() = default;
    ~InFlight();
    InFlight(InFlight&& other) noexcept;
    InFlight& operator=(InFlight&& other) noexcept;
    InFlight(const InFlight&) = delete;
    InFlight& operator=(const InFlight&) = delete;
    // Waits for the previous submission (if any), records into the reused command buffer, submits.
    Status submit(const std::function<void(VkCommandBuffer)>& record);
    Status wait();  // no-op when nothing is pending
    bool pending() const { return pending_; }

   private:
    friend class Context;
    void release();
    Context* context_ = nullptr;
    VkCommandBuffer commands_ = VK_NULL_HANDLE;
    VkFence fence_ = VK_NULL_HANDLE;
    bool pending_ = false;
  };
  Result<InFlight> create_in_flight();

  // Index of a memory type allowed by type_bits with all `required` flags.
  Result<std::uint32_t> find_memory_type(std::uint32_t type_bits, VkMemoryPropertyFlags required) const;

  // Debug labels (VK_EXT_debug_utils) when validation is on; no-ops otherwise.
  void begin_label(VkCommandBuffer commands, const char* name) const;
  void end_label(VkCommandBuffer commands) const;

  PFN_vkCmdPushDescriptorSetKHR push_descriptor_set = nullptr;

 private:
  Context() = default;
  std::unique_ptr<Instance> instance_;
  VkSurfaceKHR surface_ = VK_NULL_HANDLE;
  VkPhysicalDevice physical_device_ = VK_NULL_HANDLE;
  VkDevice device_ = VK_NULL_HANDLE;
  VkQueue queue_ = VK_NULL_HANDLE;
  std::uint32_t queue_family_ = 0;
  VkCommandPool command_pool_ = VK_NULL_HANDLE;
  DeviceReport report_;
  VkPhysicalDeviceLimits limits_{};
  VkPhysicalDeviceMemoryProperties memory_properties_{};
  PFN_vkCmdBeginDebugUtilsLabelEXT begin_label_ = nullptr;
  PFN_vkCmdEndDebugUtilsLabelEXT end_label_ = nullptr;
};

// Every device of a fresh instance (for `proxygi devices`), without creating a VkDevice.
Result<std::vector<DeviceReport>> list_devices();

}  // namespace proxygi::gpu
