#pragma once
// What proxygi needs to know about a Vulkan physical device, and how one is chosen.
// Selection prefers a discrete GPU, then an integrated GPU, then a virtual GPU, then a CPU
// device (lavapipe); a device lacking a hard requirement is rejected with a reason. With a
// surface, the requirements include a queue family that also presents to it; device extensions
// a caller asks for are requirements too.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "base/result.h"

namespace proxygi::gpu {

enum class DeviceKind { discrete, integrated, virtual_gpu, cpu, other };

struct DeviceReport {
  int index = 0;                 // position in vkEnumeratePhysicalDevices
  std::string name;
  DeviceKind kind = DeviceKind::other;
  std::uint32_t api_version = 0;  // VK_MAKE_API_VERSION layout
  std::string driver;            // driver name and info, e.g. "llvmpipe: Mesa 22.3.6"
  bool graphics_compute_queue = false;   // one queue family with graphics and compute
  bool needs_present = false;            // a surface was given: the queue must present to it
  bool present_queue = false;            // a graphics+compute family presents to that surface
  int queue_family = -1;                 // the first family with graphics and compute (and present
                                         // when needs_present); -1 when there is none
  std::vector<std::string> missing_extensions;  // requested device extensions it lacks
  bool dynamic_rendering = false;        // Vulkan 1.3 core feature (or KHR extension)
  bool synchronization2 = false;
  bool push_descriptor = false;          // VK_KHR_push_descriptor (passes bind without pools)
  bool float32_blend = false;            // RGBA32F color attachment supports blending
  bool rgba16f_attachment = false;
  std::uint64_t max_storage_buffer_range = 0;  // bytes
  bool timestamps = false;               // timestampComputeAndGraphics
  float timestamp_period_ns = 0.0f;
  std::uint32_t subgroup_size = 0;
  std::uint64_t device_local_memory = 0;  // bytes, largest device-local heap
};

const char* to_string(DeviceKind kind);
std::string api_version_string(std::uint32_t version);

// Hard requirements the project cannot run without; empty when the device is usable.
std::vector<std::string> missing_requirements(const DeviceReport& device);

struct DeviceChoice {
  int index = -1;                        // into the reports passed in
  std::string reason;                    // why this one
  std::vector<std::string> rejections;   // "NAME: reason" for every other device
};

// Chooses a device. `request` is empty (automatic), a decimal index, or a case-insensitive
// substring of the device name. Errors list the devices and why none matched.
Result<DeviceChoice> choose_device(const std::vector<DeviceReport>& devices, const std::string& request);

}  // namespace proxygi::gpu
