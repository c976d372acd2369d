#pragma once
// What `proxygi bench chart` writes: bench-chart.csv (every row), bench-chart.md (machine,
// driver, settings, goals, the mean-over-scenes table and one table per scene, Pareto front
// first) and bench-chart.png (log–log ms against relative MSE, one panel per scene, the front
// joined by a line and its members named).
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
};

// The scene the goals are evaluated on: "all" when present, else the first scene.
std::string goal_scene(const std::vector<study::ChartRow>& rows);

Status write_chart_report(const std::string& folder, const std::vector<study::ChartRow>& rows,
                          const ChartReportContext& context);
nlohmann::json chart_report_json(const std::vector<study::ChartRow>& rows, const ChartReportContext& context);
std::string chart_summary_text(const std::vector<study::ChartRow>& rows, const ChartReportContext& context);

}  // namespace proxygi::app
