// proxygi pose: placeholder until its issue lands.
#include "apps/commands.h"

namespace proxygi::app {

void add_pose_command(CLI::App& app, CommandRunner& runner) {
  auto* command = app.add_subcommand("pose", "Write every mesh of a model, skinned at one time, as OBJ or PLY");
  command->allow_extras();
  command->callback([&runner] { runner = [] { return fail_runtime("pose: not implemented yet"); }; });
}

}  // namespace proxygi::app
