// proxygi compare: placeholder until its issue lands.
#include "apps/commands.h"

namespace proxygi::app {

void add_compare_command(CLI::App& app, CommandRunner& runner) {
  auto* command = app.add_subcommand("compare", "Compare two images: RMSE, relative MSE, SSIM, FLIP");
  command->allow_extras();
  command->callback([&runner] { runner = [] { return fail_runtime("compare: not implemented yet"); }; });
}

}  // namespace proxygi::app
