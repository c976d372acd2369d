#pragma once
// Reads a DeviceReport (see device_report.h) off every physical device of an instance.
#include <vector>

#include <vulkan/vulkan.h>

#include "gpu/device_report.h"

namespace proxygi::gpu {

DeviceReport query_device(VkPhysicalDevice device, int index);
Result<std::vector<VkPhysicalDevice>> physical_devices(VkInstance instance);

}  // namespace proxygi::gpu
