#pragma once
// What a regression run found: one CheckResult per (scenario, check), in a deterministic order,
// serialized to results.json (no timings, no absolute paths: shards merge byte-identically).
// Measured times (budget checks) travel beside it in timings.json, which only they may change.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "base/result.h"

namespace proxygi::regress {

enum class Outcome { pass, fail, new_golden, blessed, skipped, error };
std::string_view outcome_name(Outcome outcome);
bool is_failure(Outcome outcome);  // fail, new_golden, error

struct FramePoint {
  int frame = 0;
  double value = 0.0;
  bool failed = false;
};

// The frame a report shows for a check (its first failing frame, else its worst), as PNG data URIs.
struct CheckImages {
  int frame = 0;
  std::string golden, actual, diff, flip;  // "data:image/png;base64,..." (empty when absent)
};

struct CheckResult {
  std::string scenario;  // name (file stem)
  std::string scenario_file;  // as given on the command line
  std::string check;
  std::string type;
  Outcome outcome = Outcome::pass;
  std::string message;               // one line
  std::vector<std::string> details;  // further lines (per-frame findings, what a bless changed)
  std::string metric;                // what `series` holds, e.g. "failing fraction"
  double threshold = 0.0;            // on `series` values (0 when none)
  std::vector<FramePoint> series;
  int first_failing_frame = -1;
  std::string tier;                  // the golden tier compared against ("" for golden-free checks)
  std::optional<CheckImages> images;
  // Budget checks: ms per frame of each timed run. Only in timings.json, never in results.json,
  // junit.xml or report.html (those stay byte-identical between runs; the outcome carries pass/fail).
  std::vector<double> timings_ms;
  std::string bless_command() const;  // "proxygi regress FILE --bless scenario/check"
};

struct RunResults {
  std::string device;  // Vulkan device name
  std::string family;  // device_family(device)
  std::vector<CheckResult> checks;
  int exit_code() const;  // 0 all pass/skipped/blessed, 1 any failure
};

std::string to_json(const RunResults& results);
Result<RunResults> results_from_json(std::string_view text, const std::string& where);
// timings.json: {"device", "checks": [{"scenario", "check", "runs_ms": [...], "median_ms"}]}
// for the checks with timings, in results.json's order.
std::string timings_to_json(const RunResults& results);
// Attaches a timings.json's runs to the matching checks of `results` (unknown checks: an error).
Status attach_timings(std::string_view text, const std::string& where, RunResults& results);
double median_ms(const std::vector<double>& runs_ms);  // 0 when empty
// Shards' results into one (checks sorted by scenario then check; device must agree).
Result<RunResults> merge_results(const std::vector<RunResults>& shards);

}  // namespace proxygi::regress
