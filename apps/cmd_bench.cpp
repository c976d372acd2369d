// proxygi bench: studies (sh, frame, chart, stability) and the Google Benchmark micro benchmarks
// (benchmarks/*.cpp, linked into this binary), e.g. `proxygi bench micro --filter '^anim/'`.
#include <benchmark/benchmark.h>

#include <fstream>
#include <string>
#include <vector>

#include "apps/commands.h"

namespace proxygi::app {
namespace {

int run_micro_benchmarks(const std::string& filter, bool json, const std::string& min_time) {
  std::vector<std::string> arguments = {"proxygi-bench"};
  if (!filter.empty()) arguments.push_back("--benchmark_filter=" + filter);
  if (json) arguments.push_back("--benchmark_format=json");
  if (!min_time.empty()) arguments.push_back("--benchmark_min_time=" + min_time);
  std::vector<char*> argv;
  for (auto& argument : arguments) argv.push_back(argument.data());
  int argc = static_cast<int>(argv.size());
  benchmark::Initialize(&argc, argv.data());
  if (benchmark::ReportUnrecognizedArguments(argc, argv.data())) return kExitBadInput;
  // --quiet: Google Benchmark's context banner and table go nowhere (--json still prints).
  std::ofstream nowhere("/dev/null");
  benchmark::ConsoleReporter silent;
  silent.SetOutputStream(&nowhere);
  silent.SetErrorStream(&nowhere);
  const std::size_t ran = quiet() && !json ? benchmark::RunSpecifiedBenchmarks(&silent) : benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  if (ran == 0) return fail_bad_input("bench micro: no benchmark matches '" + filter + "'");
  return kExitOk;
}

}  // namespace

void add_bench_command(CLI::App& app, CommandRunner& runner) {
  auto* bench = app.add_subcommand("bench", "Benchmarks: speed against accuracy, measured in one run");
  bench->require_subcommand(1);

  struct MicroOptions {
    std::string filter;
    bool json = false;
    std::string min_time;
  };
  auto options = std::make_shared<MicroOptions>();
  auto* micro = bench->add_subcommand("micro", "Google Benchmark micro benchmarks (anim/, proxies/, ...)");
  micro->add_option("--filter", options->filter, "Regular expression over benchmark names, e.g. '^anim/'");
  micro->add_flag("--json", options->json, "Google Benchmark JSON on stdout");
  micro->add_option("--min-time", options->min_time, "Minimum seconds per benchmark");
  add_quiet_flag(*micro);
  micro->callback([&runner, options] {
    runner = [options] { return run_micro_benchmarks(options->filter, options->json, options->min_time); };
  });

  add_bench_sh_command(*bench, runner);
  add_bench_frame_command(*bench, runner);
  add_bench_record_command(*bench, runner);
  add_bench_sampler_command(*bench, runner);
  add_bench_chart_command(*bench, runner);
  add_bench_stability_command(*bench, runner);
}

}  // namespace proxygi::app
