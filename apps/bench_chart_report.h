#pragma once
// What `proxygi bench chart` writes: bench-chart.csv (every row), bench-chart.md (machine,
// driver, settings, goals, the mean-over-scenes table and one table per scene, Pareto front
// first) and bench-chart.png (log–log ms against relative MSE, one panel per scene, the front
// joined by a line and its members named); and, split by what is measured:
// bench-chart-scores.json (the chart's settings and every row's identity and errors: no time, no
// machine, no Pareto flag, so it is byte-identical between runs and between sharded and single
// runs) and bench-chart-timings.json (every row's ms per frame, the only measured part).
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "base/result.h"
#include "study/chart_rows.h"

namespace proxygi::app {

struct ChartReportContext {
  std::string device;
  std::string driver;
  std::string cpu;  // empty: the model name in /proc/cpuinfo
  int size = 0;
  int frames = 0;
  int timing_frames = 0;
  int reference_spp = 0;
  std::string lighting;
  std::vector<std::string> scenes;
  bool regions = false;  // --regions: rows carry region errors and bounds (study/chart_regions.h)
};

// The context without the machine (cpu, threads): what must agree for two runs to be comparable.
nlohmann::json chart_context_json(const ChartReportContext& context);
Result<ChartReportContext> chart_context_from_json(const nlohmann::json& json);

std::string chart_scores_json(const std::vector<study::ChartRow>& rows, const ChartReportContext& context);
std::string chart_timings_json(const std::vector<study::ChartRow>& rows);

// The scene the goals are evaluated on: "all" when present, else the first scene.
std::string goal_scene(const std::vector<study::ChartRow>& rows);

Status write_chart_report(const std::string& folder, const std::vector<study::ChartRow>& rows,
                          const ChartReportContext& context);
nlohmann::json chart_report_json(const std::vector<study::ChartRow>& rows, const ChartReportContext& context);
std::string chart_summary_text(const std::vector<study::ChartRow>& rows, const ChartReportContext& context);

}  // namespace proxygi::app
