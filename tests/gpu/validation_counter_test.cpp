// The zero-message rule only means something if messages are caught: a deliberately invalid
// call (a buffer with no usage flags, VUID-VkBufferCreateInfo-usage-requiredbitmask) must be
// counted. Also reports which device the GPU tests ran on.
#include <gtest/gtest.h>

#include <cstdio>

#include "gpu/context.h"

namespace proxygi::gpu {
namespace {

TEST(ValidationCounter, CountsAnInvalidCall) {
  auto context = Context::create({.device_request = "", .validation = Validation::on});
  ASSERT_TRUE(context.ok()) << context.message();
  std::printf("GPU tests run on: %s (%s)\n", (*context)->report().name.c_str(), (*context)->report().driver.c_str());
  ASSERT_EQ((*context)->validation_message_count(), 0u);

  VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
  info.size = 256;
  info.usage = 0;  // invalid on purpose
  VkBuffer buffer = VK_NULL_HANDLE;
  const VkResult result = vkCreateBuffer((*context)->device(), &info, nullptr, &buffer);
  if (result == VK_SUCCESS) vkDestroyBuffer((*context)->device(), buffer, nullptr);
  EXPECT_GE((*context)->validation_message_count(), 1u);
  const auto messages = (*context)->validation_messages();
  ASSERT_FALSE(messages.empty());
  EXPECT_NE(messages.front().find("usage"), std::string::npos) << messages.front();
}

}  // namespace
}  // namespace proxygi::gpu
