// proxygi regress SCENARIO...|DIR [--filter S] [--shard I/N] [--bless CHECK...] [--report DIR]
//                 [--goldens DIR] [--calibrate N [--write]] [--sensitivity] [--device NAME|INDEX]
// proxygi regress --merge SHARD_DIR... --report DIR
// Exit 0: every check passed (or was skipped or blessed); 1: a check failed, has no golden or
// errored; 2: bad input (unreadable scenario, bad flag). The runner is src/regress.
#include <cstdio>
#include <memory>

#include "apps/commands.h"
#include "base/atomic_file.h"
#include "gpu/context.h"
#include "regress/report.h"
#include "regress/runner.h"
#include "regress/tolerance_study.h"

namespace proxygi::app {
namespace {

struct RegressArgs {
  std::vector<std::string> inputs;
  std::vector<std::string> filters;
  std::string shard;
  std::vector<std::string> bless;
  std::string report;
  std::string goldens;
  int calibrate = 0;
  bool write = false;
  bool sensitivity = false;
  std::vector<std::string> merge;
  std::string device;
};

int run_merge(const RegressArgs& args) {
  if (args.report.empty()) return fail_bad_input("regress --merge needs --report DIR");
  std::vector<regress::RunResults> shards;
  for (const std::string& dir : args.merge) {
    auto bytes = read_file(std::filesystem::path(dir) / "results.json", 1u << 30);
    if (!bytes) return fail_bad_input(bytes.message());
    auto parsed = regress::results_from_json(std::string_view(reinterpret_cast<const char*>(bytes->data()), bytes->size()),
                                             dir + "/results.json");
    if (!parsed) return fail_bad_input(parsed.message());
    // timings.json (budget times) is optional: shard folders from before it existed still merge.
    const auto timings_path = std::filesystem::path(dir) / "timings.json";
    if (std::error_code e; std::filesystem::exists(timings_path, e)) {
      auto timings = read_file(timings_path, 1u << 28);
      if (!timings) return fail_bad_input(timings.message());
      if (Status s = regress::attach_timings(std::string_view(reinterpret_cast<const char*>(timings->data()), timings->size()),
                                             timings_path.string(), *parsed);
          !s)
        return fail_bad_input(s.message());
    }
    shards.push_back(std::move(*parsed));
  }
  auto merged = regress::merge_results(shards);
  if (!merged) return fail_bad_input(merged.message());
  if (Status s = regress::write_reports(*merged, args.report); !s) return fail_runtime(s.message());
  std::printf("merged %zu shards: %zu checks -> %s\n", shards.size(), merged->checks.size(), args.report.c_str());
  return merged->exit_code();
}

void print_result(const regress::CheckResult& c, double seconds) {
  std::printf("%-8s %s/%s (%s, %.1f s): %s\n", std::string(regress::outcome_name(c.outcome)).c_str(), c.scenario.c_str(),
              c.check.c_str(), c.type.c_str(), seconds, c.message.c_str());
  for (std::size_t i = 0; i < c.details.size() && i < 5; ++i) std::printf("           %s\n", c.details[i].c_str());
  if (!c.timings_ms.empty()) {
    std::printf("           measured: median %.1f ms per frame (runs:", regress::median_ms(c.timings_ms));
    for (double ms : c.timings_ms) std::printf(" %.1f", ms);
    std::printf(")\n");
  }
  if (regress::is_failure(c.outcome)) std::printf("           bless: %s\n", c.bless_command().c_str());
  std::fflush(stdout);
}

// Prints a Markdown table and keeps it as REPORT/name when a report folder is given.
Status print_table(const std::string& table, const std::string& report, const char* name) {
  std::printf("%s", table.c_str());
  if (report.empty()) return {};
  std::error_code error;
  std::filesystem::create_directories(report, error);
  if (error) return make_error(report + ": " + error.message());
  return write_file_atomically(std::filesystem::path(report) / name, std::string_view(table));
}

// With PROXYGI_VALIDATION=1 (the tests) any validation message fails the run.
int validation_failure(const gpu::Context& context) {
  const auto messages = context.validation_messages();
  if (messages.empty()) return kExitOk;
  for (const std::string& message : messages) std::fprintf(stderr, "validation: %s\n", message.c_str());
  return fail_runtime("regress: " + std::to_string(messages.size()) + " Vulkan validation messages");
}

int run_regress(const RegressArgs& args) {
  if (!args.merge.empty()) return run_merge(args);
  if (args.inputs.empty()) return fail_bad_input("regress: give scenario files or folders (or --merge)");
  if (args.write && args.calibrate <= 0) return fail_bad_input("regress: --write needs --calibrate N");
  regress::RunOptions options;
  options.assets_dir = assets_dir();
  if (!args.shard.empty()) {
    auto shard = run::parse_shard(args.shard);
    if (!shard) return fail_bad_input("--shard: " + shard.message());
    options.shard = *shard;
  }
  options.filters = args.filters;
  options.bless = args.bless;
  if (!args.goldens.empty()) options.golden_root = args.goldens;
  if (!args.report.empty()) options.report_dir = args.report;
  options.on_result = print_result;
  std::vector<std::filesystem::path> inputs(args.inputs.begin(), args.inputs.end());
  auto scenarios = regress::load_scenarios(inputs, options.assets_dir);
  if (!scenarios) return fail_bad_input(scenarios.message());
  auto context = gpu::Context::create({.device_request = args.device});
  if (!context) return fail_runtime(context.message());

  if (args.calibrate > 0) {
    auto rows = regress::calibrate(**context, *scenarios, options, std::max(2, args.calibrate));
    if (!rows) return fail_runtime(rows.message());
    const std::string table = regress::calibration_table(*rows);
    if (Status s = print_table(table, args.report, "calibration.md"); !s) return fail_runtime(s.message());
    if (int failed = validation_failure(**context)) return failed;
    if (!args.write) return kExitOk;
    auto diff = regress::write_calibration(*rows, options.assets_dir);
    if (!diff) return fail_runtime("--calibrate --write: " + diff.message());
    std::printf("%s", diff->empty() ? "calibrate: every scenario already holds the proposed tolerances\n" : diff->c_str());
    return kExitOk;
  }
  if (args.sensitivity) {
    options.on_result = nullptr;
    auto report = regress::sensitivity(**context, *scenarios, options);
    if (!report) return fail_runtime(report.message());
    const std::string table = regress::sensitivity_table(*report);
    if (Status s = print_table(table, args.report, "sensitivity.md"); !s) return fail_runtime(s.message());
    if (int failed = validation_failure(**context)) return failed;
    return report->passed() ? kExitOk : kExitFailure;
  }

  auto results = regress::run_regression(**context, *scenarios, options);
  if (!results) return fail_runtime(results.message());
  if (int failed = validation_failure(**context)) return failed;
  if (!args.report.empty())
    if (Status s = regress::write_reports(*results, args.report); !s) return fail_runtime(s.message());
  int failing = 0;
  for (const auto& c : results->checks) failing += regress::is_failure(c.outcome);
  std::printf("regress: %zu checks on %s (%s), %d failing%s\n", results->checks.size(), results->device.c_str(),
              results->family.c_str(), failing, args.report.empty() ? "" : (", report in " + args.report).c_str());
  return results->exit_code();
}

}  // namespace

void add_regress_command(CLI::App& app, CommandRunner& runner) {
  auto args = std::make_shared<RegressArgs>();
  CLI::App* command = app.add_subcommand(
      "regress", "Run regression scenarios (image, animation-track, temporal, differential and budget checks) against "
                 "goldens keyed by device family; exit 0 all pass, 1 a check failed or is new, 2 bad input");
  command->add_option("scenarios", args->inputs, "Scenario files, or folders of them");
  command->add_option("--filter", args->filters, "Only checks whose scenario/check contains this (repeatable)");
  command->add_option("--shard", args->shard, "I/N: only the I-th (0-based) of N contiguous runs of the scenario/check list");
  command->add_option("--bless", args->bless, "Write goldens of these checks (scenario/check, globs allowed)")->expected(1, -1);
  command->add_option("--report", args->report, "Write report.html, results.json and junit.xml into this folder");
  command->add_option("--goldens", args->goldens, "Golden folder (default: goldens/ beside each scenario)");
  command->add_option("--calibrate", args->calibrate, "Run each check N times and propose thresholds from the spread");
  command->add_flag("--write", args->write,
                    "With --calibrate: write the proposed tolerances into the scenario files (atomically) and print the diff");
  command->add_flag("--sensitivity", args->sensitivity, "Apply known small faults and report which checks catch each");
  command->add_option("--merge", args->merge, "Merge shard report folders (their results.json) into --report")->expected(1, -1);
  add_device_option(*command, args->device);
  add_quiet_flag(*command);
  command->callback([args, &runner] { runner = [args] { return run_regress(*args); }; });
}

}  // namespace proxygi::app
