#pragma once
// Whether tolerances mean something (notes/viewer-regression.md §3.6):
//  - calibrate: renders (or evaluates) each image / tracks / temporal check N times, each time
//    with a fresh world and renderer, measures the spread against the first run and proposes
//    thresholds from it (a floor where runs are bit-identical), next to the hand-set ones;
//  - sensitivity: reruns the checks with each known fault (faults.h) and reports which checks
//    catch it; it passes when the unchanged rerun passes and every fault is caught.
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "base/result.h"
#include "gpu/context.h"
#include "regress/runner.h"

namespace proxygi::regress {

struct CalibrationRow {
  std::string scenario, check, type;
  std::filesystem::path file;  // the scenario file
  std::size_t check_index = 0; // in its "checks"
  std::string hand_set;   // "5 codes, 0.1 % of pixels" / "0.1 mm"
  std::string spread;     // measured over the runs
  std::string proposed;
  // The proposal as scenario fields (pixel_threshold, max_failing_fraction; tolerance; joint_mm,
  // vertex_mm, proxy_mm): the measured spread times its margin, rounded up (never below the
  // spread), with the floors where runs are bit-identical.
  std::vector<std::pair<std::string, double>> fields;
};

Result<std::vector<CalibrationRow>> calibrate(gpu::Context& context, const std::vector<Scenario>& scenarios,
                                              const RunOptions& options, int runs);
std::string calibration_table(const std::vector<CalibrationRow>& rows);  // Markdown

// --calibrate N --write: sets each row's proposed fields in its scenario file (only the values
// change; the file keeps its layout), checks the edited file parses to exactly those values, and
// replaces it atomically (temporary file + rename). Returns the diff of every file changed ("" when
// the files already hold the proposals). Nothing is written when any file fails.
Result<std::string> write_calibration(const std::vector<CalibrationRow>& rows, const std::filesystem::path& assets_dir);

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
