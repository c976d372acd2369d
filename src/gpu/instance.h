#pragma once
// The Vulkan instance: headless by default (no surface extensions), or with the extensions a
// caller names (a window system's surface extensions, say), and an optional validation layer
// whose messages are counted: tests fail on any message, so every one is kept for the report.
#include <atomic>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "base/result.h"

namespace proxygi::gpu {

// Validation on: explicitly requested, or $PROXYGI_VALIDATION=1, or a debug build (no NDEBUG).
// $PROXYGI_VALIDATION=0 turns the default off; an explicit request always wins.
enum class Validation { build_default, on, off };
bool resolve_validation(Validation requested);

// Collects validation-layer messages (warnings and errors) from the debug messenger.
class ValidationLog {
 public:
  void add(std::string message);
  std::size_t count() const { return count_.load(); }
  std::vector<std::string> messages() const;

 private:
  std::atomic<std::size_t> count_{0};
  mutable std::mutex mutex_;
  std::vector<std::string> messages_;
};

// Extension name lists (instance or device): `names` with each of `more` appended unless it is
// already there, in order.
std::vector<std::string> merge_extensions(std::vector<std::string> names, const std::vector<std::string>& more);
// Instance extensions that the loader and its drivers offer, plus those of `layer` when given.
std::vector<VkExtensionProperties> instance_extensions(const char* layer = nullptr);
// The names in `wanted` that `available` (from vkEnumerate*ExtensionProperties) lacks.
std::vector<std::string> missing_extensions(const std::vector<std::string>& wanted,
                                            const std::vector<VkExtensionProperties>& available);

class Instance {
 public:
  // Creates the instance; with validation the Khronos layer must be installed
  // (Debian: vulkan-validationlayers), else this fails naming the package. `extensions` are
  // enabled beside VK_EXT_debug_utils (added with validation; duplicates are dropped); one the
  // loader does not offer fails naming it and listing what the loader offers.
  static Result<std::unique_ptr<Instance>> create(bool validation, const std::vector<std::string>& extensions = {});
  ~Instance();
  Instance(const Instance&) = delete;
  Instance& operator=(const Instance&) = delete;

  VkInstance handle() const { return instance_; }
  bool validation() const { return messenger_ != VK_NULL_HANDLE; }
  const ValidationLog& validation_log() const { return log_; }

 private:
  Instance() = default;
  VkInstance instance_ = VK_NULL_HANDLE;
  VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
  ValidationLog log_;
};

}  // namespace proxygi::gpu
