#include <gtest/gtest.h>

#include "gpu/device_report.h"

namespace proxygi::gpu {
namespace {

DeviceReport usable_device(int index, std::string name, DeviceKind kind) {
  DeviceReport device;
  device.index = index;
  device.name = std::move(name);
  device.kind = kind;
  device.api_version = (1u << 22) | (3u << 12);
  device.graphics_compute_queue = device.dynamic_rendering = device.synchronization2 = true;
  device.push_descriptor = true;
  device.float32_blend = device.rgba16f_attachment = true;
  return device;
}

TEST(DeviceChoice, PrefersDiscreteThenIntegratedThenCpu) {
  std::vector<DeviceReport> devices = {usable_device(0, "llvmpipe", DeviceKind::cpu),
                                       usable_device(1, "Intel UHD", DeviceKind::integrated),
                                       usable_device(2, "NVIDIA H100", DeviceKind::discrete)};
  auto choice = choose_device(devices, "");
  ASSERT_TRUE(choice.ok()) << choice.message();
  EXPECT_EQ(choice->index, 2);
  ASSERT_EQ(choice->rejections.size(), 2u);
  devices.pop_back();
  EXPECT_EQ(choose_device(devices, "")->index, 1);
  devices.pop_back();
  EXPECT_EQ(choose_device(devices, "")->index, 0);
}

TEST(DeviceChoice, RejectsDeviceMissingRequirementWithReason) {
  std::vector<DeviceReport> devices = {usable_device(0, "llvmpipe", DeviceKind::cpu),
                                       usable_device(1, "Old GPU", DeviceKind::discrete)};
  devices[1].float32_blend = false;
  auto choice = choose_device(devices, "");
  ASSERT_TRUE(choice.ok());
  EXPECT_EQ(choice->index, 0);
  ASSERT_EQ(choice->rejections.size(), 1u);
  EXPECT_NE(choice->rejections[0].find("RGBA32F"), std::string::npos) << choice->rejections[0];
}

TEST(DeviceChoice, RequestByIndexOrNameSubstring) {
  std::vector<DeviceReport> devices = {usable_device(0, "llvmpipe (LLVM 15)", DeviceKind::cpu),
                                       usable_device(1, "NVIDIA H100", DeviceKind::discrete)};
  EXPECT_EQ(choose_device(devices, "0")->index, 0);
  EXPECT_EQ(choose_device(devices, "LLVMPIPE")->index, 0);
  EXPECT_EQ(choose_device(devices, "h100")->index, 1);
  auto missing = choose_device(devices, "radeon");
  ASSERT_FALSE(missing.ok());
  EXPECT_NE(missing.message().find("radeon"), std::string::npos);
  EXPECT_FALSE(choose_device(devices, "7").ok());
  EXPECT_FALSE(choose_device({}, "").ok());
}

TEST(DeviceChoice, WithASurfaceRejectsDeviceWhoseQueuesCannotPresent) {
  std::vector<DeviceReport> devices = {usable_device(0, "llvmpipe", DeviceKind::cpu),
                                       usable_device(1, "Headless GPU", DeviceKind::discrete)};
  for (auto& device : devices) device.needs_present = true;
  devices[0].present_queue = true;
  auto choice = choose_device(devices, "");
  ASSERT_TRUE(choice.ok()) << choice.message();
  EXPECT_EQ(choice->index, 0);
  ASSERT_EQ(choice->rejections.size(), 1u);
  EXPECT_NE(choice->rejections[0].find("present"), std::string::npos) << choice->rejections[0];
  auto requested = choose_device(devices, "headless");
  ASSERT_FALSE(requested.ok());
  EXPECT_NE(requested.message().find("present to the surface"), std::string::npos) << requested.message();
}

TEST(DeviceChoice, RejectsDeviceMissingARequestedExtensionNamingIt) {
  std::vector<DeviceReport> devices = {usable_device(0, "llvmpipe", DeviceKind::cpu)};
  devices[0].missing_extensions = {"VK_KHR_swapchain"};
  auto choice = choose_device(devices, "");
  ASSERT_FALSE(choice.ok());
  EXPECT_NE(choice.message().find("llvmpipe: lacks VK_KHR_swapchain"), std::string::npos) << choice.message();
}

}  // namespace
}  // namespace proxygi::gpu
