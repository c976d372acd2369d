#include "gpu/instance.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "base/log.h"
#include "gpu/vulkan_check.h"

namespace proxygi::gpu {
namespace {

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";

VKAPI_ATTR VkBool32 VKAPI_CALL on_debug_message(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                VkDebugUtilsMessageTypeFlagsEXT,
                                                const VkDebugUtilsMessengerCallbackDataEXT* data, void* user) {
  if (severity < VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT) return VK_FALSE;
  std::string message = data && data->pMessage ? data->pMessage : "(no message)";
  std::fprintf(stderr, "vulkan validation: %s\n", message.c_str());
  static_cast<ValidationLog*>(user)->add(std::move(message));
  return VK_FALSE;
}

bool layer_available(const char* name) {
  std::uint32_t count = 0;
  vkEnumerateInstanceLayerProperties(&count, nullptr);
  std::vector<VkLayerProperties> layers(count);
  vkEnumerateInstanceLayerProperties(&count, layers.data());
  for (const auto& layer : layers)
    if (std::strcmp(layer.layerName, name) == 0) return true;
  return false;
}

}  // namespace

std::vector<VkExtensionProperties> instance_extensions(const char* layer) {
  auto list = [](const char* source) {
    std::uint32_t count = 0;
    vkEnumerateInstanceExtensionProperties(source, &count, nullptr);
    std::vector<VkExtensionProperties> extensions(count);
    vkEnumerateInstanceExtensionProperties(source, &count, extensions.data());
    extensions.resize(count);
    return extensions;
  };
  auto all = list(nullptr);
  if (layer) {
    const auto more = list(layer);
    all.insert(all.end(), more.begin(), more.end());
  }
  return all;
}

std::vector<std::string> merge_extensions(std::vector<std::string> names, const std::vector<std::string>& more) {
  for (const auto& name : more)
    if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
  return names;
}

std::vector<std::string> missing_extensions(const std::vector<std::string>& wanted,
                                            const std::vector<VkExtensionProperties>& available) {
  std::vector<std::string> missing;
  for (const auto& name : wanted) {
    const bool found = std::any_of(available.begin(), available.end(), [&](const VkExtensionProperties& extension) {
      return name == extension.extensionName;
    });
    if (!found) missing.push_back(name);
  }
  return missing;
}

namespace {

// "A, B, C": each name once (the loader and a layer may both offer one).
std::string join_names(const std::vector<VkExtensionProperties>& extensions) {
  std::vector<std::string> names;
  for (const auto& extension : extensions) names.push_back(extension.extensionName);
  std::string out;
  for (const auto& name : merge_extensions({}, names)) out += (out.empty() ? "" : ", ") + name;
  return out;
}

}  // namespace

bool resolve_validation(Validation requested) {
  if (requested == Validation::on) return true;
  if (requested == Validation::off) return false;
  if (const char* value = std::getenv("PROXYGI_VALIDATION")) return std::strcmp(value, "0") != 0;
#ifdef NDEBUG
  return false;
#else
  return true;
#endif
}

void ValidationLog::add(std::string message) {
  std::lock_guard lock(mutex_);
  messages_.push_back(std::move(message));
  count_.fetch_add(1);
}

std::vector<std::string> ValidationLog::messages() const {
  std::lock_guard lock(mutex_);
  return messages_;
}

Result<std::unique_ptr<Instance>> Instance::create(bool validation, const std::vector<std::string>& extensions) {
  if (validation && !layer_available(kValidationLayer))
    return make_error(std::string("validation requested but ") + kValidationLayer +
                      " is not installed (Debian package vulkan-validationlayers)");
  const auto names = merge_extensions(
      validation ? std::vector<std::string>{VK_EXT_DEBUG_UTILS_EXTENSION_NAME} : std::vector<std::string>{},
      extensions);
  const auto available = instance_extensions(validation ? kValidationLayer : nullptr);
  if (const auto missing = missing_extensions(names, available); !missing.empty())
    return make_error("Vulkan instance extension " + missing.front() +
                      " is not available (the loader offers: " + join_names(available) + ")");

  std::unique_ptr<Instance> instance(new Instance());
  VkApplicationInfo application{VK_STRUCTURE_TYPE_APPLICATION_INFO};
  application.pApplicationName = "proxygi";
  application.pEngineName = "proxygi";
  application.apiVersion = VK_API_VERSION_1_3;

  std::vector<const char*> layers;
  std::vector<const char*> enabled;
  for (const auto& name : names) enabled.push_back(name.c_str());
  VkDebugUtilsMessengerCreateInfoEXT messenger_info{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
  messenger_info.messageSeverity =
      VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
  messenger_info.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                               VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                               VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
  messenger_info.pfnUserCallback = on_debug_message;
  messenger_info.pUserData = &instance->log_;
  if (validation) layers.push_back(kValidationLayer);

  VkInstanceCreateInfo create{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
  create.pApplicationInfo = &application;
  create.enabledLayerCount = static_cast<std::uint32_t>(layers.size());
  create.ppEnabledLayerNames = layers.data();
  create.enabledExtensionCount = static_cast<std::uint32_t>(enabled.size());
  create.ppEnabledExtensionNames = enabled.data();
  if (validation) create.pNext = &messenger_info;  // also reports instance creation itself
  PROXYGI_VK_TRY(vkCreateInstance(&create, nullptr, &instance->instance_));

  if (validation) {
    auto create_messenger = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance->instance_, "vkCreateDebugUtilsMessengerEXT"));
    if (!create_messenger) return make_error("vkCreateDebugUtilsMessengerEXT is not available");
    PROXYGI_VK_TRY(create_messenger(instance->instance_, &messenger_info, nullptr, &instance->messenger_));
    log_debug("vulkan: validation layer on");
  }
  return instance;
}

Instance::~Instance() {
  if (messenger_ != VK_NULL_HANDLE) {
    auto destroy_messenger = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance_, "vkDestroyDebugUtilsMessengerEXT"));
    if (destroy_messenger) destroy_messenger(instance_, messenger_, nullptr);
  }
  if (instance_ != VK_NULL_HANDLE) vkDestroyInstance(instance_, nullptr);
}

}  // namespace proxygi::gpu
