// proxygi devices [--json]: every Vulkan device with what the project needs of it, and which one
// automatic selection (or --device / $PROXYGI_DEVICE) would choose.
#include <cstdio>
#include <cstdlib>

#include <nlohmann/json.hpp>

#include "apps/commands.h"
#include "gpu/context.h"

namespace proxygi::app {
namespace {

std::string mebibytes(std::uint64_t bytes) { return std::to_string(bytes >> 20) + " MiB"; }

int run_devices(bool json, const std::string& device_request) {
  auto devices = gpu::list_devices();
  if (!devices) return fail_runtime(devices.message());
  std::string request = device_request;
  if (request.empty())
    if (const char* value = std::getenv("PROXYGI_DEVICE")) request = value;
  auto choice = gpu::choose_device(*devices, request);

  if (json) {
    nlohmann::json out;
    out["devices"] = nlohmann::json::array();
    for (const auto& device : *devices) {
      const auto missing = gpu::missing_requirements(device);
      out["devices"].push_back({
          {"index", device.index},
          {"name", device.name},
          {"kind", gpu::to_string(device.kind)},
          {"api_version", gpu::api_version_string(device.api_version)},
          {"driver", device.driver},
          {"float32_blend", device.float32_blend},
          {"max_storage_buffer_range", device.max_storage_buffer_range},
          {"timestamps", device.timestamps},
          {"timestamp_period_ns", device.timestamp_period_ns},
          {"subgroup_size", device.subgroup_size},
          {"device_local_memory", device.device_local_memory},
          {"usable", missing.empty()},
          {"missing", missing},
      });
    }
    out["chosen"] = choice ? nlohmann::json(choice->index) : nlohmann::json(nullptr);
    out["reason"] = choice ? choice->reason : choice.message();
    std::printf("%s\n", out.dump(2).c_str());
    return choice ? kExitOk : (request.empty() ? kExitFailure : kExitBadInput);
  }

  for (const auto& device : *devices) {
    const auto missing = gpu::missing_requirements(device);
    const bool chosen = choice && choice->index == device.index;
    std::printf("%s[%d] %s (%s, Vulkan %s)\n", chosen ? "* " : "  ", device.index, device.name.c_str(),
                gpu::to_string(device.kind), gpu::api_version_string(device.api_version).c_str());
    std::printf("      driver: %s\n", device.driver.c_str());
    std::printf("      float32 blending on RGBA32F: %s\n", device.float32_blend ? "yes" : "no");
    std::printf("      max storage buffer range: %s\n", mebibytes(device.max_storage_buffer_range).c_str());
    std::printf("      timestamps: %s (period %.3g ns)\n", device.timestamps ? "yes" : "no",
                double(device.timestamp_period_ns));
    std::printf("      subgroup size: %u\n", device.subgroup_size);
    std::printf("      device-local memory: %s\n", mebibytes(device.device_local_memory).c_str());
    if (!missing.empty())
      for (const auto& reason : missing) std::printf("      unusable: %s\n", reason.c_str());
  }
  if (!choice) return request.empty() ? fail_runtime(choice.message()) : fail_bad_input(choice.message());
  std::printf("chosen: [%d] %s (%s)\n", choice->index, (*devices)[std::size_t(choice->index)].name.c_str(),
              choice->reason.c_str());
  return kExitOk;
}

}  // namespace

void add_devices_command(CLI::App& app, CommandRunner& runner) {
  auto* command = app.add_subcommand("devices", "List Vulkan devices and the capabilities proxygi needs");
  auto json = std::make_shared<bool>(false);
  auto device = std::make_shared<std::string>();
  command->add_flag("--json", *json, "Machine-readable output");
  add_device_option(*command, *device);
  add_quiet_flag(*command);
  command->callback([&runner, json, device] { runner = [json, device] { return run_devices(*json, *device); }; });
}

}  // namespace proxygi::app
