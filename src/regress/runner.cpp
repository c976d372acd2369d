#include "regress/runner.h"

#include <fnmatch.h>

#include <chrono>

#include "regress/checks.h"
#include "regress/golden_store.h"
#include "regress/scenario_run.h"

namespace proxygi::regress {
namespace {

struct Job {
  const Scenario* scenario;
  const Check* check;
};

bool wanted(const RunOptions& options, const std::string& scenario, const std::string& check) {
  const std::string id = scenario + "/" + check;
  auto hit = [&](const std::string& f) { return id.find(f) != std::string::npos || matches_pattern(f, scenario, check); };
  bool any_positive = false, included = false;
  for (const std::string& filter : options.filters) {
    if (!filter.empty() && filter[0] == '!') {
      if (hit(filter.substr(1))) return false;
    } else {
      any_positive = true;
      included = included || hit(filter);
    }
  }
  return !any_positive || included;
}

Status run_check(CheckContext& c) {
  switch (c.check.type) {
    case CheckType::image: return run_image_check(c);
    case CheckType::tracks: return run_tracks_check(c);
    case CheckType::temporal: return run_temporal_check(c);
    case CheckType::differential: return run_differential_check(c);
    case CheckType::budget: return run_budget_check(c);
  }
  return make_error("unknown check type");
}

}  // namespace

bool matches_pattern(const std::string& pattern, const std::string& scenario, const std::string& check) {
  const std::string id = pattern.find('/') != std::string::npos ? scenario + "/" + check : check;
  return fnmatch(pattern.c_str(), id.c_str(), 0) == 0;
}

Result<RunResults> run_regression(gpu::Context& context, const std::vector<Scenario>& scenarios, const RunOptions& options) {
  RunResults results;
  results.device = context.report().name;
  results.family = device_family(results.device);
  // Every wanted scenario/check in order; shard I of N takes the I-th of N contiguous, balanced
  // runs of that list, so a scenario's world is loaded by at most two shards.
  std::vector<Job> all;
  for (const Scenario& scenario : scenarios)
    for (const Check& check : scenario.checks)
      if (wanted(options, scenario.name, check.name)) all.push_back({&scenario, &check});
  const run::IndexRange slice = run::shard_slice(all.size(), options.shard);
  const std::vector<Job> jobs(all.begin() + std::ptrdiff_t(slice.begin), all.begin() + std::ptrdiff_t(slice.end));
  std::unique_ptr<ScenarioRun> run;
  const Scenario* loaded = nullptr;
  for (const Job& job : jobs) {
    const auto start = std::chrono::steady_clock::now();
    const Scenario& scenario = *job.scenario;
    CheckResult result;
    result.scenario = scenario.name;
    result.scenario_file = scenario.file.generic_string();
    result.check = job.check->name;
    result.type = std::string(check_type_name(job.check->type));
    const bool bless = std::any_of(options.bless.begin(), options.bless.end(),
                                   [&](const std::string& p) { return matches_pattern(p, scenario.name, job.check->name); });
    if (!scenario.requirements_met()) {
      result.outcome = Outcome::skipped;
      result.message = "requires " + scenario.requires_paths.front().generic_string() + " (absent)";
    } else {
      Status status;
      if (loaded != &scenario) {
        run.reset();
        auto created = ScenarioRun::create(context, scenario, options.assets_dir, options.fault);
        if (created) {
          run = std::move(*created);
          loaded = &scenario;
        } else {
          loaded = nullptr;
          status = created.error();
        }
      }
      if (status) {
        GoldenStore store{options.golden_root ? *options.golden_root / "" : scenario.file.parent_path() / "goldens",
                          results.family};
        CheckContext c{context, *run, *job.check, store, bless, options, result};
        status = run_check(c);
      }
      if (!status) {
        result.outcome = Outcome::error;
        result.message = status.message();
      }
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (options.on_result) options.on_result(result, seconds);
    results.checks.push_back(std::move(result));
  }
  return results;
}

}  // namespace proxygi::regress
