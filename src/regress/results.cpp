#include "regress/results.h"

#include <algorithm>
#include <tuple>

#include <nlohmann/json.hpp>

namespace proxygi::regress {
namespace {

using ojson = nlohmann::ordered_json;

constexpr std::pair<std::string_view, Outcome> kOutcomes[] = {
    {"pass", Outcome::pass},       {"fail", Outcome::fail},       {"new", Outcome::new_golden},
    {"blessed", Outcome::blessed}, {"skipped", Outcome::skipped}, {"error", Outcome::error}};

void sort_checks(std::vector<CheckResult>& checks) {
  std::sort(checks.begin(), checks.end(), [](const CheckResult& a, const CheckResult& b) {
    return std::tie(a.scenario, a.check) < std::tie(b.scenario, b.check);
  });
}

}  // namespace

std::string_view outcome_name(Outcome outcome) {
  for (const auto& [name, o] : kOutcomes)
    if (o == outcome) return name;
  return "?";
}

bool is_failure(Outcome outcome) {
  return outcome == Outcome::fail || outcome == Outcome::new_golden || outcome == Outcome::error;
}

std::string CheckResult::bless_command() const {
  return "proxygi regress " + scenario_file + " --bless " + scenario + "/" + check;
}

int RunResults::exit_code() const {
  return std::any_of(checks.begin(), checks.end(), [](const CheckResult& c) { return is_failure(c.outcome); }) ? 1 : 0;
}

std::string to_json(const RunResults& results) {
  std::vector<CheckResult> checks = results.checks;
  sort_checks(checks);
  ojson j;
  j["device"] = results.device;
  j["family"] = results.family;
  int counts[6] = {};
  for (const CheckResult& c : checks) ++counts[int(c.outcome)];
  ojson summary = ojson::object();
  for (const auto& [name, o] : kOutcomes) summary[std::string(name)] = counts[int(o)];
  j["summary"] = summary;
  j["checks"] = ojson::array();
  for (const CheckResult& c : checks) {
    ojson k;
    k["scenario"] = c.scenario;
    k["scenario_file"] = c.scenario_file;
    k["check"] = c.check;
    k["type"] = c.type;
    k["outcome"] = std::string(outcome_name(c.outcome));
    k["message"] = c.message;
    k["details"] = c.details;
    k["metric"] = c.metric;
    k["threshold"] = c.threshold;
    k["first_failing_frame"] = c.first_failing_frame;
    k["tier"] = c.tier;
    if (is_failure(c.outcome)) k["bless"] = c.bless_command();
    ojson series = ojson::array();
    for (const FramePoint& p : c.series) series.push_back({p.frame, p.value, p.failed});
    k["series"] = series;
    if (c.images) {
      k["images"] = {{"frame", c.images->frame}, {"golden", c.images->golden}, {"actual", c.images->actual},
                     {"diff", c.images->diff},   {"flip", c.images->flip}};
    }
    j["checks"].push_back(k);
  }
  return j.dump(1) + "\n";
}

Result<RunResults> results_from_json(std::string_view text, const std::string& where) {
  try {
    const ojson j = ojson::parse(text.begin(), text.end());
    RunResults results;
    results.device = j.at("device").get<std::string>();
    results.family = j.at("family").get<std::string>();
    for (const ojson& k : j.at("checks")) {
      CheckResult c;
      c.scenario = k.at("scenario").get<std::string>();
      c.scenario_file = k.at("scenario_file").get<std::string>();
      c.check = k.at("check").get<std::string>();
      c.type = k.at("type").get<std::string>();
      const std::string outcome = k.at("outcome").get<std::string>();
      bool known = false;
      for (const auto& [name, o] : kOutcomes)
        if (name == outcome) c.outcome = o, known = true;
      if (!known) return make_error(where + ": " + c.scenario + "/" + c.check + ": unknown outcome " + outcome);
      c.message = k.at("message").get<std::string>();
      c.details = k.at("details").get<std::vector<std::string>>();
      c.metric = k.at("metric").get<std::string>();
      c.threshold = k.at("threshold").get<double>();
      c.first_failing_frame = k.at("first_failing_frame").get<int>();
      c.tier = k.at("tier").get<std::string>();
      for (const ojson& p : k.at("series")) c.series.push_back({p.at(0).get<int>(), p.at(1).get<double>(), p.at(2).get<bool>()});
      if (k.contains("images")) {
        const ojson& i = k.at("images");
        c.images = CheckImages{i.at("frame").get<int>(), i.at("golden").get<std::string>(), i.at("actual").get<std::string>(),
                               i.at("diff").get<std::string>(), i.at("flip").get<std::string>()};
      }
      results.checks.push_back(std::move(c));
    }
    return results;
  } catch (const ojson::exception& e) {
    return make_error(where + ": not a results.json: " + e.what());
  }
}

double median_ms(const std::vector<double>& runs_ms) {
  if (runs_ms.empty()) return 0.0;
  std::vector<double> sorted = runs_ms;
  std::sort(sorted.begin(), sorted.end());
  return sorted[sorted.size() / 2];
}

std::string timings_to_json(const RunResults& results) {
  std::vector<CheckResult> checks = results.checks;
  sort_checks(checks);
  ojson j;
  j["device"] = results.device;
  j["checks"] = ojson::array();
  for (const CheckResult& c : checks)
    if (!c.timings_ms.empty())
      j["checks"].push_back({{"scenario", c.scenario}, {"check", c.check}, {"runs_ms", c.timings_ms}, {"median_ms", median_ms(c.timings_ms)}});
  return j.dump(1) + "\n";
}

Status attach_timings(std::string_view text, const std::string& where, RunResults& results) {
  try {
    const ojson j = ojson::parse(text.begin(), text.end());
    for (const ojson& k : j.at("checks")) {
      const std::string scenario = k.at("scenario").get<std::string>(), check = k.at("check").get<std::string>();
      auto found = std::find_if(results.checks.begin(), results.checks.end(),
                                [&](const CheckResult& c) { return c.scenario == scenario && c.check == check; });
      if (found == results.checks.end()) return make_error(where + ": " + scenario + "/" + check + ": not in results.json");
      found->timings_ms = k.at("runs_ms").get<std::vector<double>>();
    }
    return {};
  } catch (const ojson::exception& e) {
    return make_error(where + ": not a timings.json: " + e.what());
  }
}

Result<RunResults> merge_results(const std::vector<RunResults>& shards) {
  RunResults merged;
  for (const RunResults& shard : shards) {
    if (merged.device.empty()) {
      merged.device = shard.device;
      merged.family = shard.family;
    } else if (!shard.device.empty() && shard.device != merged.device) {
      return make_error("merge: shards ran on different devices (" + merged.device + ", " + shard.device + ")");
    }
    merged.checks.insert(merged.checks.end(), shard.checks.begin(), shard.checks.end());
  }
  sort_checks(merged.checks);
  for (std::size_t i = 1; i < merged.checks.size(); ++i)
    if (merged.checks[i].scenario == merged.checks[i - 1].scenario && merged.checks[i].check == merged.checks[i - 1].check)
      return make_error("merge: " + merged.checks[i].scenario + "/" + merged.checks[i].check + " appears in two shards");
  return merged;
}

}  // namespace proxygi::regress
