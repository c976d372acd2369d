#include "gpu/device_report.h"

#include <algorithm>
#include <cctype>

namespace proxygi::gpu {
namespace {

int preference_rank(DeviceKind kind) {
  switch (kind) {
    case DeviceKind::discrete: return 0;
    case DeviceKind::integrated: return 1;
    case DeviceKind::virtual_gpu: return 2;
    case DeviceKind::cpu: return 3;
    case DeviceKind::other: return 4;
  }
  return 5;
}

std::string lower(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

bool is_index(const std::string& text) {
  return !text.empty() && std::all_of(text.begin(), text.end(), [](unsigned char c) { return std::isdigit(c); });
}

std::string join(const std::vector<std::string>& parts, const char* separator) {
  std::string out;
  for (const auto& part : parts) out += (out.empty() ? "" : separator) + part;
  return out;
}

}  // namespace

const char* to_string(DeviceKind kind) {
  switch (kind) {
    case DeviceKind::discrete: return "discrete GPU";
    case DeviceKind::integrated: return "integrated GPU";
    case DeviceKind::virtual_gpu: return "virtual GPU";
    case DeviceKind::cpu: return "CPU";
    case DeviceKind::other: return "other";
  }
  return "other";
}

std::string api_version_string(std::uint32_t version) {
  return std::to_string((version >> 22) & 0x7f) + "." + std::to_string((version >> 12) & 0x3ff) + "." +
         std::to_string(version & 0xfff);
}

std::vector<std::string> missing_requirements(const DeviceReport& device) {
  std::vector<std::string> missing;
  if (device.api_version < ((1u << 22) | (2u << 12))) missing.push_back("Vulkan " + api_version_string(device.api_version) + " < 1.2");
  if (!device.graphics_compute_queue) missing.push_back("no queue family with graphics and compute");
  else if (device.needs_present && !device.present_queue)
    missing.push_back("no queue family with graphics and compute that can present to the surface");
  if (!device.dynamic_rendering) missing.push_back("no dynamic rendering");
  if (!device.synchronization2) missing.push_back("no synchronization2");
  if (!device.push_descriptor) missing.push_back("no VK_KHR_push_descriptor");
  if (!device.rgba16f_attachment) missing.push_back("RGBA16F is not a color attachment format");
  if (!device.float32_blend) missing.push_back("no blending on RGBA32F attachments");
  for (const auto& extension : device.missing_extensions) missing.push_back("lacks " + extension);
  return missing;
}

Result<DeviceChoice> choose_device(const std::vector<DeviceReport>& devices, const std::string& request) {
  if (devices.empty()) return make_error("no Vulkan device found (is mesa-vulkan-drivers installed?)");
  DeviceChoice choice;
  std::vector<std::string> usable_reasons(devices.size());
  std::vector<bool> usable(devices.size(), false);
  for (std::size_t i = 0; i < devices.size(); ++i) {
    const auto missing = missing_requirements(devices[i]);
    usable[i] = missing.empty();
    usable_reasons[i] = join(missing, ", ");
  }

  auto reject_others = [&](int chosen, const std::string& why_not_chosen) {
    for (std::size_t i = 0; i < devices.size(); ++i) {
      if (static_cast<int>(i) == chosen) continue;
      choice.rejections.push_back(devices[i].name + ": " + (usable[i] ? why_not_chosen : usable_reasons[i]));
    }
  };

  if (!request.empty()) {
    int match = -1;
    if (is_index(request)) {
      const auto index = std::stoul(request);
      if (index < devices.size()) match = static_cast<int>(index);
    } else {
      for (std::size_t i = 0; i < devices.size() && match < 0; ++i)
        if (lower(devices[i].name).find(lower(request)) != std::string::npos) match = static_cast<int>(i);
    }
    if (match < 0) {
      std::vector<std::string> listing;
      for (const auto& device : devices) listing.push_back(std::to_string(device.index) + ": " + device.name);
      return make_error("no Vulkan device matches '" + request + "' (devices: " + join(listing, "; ") + ")");
    }
    if (!usable[static_cast<std::size_t>(match)])
      return make_error("device '" + devices[static_cast<std::size_t>(match)].name + "' cannot run proxygi: " +
                        usable_reasons[static_cast<std::size_t>(match)]);
    choice.index = match;
    choice.reason = "requested '" + request + "'";
    reject_others(match, "not requested");
    return choice;
  }

  int best = -1;
  for (std::size_t i = 0; i < devices.size(); ++i) {
    if (!usable[i]) continue;
    if (best < 0 || preference_rank(devices[i].kind) < preference_rank(devices[static_cast<std::size_t>(best)].kind))
      best = static_cast<int>(i);
  }
  if (best < 0) {
    std::vector<std::string> listing;
    for (std::size_t i = 0; i < devices.size(); ++i) listing.push_back(devices[i].name + ": " + usable_reasons[i]);
    return make_error("no usable Vulkan device (" + join(listing, "; ") + ")");
  }
  choice.index = best;
  choice.reason = std::string("preferred kind: ") + to_string(devices[static_cast<std::size_t>(best)].kind);
  reject_others(best, std::string("a ") + to_string(devices[static_cast<std::size_t>(best)].kind) + " is preferred");
  return choice;
}

}  // namespace proxygi::gpu
