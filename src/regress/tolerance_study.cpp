#include "regress/tolerance_study.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>

#include "base/atomic_file.h"
#include "regress/json_edit.h"
#include "scene/scene_parse.h"

#include "regress/image_compare.h"
#include "regress/tracks.h"

namespace proxygi::regress {
namespace {

std::string format(const char* pattern, double a, double b = 0.0) {
  char text[128];
  std::snprintf(text, sizeof(text), pattern, a, b);
  return text;
}

// Largest code difference and the fraction of region pixels differing at all, over frames.
struct ImageSpread {
  double largest = 0.0;  // codes (fractions of a code for EXR goldens)
  double fraction = 0.0;
};

// Rounds up to two significant digits: a written tolerance is never below what was measured.
double round_up(double value) {
  if (!(value > 0)) return value;
  const double unit = std::pow(10.0, std::floor(std::log10(value)) - 1.0);
  return std::ceil(value / unit - 1e-9) * unit;
}

std::string json_number(double value) {
  char text[32];
  std::snprintf(text, sizeof(text), "%.6g", value);
  return text;
}

}  // namespace

Result<std::vector<CalibrationRow>> calibrate(gpu::Context& context, const std::vector<Scenario>& scenarios,
                                              const RunOptions& options, int runs) {
  std::vector<CalibrationRow> rows;
  for (const Scenario& scenario : scenarios) {
    if (!scenario.requirements_met()) continue;
    std::vector<std::unique_ptr<ScenarioRun>> sessions;
    for (int r = 0; r < runs; ++r) {
      auto created = ScenarioRun::create(context, scenario, options.assets_dir, options.fault);
      if (!created) return created.error();
      sessions.push_back(std::move(*created));
    }
    for (const Check& check : scenario.checks) {
      CalibrationRow row;
      row.scenario = scenario.name;
      row.check = check.name;
      row.type = std::string(check_type_name(check.type));
      row.file = scenario.file;
      row.check_index = std::size_t(&check - scenario.checks.data());
      if (check.type == CheckType::image || check.type == CheckType::temporal) {
        ImageSpread spread;
        for (int frame : check.frames) {
          auto base = sessions[0]->frame(frame);
          if (!base) return base.error();
          for (int r = 1; r < runs; ++r) {
            auto other = sessions[std::size_t(r)]->frame(frame);
            if (!other) return other.error();
            const auto mask = region_mask((*base)->classes, check.region);
            auto codes = [&](const RenderedFrame& f) {
              return check.aov == Aov::final_frame ? codes_of(f.final_frame) : codes_of(f.aov(check.aov));
            };
            auto d = compare_images(codes(**other), codes(**base), mask, {0, 0.0});
            if (!d) return d.error();
            spread.largest = std::max(spread.largest, d->largest);
            spread.fraction = std::max(spread.fraction, d->failing_fraction);
          }
        }
        if (check.type == CheckType::image) {
          const double threshold = std::max(1.0, std::ceil(2.0 * spread.largest));
          const double fraction = round_up(std::max(0.0005, 3.0 * spread.fraction));
          row.hand_set = format("%.0f codes, %.3f %% of pixels", check.image.pixel_threshold, 100.0 * check.image.max_failing_fraction);
          row.spread = format("largest %.3g codes, %.3f %% of pixels differ", spread.largest, 100.0 * spread.fraction);
          row.proposed = format("%.0f codes, %.3f %% of pixels", threshold, fraction * 100.0);
          row.fields = {{"pixel_threshold", threshold}, {"max_failing_fraction", fraction}};
        } else {
          const double tolerance = round_up(std::max(0.05, 2.0 * spread.largest * spread.fraction));
          row.hand_set = format("%.3f codes", check.temporal_tolerance);
          row.spread = format("largest %.3g codes between runs", spread.largest);
          row.proposed = format("%.3f codes", tolerance);
          row.fields = {{"tolerance", tolerance}};
        }
      } else if (check.type == CheckType::tracks) {
        auto base = compute_tracks(*sessions[0], check);
        if (!base) return base.error();
        double worst_ratio = 0.0;
        for (int r = 1; r < runs; ++r) {
          auto other = compute_tracks(*sessions[std::size_t(r)], check);
          if (!other) return other.error();
          CheckResult probe;
          Check tight = check;
          tight.tracks.joint_mm = tight.tracks.vertex_mm = tight.tracks.proxy_mm = 1e-6;  // ratios become nanometres
          compare_tracks(*other, *base, tight, 1.0, probe);
          for (const FramePoint& p : probe.series) worst_ratio = std::max(worst_ratio, p.value);
        }
        const double spread_mm = worst_ratio * 1e-6;
        row.hand_set = format("%.3f mm joints, %.3f mm proxies", check.tracks.joint_mm, check.tracks.proxy_mm);
        row.spread = format("%.2g mm", spread_mm);
        const double mm = round_up(std::max(0.01, 3.0 * spread_mm));
        row.proposed = format("%.3f mm", mm);
        row.fields = {{"joint_mm", mm}, {"vertex_mm", mm}, {"proxy_mm", mm}};
      } else {
        continue;
      }
      rows.push_back(std::move(row));
    }
  }
  return rows;
}

std::string calibration_table(const std::vector<CalibrationRow>& rows) {
  std::ostringstream out;
  out << "| check | type | hand-set | measured spread | proposed |\n|---|---|---|---|---|\n";
  for (const CalibrationRow& r : rows)
    out << "| " << r.scenario << "/" << r.check << " | " << r.type << " | " << r.hand_set << " | " << r.spread << " | " << r.proposed << " |\n";
  return out.str();
}

Result<std::string> write_calibration(const std::vector<CalibrationRow>& rows, const std::filesystem::path& assets_dir) {
  std::map<std::filesystem::path, std::vector<const CalibrationRow*>> by_file;
  for (const CalibrationRow& row : rows)
    if (!row.fields.empty()) by_file[row.file].push_back(&row);
  std::vector<std::pair<std::filesystem::path, std::string>> edited;
  std::string diff;
  for (const auto& [file, file_rows] : by_file) {
    auto bytes = read_file(file, scene::kMaxSceneFileBytes);
    if (!bytes) return bytes.error();
    const std::string before(bytes->begin(), bytes->end());
    auto original = parse_scenario(before, file, assets_dir);
    if (!original) return original.error();
    std::vector<FieldEdit> edits;
    for (const CalibrationRow* row : file_rows)
      for (const auto& [key, value] : row->fields) edits.push_back({row->check_index, key, json_number(value)});
    auto after = edit_check_fields(before, edits);
    if (!after) return make_error(file.string() + ": " + after.message());
    // The edited file must parse, and to exactly the proposals in the intended checks.
    auto changed = parse_scenario(*after, file, assets_dir);
    if (!changed) return make_error(file.string() + ": the calibrated file does not parse: " + changed.message());
    for (const CalibrationRow* row : file_rows) {
      const Check& check = changed->checks.at(row->check_index);
      for (const auto& [key, value] : row->fields) {
        const double got = key == "pixel_threshold"        ? double(check.image.pixel_threshold)
                           : key == "max_failing_fraction" ? check.image.max_failing_fraction
                           : key == "tolerance"            ? check.temporal_tolerance
                           : key == "joint_mm"             ? check.tracks.joint_mm
                           : key == "vertex_mm"            ? check.tracks.vertex_mm
                                                           : check.tracks.proxy_mm;
        if (check.name != row->check || std::abs(got - std::stod(json_number(value))) > 1e-12)
          return make_error(file.string() + ": " + row->check + "." + key + " did not take the proposed value");
      }
    }
    if (*after == before) continue;
    diff += line_diff(before, *after, file.generic_string());
    edited.emplace_back(file, std::move(*after));
  }
  for (const auto& [file, text] : edited)
    if (Status s = write_file_atomically(file, std::string_view(text)); !s) return s.error();
  return diff;
}

bool SensitivityReport::passed() const {
  return clean_failures.empty() && std::all_of(rows.begin(), rows.end(), [](const SensitivityRow& r) { return !r.caught_by.empty(); });
}

Result<SensitivityReport> sensitivity(gpu::Context& context, const std::vector<Scenario>& scenarios, const RunOptions& options) {
  SensitivityReport report;
  std::vector<Fault> faults{Fault{FaultKind::none}};
  for (const Fault& f : sensitivity_faults()) faults.push_back(f);
  for (const Fault& fault : faults) {
    RunOptions faulted = options;
    faulted.fault = fault;
    faulted.bless.clear();
    faulted.report_dir.reset();
    auto results = run_regression(context, scenarios, faulted);
    if (!results) return results.error();
    std::vector<std::string> failing;
    for (const CheckResult& c : results->checks)
      if (is_failure(c.outcome) && c.type != "budget") failing.push_back(c.scenario + "/" + c.check);
    if (fault.kind == FaultKind::none) report.clean_failures = failing;
    else report.rows.push_back({std::string(fault.name()), failing});
  }
  return report;
}

std::string sensitivity_table(const SensitivityReport& report) {
  std::ostringstream out;
  out << "| fault | caught by |\n|---|---|\n";
  out << "| (none: unchanged rerun) | " << (report.clean_failures.empty() ? "passes" : "FAILS: ") ;
  for (const auto& c : report.clean_failures) out << c << " ";
  out << " |\n";
  for (const SensitivityRow& r : report.rows) {
    out << "| " << r.fault << " | ";
    if (r.caught_by.empty()) out << "**NOT CAUGHT**";
    for (std::size_t i = 0; i < r.caught_by.size(); ++i) out << (i ? ", " : "") << r.caught_by[i];
    out << " |\n";
  }
  return out.str();
}

}  // namespace proxygi::regress
