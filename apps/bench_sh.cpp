// proxygi bench sh: placeholder until the SH issue lands.
#include "apps/commands.h"

namespace proxygi::app {

void add_bench_sh_command(CLI::App& bench, CommandRunner& runner) {
  auto* command = bench.add_subcommand("sh", "Accuracy and cost of every SH exponential and indirect operator");
  command->allow_extras();
  command->callback([&runner] { runner = [] { return fail_runtime("bench sh: not implemented yet"); }; });
}

}  // namespace proxygi::app
