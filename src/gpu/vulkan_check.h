#pragma once
// Turning VkResult into Status: PROXYGI_VK_TRY(call) returns an Error naming the call and the
// VkResult from the enclosing function (which must return Status or Result<T>).
#include <string>

#include <vulkan/vulkan.h>

#include "base/result.h"

namespace proxygi::gpu {

// Name of a VkResult (Debian 12's Vulkan headers lack vk_enum_string_helper.h).
const char* result_name(VkResult result);

inline Error vulkan_error(const char* call, VkResult result) {
  return make_error(std::string(call) + " failed: " + result_name(result));
}

}  // namespace proxygi::gpu

#define PROXYGI_VK_TRY(call)                                                  \
  do {                                                                        \
    const VkResult proxygi_vk_result_ = (call);                               \
    if (proxygi_vk_result_ != VK_SUCCESS)                                     \
      return ::proxygi::gpu::vulkan_error(#call, proxygi_vk_result_);         \
  } while (0)
