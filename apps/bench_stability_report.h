#pragma once
// The files of `proxygi bench stability`: JSON of every sweep point, a markdown table per sweep
// (method, worst value per metric, threshold, pass/fail), one chart per sweep with its threshold
// lines, and the robustness–speed chart (x: ms per frame of the frame setting a method stands for,
// from the committed speed–accuracy chart; y: fraction of its sweep points that fail).
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "base/result.h"
#include "study/stability_sweeps.h"

namespace proxygi::app {

// ms per frame of the frame setting each method stands for ("hyb" → the default proxy row).
using MethodTimings = std::map<std::string, double>;
// Reads rows of scene "all" from a bench-chart.csv; an absent file gives no timings. Also returns
// the smallest relative MSE of a proxy row (S10's threshold × 3) through `best_proxy_relative_mse`.
MethodTimings timings_from_chart_csv(const std::string& path, double* best_proxy_relative_mse);

nlohmann::json stability_json(const std::vector<study::SweepResult>& sweeps, const MethodTimings& timings);
std::string stability_markdown(const std::vector<study::SweepResult>& sweeps);
std::string stability_summary_text(const std::vector<study::SweepResult>& sweeps);
// Writes bench-stability.json, .md, stability-<id>.png per sweep (and stability-<id>-traces.png,
// -heatmaps.png where the sweep has them) and stability-robustness-speed.png.
Status write_stability_report(const std::string& out_dir, const std::vector<study::SweepResult>& sweeps,
                              const MethodTimings& timings);

}  // namespace proxygi::app
