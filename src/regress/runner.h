#pragma once
// The regression runner behind `proxygi regress`: every (scenario, check) of this shard, in
// order, against goldens (golden_store.h) or, for golden-free checks, against a second render.
// Deterministic: the same scenarios, goldens and driver give byte-identical results.json, and
// shards (run::Shard: the I-th of N contiguous runs of the scenario/check list) merge into exactly that.
//
//   auto results = regress::run_regression(context, scenarios, {.assets_dir = assets});
//   return results->exit_code();   // 0 all pass, 1 a check failed or has no golden
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "base/result.h"
#include "gpu/context.h"
#include "regress/faults.h"
#include "regress/results.h"
#include "regress/scenario.h"
#include "run/frame_plan.h"

namespace proxygi::regress {

struct RunOptions {
  std::filesystem::path assets_dir;
  std::optional<std::filesystem::path> golden_root;  // default: <scenario folder>/goldens
  run::Shard shard;
  std::vector<std::string> filters;  // substrings or globs of "scenario/check"; any may match; "!F" excludes
  std::vector<std::string> bless;    // glob patterns on "scenario/check" (or on the check name alone)
  Fault fault;                       // sensitivity runs
  std::optional<std::filesystem::path> report_dir;  // images of each check are written under it
  std::function<void(const CheckResult&, double seconds)> on_result;  // progress
};

bool matches_pattern(const std::string& pattern, const std::string& scenario, const std::string& check);

Result<RunResults> run_regression(gpu::Context& context, const std::vector<Scenario>& scenarios, const RunOptions& options);

}  // namespace proxygi::regress
