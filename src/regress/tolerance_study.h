#pragma once
// Whether tolerances mean something (notes/viewer-regression.md §3.6):
//  - calibrate: renders (or evaluates) each image / tracks / temporal check N times, each time
//    with a fresh world and renderer, measures the spread against the first run and proposes
//    thresholds from it (a floor where runs are bit-identical), next to the hand-set ones;
//  - sensitivity: reruns the checks with each known fault (faults.h) and reports which checks
//    catch it; it passes when the unchanged rerun passes and every fault is caught.
#include <string>
#include <vector>

#include "base/result.h"
#include "gpu/context.h"
#include "regress/runner.h"

namespace proxygi::regress {

struct CalibrationRow {
  std::string scenario, check, type;
  std::string hand_set;   // "5 codes, 0.1 % of pixels" / "0.1 mm"
  std::string spread;     // measured over the runs
  std::string proposed;
};

Result<std::vector<CalibrationRow>> calibrate(gpu::Context& context, const std::vector<Scenario>& scenarios,
                                              const RunOptions& options, int runs);
std::string calibration_table(const std::vector<CalibrationRow>& rows);  // Markdown

struct SensitivityRow {
  std::string fault;
  std::vector<std::string> caught_by;  // "scenario/check"
};
struct SensitivityReport {
  std::vector<std::string> clean_failures;  // checks failing without a fault (must be none)
  std::vector<SensitivityRow> rows;
  bool passed() const;
};

Result<SensitivityReport> sensitivity(gpu::Context& context, const std::vector<Scenario>& scenarios, const RunOptions& options);
std::string sensitivity_table(const SensitivityReport& report);  // Markdown

}  // namespace proxygi::regress
