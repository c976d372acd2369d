// proxygi info: placeholder until its issue lands.
#include "apps/commands.h"

namespace proxygi::app {

void add_info_command(CLI::App& app, CommandRunner& runner) {
  auto* command = app.add_subcommand("info", "Describe a glTF model: nodes, joints, skins, meshes, materials, clips");
  command->allow_extras();
  command->callback([&runner] { runner = [] { return fail_runtime("info: not implemented yet"); }; });
}

}  // namespace proxygi::app
