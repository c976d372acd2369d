#include "gpu/context.h"

#include <cstdlib>
#include <utility>

#include "base/log.h"
#include "gpu/device_query.h"
#include "gpu/vulkan_check.h"

namespace proxygi::gpu {
namespace {

std::string requested_device(const ContextOptions& options) {
  if (!options.device_request.empty()) return options.device_request;
  if (const char* value = std::getenv("PROXYGI_DEVICE")) return value;
  return {};
}

std::vector<DeviceReport> reports_of(const std::vector<VkPhysicalDevice>& devices, const DeviceNeeds& needs = {}) {
  std::vector<DeviceReport> reports;
  for (std::size_t i = 0; i < devices.size(); ++i)
    reports.push_back(query_device(devices[i], static_cast<int>(i), needs));
  return reports;
}

}  // namespace

Result<std::vector<DeviceReport>> list_devices() {
  auto instance = Instance::create(false);
  if (!instance) return instance.error();
  auto devices = physical_devices((*instance)->handle());
  if (!devices) return devices.error();
  return reports_of(*devices);
}

Result<std::unique_ptr<Context>> Context::create(const ContextOptions& options) {
  std::unique_ptr<Context> context(new Context());
  const auto instance_extension_names =
      options.create_surface ? merge_extensions(options.instance_extensions, {VK_KHR_SURFACE_EXTENSION_NAME})
                             : options.instance_extensions;
  auto instance = Instance::create(resolve_validation(options.validation), instance_extension_names);
  if (!instance) return instance.error();
  context->instance_ = std::move(*instance);

  if (options.create_surface) {
    auto surface = options.create_surface(context->instance());
    if (!surface) return make_error("creating the Vulkan surface: " + surface.message());
    if (*surface == VK_NULL_HANDLE) return make_error("creating the Vulkan surface: the factory returned no surface");
    context->surface_ = *surface;
  }

  auto devices = physical_devices(context->instance());
  if (!devices) return devices.error();
  const auto reports = reports_of(*devices, {.surface = context->surface_, .extensions = options.device_extensions});
  auto choice = choose_device(reports, requested_device(options));
  if (!choice) return choice.error();

  const auto chosen = static_cast<std::size_t>(choice->index);
  context->physical_device_ = (*devices)[chosen];
  context->report_ = reports[chosen];
  log_info("vulkan: using " + context->report_.name + " (" + context->report_.driver + "; " + choice->reason + ")");
  for (const auto& rejection : choice->rejections) log_info("vulkan: not using " + rejection);

  VkPhysicalDeviceProperties properties{};
  vkGetPhysicalDeviceProperties(context->physical_device_, &properties);
  context->limits_ = properties.limits;
  vkGetPhysicalDeviceMemoryProperties(context->physical_device_, &context->memory_properties_);

  context->queue_family_ = static_cast<std::uint32_t>(context->report_.queue_family);  // >= 0: a requirement

  const float priority = 1.0f;
  VkDeviceQueueCreateInfo queue_info{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
  queue_info.queueFamilyIndex = context->queue_family_;
  queue_info.queueCount = 1;
  queue_info.pQueuePriorities = &priority;

  VkPhysicalDeviceVulkan13Features features13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
  features13.dynamicRendering = VK_TRUE;
  features13.synchronization2 = VK_TRUE;
  VkPhysicalDeviceVulkan12Features features12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES};
  features12.pNext = &features13;
  VkPhysicalDeviceFeatures2 features{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
  features.pNext = &features12;
  const auto extension_names = merge_extensions({VK_KHR_PUSH_DESCRIPTOR_EXTENSION_NAME}, options.device_extensions);
  std::vector<const char*> extensions;
  for (const auto& name : extension_names) extensions.push_back(name.c_str());

  VkDeviceCreateInfo device_info{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
  device_info.pNext = &features;
  device_info.queueCreateInfoCount = 1;
  device_info.pQueueCreateInfos = &queue_info;
  device_info.enabledExtensionCount = static_cast<std::uint32_t>(extensions.size());
  device_info.ppEnabledExtensionNames = extensions.data();
  PROXYGI_VK_TRY(vkCreateDevice(context->physical_device_, &device_info, nullptr, &context->device_));
  vkGetDeviceQueue(context->device_, context->queue_family_, 0, &context->queue_);

  VkCommandPoolCreateInfo pool_info{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
  pool_info.flags = VK_COMMAND_POOL_CREATE_TRANSIENT_BIT | VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
  pool_info.queueFamilyIndex = context->queue_family_;
  PROXYGI_VK_TRY(vkCreateCommandPool(context->device_, &pool_info, nullptr, &context->command_pool_));

  context->push_descriptor_set = reinterpret_cast<PFN_vkCmdPushDescriptorSetKHR>(
      vkGetDeviceProcAddr(context->device_, "vkCmdPushDescriptorSetKHR"));
  if (!context->push_descriptor_set) return make_error("vkCmdPushDescriptorSetKHR is not available");
  if (context->validation_enabled()) {
    context->begin_label_ = reinterpret_cast<PFN_vkCmdBeginDebugUtilsLabelEXT>(
        vkGetInstanceProcAddr(context->instance(), "vkCmdBeginDebugUtilsLabelEXT"));
    context->end_label_ = reinterpret_cast<PFN_vkCmdEndDebugUtilsLabelEXT>(
        vkGetInstanceProcAddr(context->instance(), "vkCmdEndDebugUtilsLabelEXT"));
  }
  return context;
}

Context::~Context() {
  if (device_ != VK_NULL_HANDLE) {
    vkDeviceWaitIdle(device_);
    if (command_pool_ != VK_NULL_HANDLE) vkDestroyCommandPool(device_, command_pool_, nullptr);
    vkDestroyDevice(device_, nullptr);
  }
  if (surface_ != VK_NULL_HANDLE) vkDestroySurfaceKHR(instance(), surface_, nullptr);
}

Status Context::submit_and_wait(const std::function<void(VkCommandBuffer)>& record) {
  VkCommandBufferAllocateInfo allocate{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
  allocate.commandPool = command_pool_;
  allocate.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  allocate.commandBufferCount = 1;
  VkCommandBuffer commands = VK_NULL_HANDLE;
  PROXYGI_VK_TRY(vkAllocateCommandBuffers(device_, &allocate, &commands));
  struct FreeOnExit {
    VkDevice device;
    VkCommandPool pool;
    VkCommandBuffer commands;
    VkFence fence = VK_NULL_HANDLE;
    ~FreeOnExit() {
      if (fence != VK_NULL_HANDLE) vkDestroyFence(device, fence, nullptr);
      vkFreeCommandBuffers(device, pool, 1, &commands);
    }
  } cleanup{device_, command_pool_, commands};

  VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  PROXYGI_VK_TRY(vkBeginCommandBuffer(commands, &begin));
  record(commands);
  PROXYGI_VK_TRY(vkEndCommandBuffer(commands));

  VkFenceCreateInfo fence_info{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
  PROXYGI_VK_TRY(vkCreateFence(device_, &fence_info, nullptr, &cleanup.fence));
  VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
  submit.commandBufferCount = 1;
  submit.pCommandBuffers = &commands;
  PROXYGI_VK_TRY(vkQueueSubmit(queue_, 1, &submit, cleanup.fence));
  PROXYGI_VK_TRY(vkWaitForFences(device_, 1, &cleanup.fence, VK_TRUE, UINT64_MAX));
  return {};
}

Result<Context::InFlight> Context::create_in_flight() {
  InFlight slot;
  slot.context_ = this;
  VkCommandBufferAllocateInfo allocate{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
  allocate.commandPool = command_pool_;
  allocate.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  allocate.commandBufferCount = 1;
  PROXYGI_VK_TRY(vkAllocateCommandBuffers(device_, &allocate, &slot.commands_));
  VkFenceCreateInfo fence_info{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
  PROXYGI_VK_TRY(vkCreateFence(device_, &fence_info, nullptr, &slot.fence_));
  return slot;
}

Status Context::InFlight::wait() {
  if (!pending_) return {};
  PROXYGI_VK_TRY(vkWaitForFences(context_->device_, 1, &fence_, VK_TRUE, UINT64_MAX));
  PROXYGI_VK_TRY(vkResetFences(context_->device_, 1, &fence_));
  pending_ = false;
  return {};
}

Status Context::InFlight::submit(const std::function<void(VkCommandBuffer)>& record) {
  if (Status waited = wait(); !waited) return waited;
  PROXYGI_VK_TRY(vkResetCommandBuffer(commands_, 0));
  VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  PROXYGI_VK_TRY(vkBeginCommandBuffer(commands_, &begin));
  record(commands_);
  PROXYGI_VK_TRY(vkEndCommandBuffer(commands_));
  VkSubmitInfo submit_info{VK_STRUCTURE_TYPE_SUBMIT_INFO};
  submit_info.commandBufferCount = 1;
  submit_info.pCommandBuffers = &commands_;
  PROXYGI_VK_TRY(vkQueueSubmit(context_->queue_, 1, &submit_info, fence_));
  pending_ = true;
  return {};
}

void Context::InFlight::release() {
  if (!context_) return;
  if (pending_) vkWaitForFences(context_->device_, 1, &fence_, VK_TRUE, UINT64_MAX);
  if (fence_ != VK_NULL_HANDLE) vkDestroyFence(context_->device_, fence_, nullptr);
  if (commands_ != VK_NULL_HANDLE) vkFreeCommandBuffers(context_->device_, context_->command_pool_, 1, &commands_);
  context_ = nullptr;
  fence_ = VK_NULL_HANDLE;
  commands_ = VK_NULL_HANDLE;
  pending_ = false;
}

Context::InFlight::~InFlight() { release(); }
Context::InFlight::InFlight(InFlight&& other) noexcept { *this = std::move(other); }
Context::InFlight& Context::InFlight::operator=(InFlight&& other) noexcept {
  if (this != &other) {
    release();
    context_ = std::exchange(other.context_, nullptr);
    commands_ = std::exchange(other.commands_, VK_NULL_HANDLE);
    fence_ = std::exchange(other.fence_, VK_NULL_HANDLE);
    pending_ = std::exchange(other.pending_, false);
  }
  return *this;
}

Result<std::uint32_t> Context::find_memory_type(std::uint32_t type_bits, VkMemoryPropertyFlags required) const {
  for (std::uint32_t i = 0; i < memory_properties_.memoryTypeCount; ++i)
    if ((type_bits & (1u << i)) && (memory_properties_.memoryTypes[i].propertyFlags & required) == required) return i;
  return make_error("no Vulkan memory type with flags " + std::to_string(required) + " for type bits " +
                    std::to_string(type_bits));
}

void Context::begin_label(VkCommandBuffer commands, const char* name) const {
  if (!begin_label_) return;
  VkDebugUtilsLabelEXT label{VK_STRUCTURE_TYPE_DEBUG_UTILS_LABEL_EXT};
  label.pLabelName = name;
  begin_label_(commands, &label);
}

void Context::end_label(VkCommandBuffer commands) const {
  if (end_label_) end_label_(commands);
}

}  // namespace proxygi::gpu
