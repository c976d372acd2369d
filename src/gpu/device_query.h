#pragma once
// Reads a DeviceReport (see device_report.h) off every physical device of an instance.
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "gpu/device_report.h"

namespace proxygi::gpu {

// What a caller needs beyond proxygi's own requirements.
struct DeviceNeeds {
  VkSurfaceKHR surface = VK_NULL_HANDLE;  // when set, the queue family must present to it
  std::vector<std::string> extensions;    // device extensions that must be offered
};

DeviceReport query_device(VkPhysicalDevice device, int index, const DeviceNeeds& needs = {});
Result<std::vector<VkPhysicalDevice>> physical_devices(VkInstance instance);

}  // namespace proxygi::gpu
