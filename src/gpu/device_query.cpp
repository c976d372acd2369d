#include "gpu/device_query.h"

#include <algorithm>

#include "gpu/instance.h"
#include "gpu/vulkan_check.h"

namespace proxygi::gpu {
namespace {

DeviceKind kind_of(VkPhysicalDeviceType type) {
  switch (type) {
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU: return DeviceKind::discrete;
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU: return DeviceKind::integrated;
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU: return DeviceKind::virtual_gpu;
    case VK_PHYSICAL_DEVICE_TYPE_CPU: return DeviceKind::cpu;
    default: return DeviceKind::other;
  }
}

std::vector<VkExtensionProperties> device_extensions(VkPhysicalDevice device) {
  std::uint32_t count = 0;
  vkEnumerateDeviceExtensionProperties(device, nullptr, &count, nullptr);
  std::vector<VkExtensionProperties> extensions(count);
  vkEnumerateDeviceExtensionProperties(device, nullptr, &count, extensions.data());
  extensions.resize(count);
  return extensions;
}

bool presents(VkPhysicalDevice device, std::uint32_t family, VkSurfaceKHR surface) {
  VkBool32 supported = VK_FALSE;
  return vkGetPhysicalDeviceSurfaceSupportKHR(device, family, surface, &supported) == VK_SUCCESS &&
         supported == VK_TRUE;
}

}  // namespace

Result<std::vector<VkPhysicalDevice>> physical_devices(VkInstance instance) {
  std::uint32_t count = 0;
  PROXYGI_VK_TRY(vkEnumeratePhysicalDevices(instance, &count, nullptr));
  std::vector<VkPhysicalDevice> devices(count);
  PROXYGI_VK_TRY(vkEnumeratePhysicalDevices(instance, &count, devices.data()));
  return devices;
}

DeviceReport query_device(VkPhysicalDevice device, int index, const DeviceNeeds& needs) {
  DeviceReport report;
  report.index = index;

  VkPhysicalDeviceSubgroupProperties subgroup{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SUBGROUP_PROPERTIES};
  VkPhysicalDeviceDriverProperties driver{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DRIVER_PROPERTIES};
  driver.pNext = &subgroup;
  VkPhysicalDeviceProperties2 properties{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2};
  properties.pNext = &driver;
  vkGetPhysicalDeviceProperties2(device, &properties);
  const VkPhysicalDeviceProperties& base = properties.properties;
  report.name = base.deviceName;
  report.kind = kind_of(base.deviceType);
  report.api_version = base.apiVersion;
  report.driver = std::string(driver.driverName) + ": " + driver.driverInfo;
  report.max_storage_buffer_range = base.limits.maxStorageBufferRange;
  report.timestamps = base.limits.timestampComputeAndGraphics == VK_TRUE;
  report.timestamp_period_ns = base.limits.timestampPeriod;
  report.subgroup_size = subgroup.subgroupSize;

  VkPhysicalDeviceVulkan13Features features13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
  VkPhysicalDeviceFeatures2 features{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
  if (base.apiVersion >= VK_API_VERSION_1_3) {
    features.pNext = &features13;
    vkGetPhysicalDeviceFeatures2(device, &features);
    report.dynamic_rendering = features13.dynamicRendering == VK_TRUE;
    report.synchronization2 = features13.synchronization2 == VK_TRUE;
  }
  const auto extensions = device_extensions(device);
  report.push_descriptor = missing_extensions({VK_KHR_PUSH_DESCRIPTOR_EXTENSION_NAME}, extensions).empty();
  report.missing_extensions = missing_extensions(needs.extensions, extensions);

  std::uint32_t family_count = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(device, &family_count, nullptr);
  std::vector<VkQueueFamilyProperties> families(family_count);
  vkGetPhysicalDeviceQueueFamilyProperties(device, &family_count, families.data());
  report.needs_present = needs.surface != VK_NULL_HANDLE;
  for (std::uint32_t i = 0; i < family_count; ++i) {
    if (!(families[i].queueFlags & VK_QUEUE_GRAPHICS_BIT) || !(families[i].queueFlags & VK_QUEUE_COMPUTE_BIT)) continue;
    report.graphics_compute_queue = true;
    if (report.queue_family < 0 && (!report.needs_present || presents(device, i, needs.surface)))
      report.queue_family = static_cast<int>(i);
  }
  report.present_queue = report.needs_present && report.queue_family >= 0;

  VkFormatProperties rgba32f{};
  vkGetPhysicalDeviceFormatProperties(device, VK_FORMAT_R32G32B32A32_SFLOAT, &rgba32f);
  report.float32_blend = (rgba32f.optimalTilingFeatures & VK_FORMAT_FEATURE_COLOR_ATTACHMENT_BLEND_BIT) != 0;
  VkFormatProperties rgba16f{};
  vkGetPhysicalDeviceFormatProperties(device, VK_FORMAT_R16G16B16A16_SFLOAT, &rgba16f);
  report.rgba16f_attachment = (rgba16f.optimalTilingFeatures & VK_FORMAT_FEATURE_COLOR_ATTACHMENT_BIT) != 0;

  VkPhysicalDeviceMemoryProperties memory{};
  vkGetPhysicalDeviceMemoryProperties(device, &memory);
  for (std::uint32_t i = 0; i < memory.memoryHeapCount; ++i)
    if (memory.memoryHeaps[i].flags & VK_MEMORY_HEAP_DEVICE_LOCAL_BIT)
      report.device_local_memory = std::max<std::uint64_t>(report.device_local_memory, memory.memoryHeaps[i].size);
  return report;
}

}  // namespace proxygi::gpu
