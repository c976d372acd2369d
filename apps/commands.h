#pragma once
// The proxygi CLI: one file per subcommand, each registering itself on the root app. A command's
// callback stores the work to run in `runner`; main() runs it after parsing and returns its exit
// code. Exit codes: 0 success, 1 runtime failure, 2 usage error or bad input.
#include <filesystem>
#include <functional>
#include <string>

#include <CLI/CLI.hpp>

namespace proxygi::app {

using CommandRunner = std::function<int()>;

inline constexpr int kExitOk = 0;
inline constexpr int kExitFailure = 1;
inline constexpr int kExitBadInput = 2;

// Prints "proxygi: <message>" on stderr and returns kExitBadInput / kExitFailure.
int fail_bad_input(const std::string& message);
int fail_runtime(const std::string& message);

// The folder of the bundled assets (assets/mannequin.glb, scenes): $PROXYGI_ASSETS when set,
// else the source tree's assets/ folder this binary was built from.
std::filesystem::path assets_dir();

// Adds --device NAME|INDEX to a subcommand (falls back to $PROXYGI_DEVICE when not given).
void add_device_option(CLI::App& command, std::string& device);

// Adds -q/--quiet to a subcommand (every command has it). With it, main() silences the library
// log and stdout (except output asked for with --json), and commands skip their progress and
// informational lines on stderr: only warnings and errors print.
void add_quiet_flag(CLI::App& command);
// True when the command being run was given --quiet.
bool quiet();

// Top-level commands, one file each (apps/cmd_<name>.cpp).
void add_devices_command(CLI::App& app, CommandRunner& runner);  // cmd_devices.cpp
void add_info_command(CLI::App& app, CommandRunner& runner);     // cmd_info.cpp
void add_pose_command(CLI::App& app, CommandRunner& runner);     // cmd_pose.cpp
void add_mannequin_command(CLI::App& app, CommandRunner& runner);  // cmd_mannequin.cpp
void add_fit_command(CLI::App& app, CommandRunner& runner);      // cmd_fit.cpp
void add_compare_command(CLI::App& app, CommandRunner& runner);  // cmd_compare.cpp
void add_bench_command(CLI::App& app, CommandRunner& runner);    // cmd_bench.cpp
void add_record_command(CLI::App& app, CommandRunner& runner);   // cmd_record.cpp
void add_reference_command(CLI::App& app, CommandRunner& runner);  // cmd_reference.cpp
void add_regress_command(CLI::App& app, CommandRunner& runner);  // cmd_regress.cpp
void add_view_command(CLI::App& app, CommandRunner& runner);     // cmd_view.cpp
void add_prt_command(CLI::App& app, CommandRunner& runner);      // cmd_prt.cpp

// `proxygi bench <study>` subcommands, one file each (apps/bench_<name>.cpp).
void add_bench_sh_command(CLI::App& bench, CommandRunner& runner);     // bench_sh.cpp
void add_bench_frame_command(CLI::App& bench, CommandRunner& runner);  // bench_frame.cpp
void add_bench_record_command(CLI::App& bench, CommandRunner& runner);  // bench_record.cpp
void add_bench_sampler_command(CLI::App& bench, CommandRunner& runner);  // bench_sampler.cpp
void add_bench_chart_command(CLI::App& bench, CommandRunner& runner);  // bench_chart.cpp
void add_bench_stability_command(CLI::App& bench, CommandRunner& runner);  // bench_stability.cpp

}  // namespace proxygi::app
