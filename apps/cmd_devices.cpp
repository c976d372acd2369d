// proxygi devices [--json]: every Vulkan device with what the project needs of it.
#include "apps/commands.h"

namespace proxygi::app {

void add_devices_command(CLI::App& app, CommandRunner& runner) {
  auto* command = app.add_subcommand("devices", "List Vulkan devices and the capabilities proxygi needs");
  command->callback([&runner] { runner = [] { return fail_runtime("devices: not built yet"); }; });
}

}  // namespace proxygi::app
