// proxygi: parse the command line, run one subcommand, return its exit code.
#include <cstdio>
#include <cstdlib>

#include <unistd.h>
#include <fcntl.h>

#include "apps/commands.h"
#include "base/log.h"

#ifndef PROXYGI_ASSETS_DIR
#define PROXYGI_ASSETS_DIR "assets"
#endif
#ifndef PROXYGI_VERSION
#define PROXYGI_VERSION "unknown"
#endif

namespace proxygi::app {

int fail_bad_input(const std::string& message) {
  std::fprintf(stderr, "proxygi: %s\n", message.c_str());
  return kExitBadInput;
}

int fail_runtime(const std::string& message) {
  std::fprintf(stderr, "proxygi: %s\n", message.c_str());
  return kExitFailure;
}

std::filesystem::path assets_dir() {
  if (const char* overridden = std::getenv("PROXYGI_ASSETS")) return overridden;
  return PROXYGI_ASSETS_DIR;
}

namespace {
bool g_quiet = false;
}  // namespace

bool quiet() { return g_quiet; }

void add_quiet_flag(CLI::App& command) {
  command.add_flag("-q,--quiet", g_quiet, "Print only warnings and errors (no progress, no summary; for scripts)");
}

// --quiet: the log goes quiet and stdout to /dev/null, unless the command was asked for --json
// (data on stdout, not information).
void apply_quiet(const CLI::App& app) {
  if (!g_quiet) return;
  set_log_level(LogLevel::quiet);
  const CLI::App* command = &app;
  bool json = false;
  while (true) {
    if (command->get_option_no_throw("--json") != nullptr && command->count("--json") > 0) json = true;
    const auto chosen = command->get_subcommands();
    if (chosen.empty()) break;
    command = chosen.front();
  }
  if (json) return;
  std::fflush(stdout);
  const int null = ::open("/dev/null", O_WRONLY | O_CLOEXEC);
  if (null >= 0) {
    ::dup2(null, STDOUT_FILENO);
    ::close(null);
  }
}

void add_device_option(CLI::App& command, std::string& device) {
  command.add_option("--device", device,
                     "Vulkan device by name substring or index (default: $PROXYGI_DEVICE, else the "
                     "first discrete GPU, integrated GPU, then lavapipe)");
}

}  // namespace proxygi::app

int main(int argc, char** argv) {
  using namespace proxygi::app;
  CLI::App app{"proxygi: soft shadows and bounce light from sphere proxies of animated glTF characters"};
  app.name("proxygi");
  app.set_version_flag("--version", std::string("proxygi ") + PROXYGI_VERSION);
  app.require_subcommand(1);

  CommandRunner runner;
  add_devices_command(app, runner);
  add_info_command(app, runner);
  add_pose_command(app, runner);
  add_mannequin_command(app, runner);
  add_fit_command(app, runner);
  add_compare_command(app, runner);
  add_bench_command(app, runner);
  add_record_command(app, runner);
  add_reference_command(app, runner);
  add_regress_command(app, runner);
  add_view_command(app, runner);
  add_prt_command(app, runner);

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& help) {
    return app.exit(help);
  } catch (const CLI::CallForAllHelp& help) {
    return app.exit(help);
  } catch (const CLI::Success& success) {  // --version
    return app.exit(success);
  } catch (const CLI::ParseError& error) {
    // Name an unknown flag first: CLI11 reports a missing required argument before extras.
    std::string unknown;
    for (const CLI::App* command : app.get_subcommands())
      for (const std::string& extra : command->remaining())
        if (unknown.empty() && extra.size() > 1 && extra[0] == '-') unknown = extra;
    const CLI::App* command = app.get_subcommands().empty() ? &app : app.get_subcommands().front();
    if (app.get_subcommands().empty() && !app.remaining().empty() && app.remaining().front()[0] != '-')
      std::fprintf(stderr, "proxygi: unknown command '%s'\n\n%s", app.remaining().front().c_str(), app.help().c_str());
    else if (!unknown.empty())
      std::fprintf(stderr, "proxygi %s: unknown option '%s'\n\n%s", command->get_name().c_str(), unknown.c_str(),
                   command->help().c_str());
    else
      std::fprintf(stderr, "proxygi: %s\n\n%s", error.what(), command == &app ? app.help().c_str() : command->help().c_str());
    return kExitBadInput;
  }
  if (!runner) return fail_bad_input("no command to run");
  apply_quiet(app);
  return runner();
}
