// proxygi fit: placeholder until its issue lands.
#include "apps/commands.h"

namespace proxygi::app {

void add_fit_command(CLI::App& app, CommandRunner& runner) {
  auto* command = app.add_subcommand("fit", "Fit sphere proxies to each bone of a model");
  command->allow_extras();
  command->callback([&runner] { runner = [] { return fail_runtime("fit: not implemented yet"); }; });
}

}  // namespace proxygi::app
