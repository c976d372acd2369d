#include "apps/bench_stability_report.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

#include "apps/matplotlib_chart.h"
#include "base/atomic_file.h"

namespace proxygi::app {
namespace {

// The chart row each stability method stands for (its frame cost).
const std::map<std::string, std::string> kChartRowOf = {
    {"hyb", "proxy n4 k4 bilateral averaged"}, {"hard", "proxy n4 k4 bilateral averaged"},
    {"fade1", "proxy n4 k4 bilateral averaged"}, {"fade4", "proxy n4 k4 bilateral averaged"},
    {"fade16", "proxy n4 k4 bilateral averaged"}, {"bilateral", "proxy n4 k4 bilateral averaged"},
    {"bilinear", "proxy n4 k4 bilinear averaged"}, {"k1", "proxy n4 k1 averaged"}, {"path", "path 64 spp"},
    {"ao", "ao k4 bilateral"}, {"vertex", "vertex n4"}, {"gpu gather", "proxy n4 k4 bilateral averaged"}};

std::vector<std::string> split_csv_line(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream stream(line);
  std::string cell;
  while (std::getline(stream, cell, ',')) out.push_back(cell);
  return out;
}

nlohmann::json json_number(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }

struct Worst {
  double value = -std::numeric_limits<double>::infinity();
  std::size_t points = 0, failures = 0;
};
// (method, metric) → worst value, in the order methods first appear.
std::vector<std::pair<std::pair<std::string, int>, Worst>> worst_per_method(const study::SweepResult& sweep) {
  std::vector<std::pair<std::pair<std::string, int>, Worst>> out;
  for (const study::SweepPoint& p : sweep.points) {
    auto it = std::find_if(out.begin(), out.end(), [&](const auto& e) { return e.first == std::pair{p.method, p.metric}; });
    if (it == out.end()) it = out.insert(out.end(), {{p.method, p.metric}, Worst{}});
    it->second.value = std::isfinite(p.value) ? std::max(it->second.value, p.value) : INFINITY;
    ++it->second.points;
    it->second.failures += p.pass ? 0 : 1;
  }
  return out;
}

// A table cell: '|' would end it.
std::string cell(const std::string& text) {
  std::string out;
  for (char c : text) out += c == '|' ? std::string("\\|") : std::string(1, c);
  return out;
}

std::string number(double v) {
  if (!std::isfinite(v)) return v > 0 ? "inf" : "-";
  char text[32];
  std::snprintf(text, sizeof text, std::abs(v) >= 100 || v == 0 ? "%.0f" : std::abs(v) >= 1 ? "%.2f" : "%.3g", v);
  return text;
}

constexpr const char* kSweepChart = R"PY(
import json, sys
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
sweep = json.load(sys.stdin)
metrics = sweep["metrics"]
fig, axes = plt.subplots(1, len(metrics), figsize=(6.2 * len(metrics), 4.6), squeeze=False)
for m, metric in enumerate(metrics):
    ax = axes[0][m]
    series = {}
    for p in sweep["points"]:
        if p["metric"] != m or p["value"] is None:
            continue
        series.setdefault(p["series"], []).append((p["x"], p["value"], p["pass"]))
    for name, pts in series.items():
        pts.sort()
        xs = [q[0] for q in pts]
        ys = [q[1] for q in pts]
        line, = ax.plot(xs, ys, marker="o", markersize=3, linewidth=1, label=name)
        bad = [(q[0], q[1]) for q in pts if not q[2]]
        if bad:
            ax.scatter([b[0] for b in bad], [b[1] for b in bad], marker="x", color="red", s=30, zorder=5)
    if metric["threshold"] is not None:
        ax.axhline(metric["threshold"], color="red", linestyle="--", linewidth=1.2, label=f'threshold {metric["threshold"]:g} {metric["unit"]}')
    if sweep["log_x"]:
        ax.set_xscale("log")
    ax.set_xlabel(sweep["x_label"], fontsize=8)
    ax.set_ylabel(f'{metric["name"]} ({metric["unit"]})', fontsize=8)
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=6, ncol=2)
fig.suptitle(f'{sweep["id"]}: {sweep["title"]}', fontsize=9)
fig.tight_layout()
fig.savefig(sys.argv[1], dpi=100, format="png")
)PY";

constexpr const char* kRobustnessChart = R"PY(
import json, sys
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
data = json.load(sys.stdin)
fig, ax = plt.subplots(figsize=(7.5, 5))
untimed = []
for m in data["methods"]:
    y = 100.0 * m["failures"] / m["points"]
    if m["ms_per_frame"] is None:
        untimed.append((m["method"], y))
        continue
    ax.scatter(m["ms_per_frame"], y, s=40)
    ax.annotate(f'{m["method"]} ({m["failures"]}/{m["points"]})', (m["ms_per_frame"], y), fontsize=8, xytext=(4, 4), textcoords="offset points")
ax.set_xscale("log")
ax.set_xlabel("ms per frame (the frame setting each method stands for, committed bench-chart.csv, scene all)")
ax.set_ylabel("sweep points failing (%)")
ax.set_ylim(-5, 105)
if untimed:
    ax.text(0.01, 0.99, "not a frame setting of the chart (no ms):\n" + "\n".join(f"{n}: {y:.0f} %" for n, y in untimed),
            transform=ax.transAxes, va="top", fontsize=8)
ax.grid(True, which="both", alpha=0.3)
ax.set_title("robustness against speed over the stability sweeps", fontsize=10)
fig.tight_layout()
fig.savefig(sys.argv[1], dpi=100, format="png")
)PY";

// Traces (per frame, or S5's error against pole width / k), one panel per quantity; argv[1] = PNG.
constexpr const char* kTraceChart = R"PY(
import json, sys
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
data = json.load(sys.stdin)
panels = []
for t in data["traces"]:
    if t["panel"] not in panels:
        panels.append(t["panel"])
fig, axes = plt.subplots(1, len(panels), figsize=(6.4 * len(panels), 4.6), squeeze=False)
for i, panel in enumerate(panels):
    ax = axes[0][i]
    for t in data["traces"]:
        if t["panel"] == panel:
            ax.plot(t["x"], t["y"], linewidth=1, label=t["series"], marker="." if len(t["x"]) < 20 else None)
    if data.get("log_x"):
        ax.set_xscale("log", base=2)
    ax.set_xlabel(data["x_label"], fontsize=8)
    ax.set_ylabel(panel, fontsize=8)
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=6, ncol=2)
fig.suptitle(f'{data["id"]} traces: {data["title"]}', fontsize=9)
fig.tight_layout()
fig.savefig(sys.argv[1], dpi=100, format="png")
)PY";

// Error images at each method's worst point, one panel each (blank: not scored); argv[1] = PNG.
constexpr const char* kHeatMapChart = R"PY(
import json, sys
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
data = json.load(sys.stdin)
maps = data["maps"]
fig, axes = plt.subplots(1, len(maps), figsize=(5.2 * len(maps), 4.8), squeeze=False)
for i, m in enumerate(maps):
    ax = axes[0][i]
    values = np.array([np.nan if v is None else v for v in m["values"]], dtype=float).reshape(m["height"], m["width"])
    image = ax.imshow(values, cmap="magma", interpolation="nearest")
    fig.colorbar(image, ax=ax, fraction=0.046, pad=0.04, label=m["unit"])
    ax.set_title(m["title"], fontsize=7, wrap=True)
    ax.set_xticks([])
    ax.set_yticks([])
fig.suptitle(f'{data["id"]} error at each method\'s worst point: {data["title"]}', fontsize=9)
fig.tight_layout()
fig.savefig(sys.argv[1], dpi=100, format="png")
)PY";

nlohmann::json traces_array(const study::SweepResult& sweep) {
  nlohmann::json traces = nlohmann::json::array();
  for (const study::SweepTrace& t : sweep.traces) {
    nlohmann::json ys = nlohmann::json::array();
    for (double y : t.y) ys.push_back(json_number(y));
    traces.push_back({{"panel", t.panel}, {"series", t.series}, {"x", t.x}, {"y", ys}});
  }
  return traces;
}

nlohmann::json traces_json(const study::SweepResult& sweep) {
  return {{"id", sweep.id}, {"title", sweep.title}, {"x_label", sweep.trace_x_label}, {"log_x", sweep.trace_log_x},
          {"traces", traces_array(sweep)}};
}

nlohmann::json heat_maps_json(const study::SweepResult& sweep) {
  nlohmann::json json = {{"id", sweep.id}, {"title", sweep.title}};
  json["maps"] = nlohmann::json::array();
  for (const study::SweepHeatMap& m : sweep.heat_maps) {
    nlohmann::json values = nlohmann::json::array();
    for (float v : m.values.values) values.push_back(json_number(v));
    json["maps"].push_back({{"title", m.title}, {"unit", m.unit}, {"width", m.values.width}, {"height", m.values.height},
                            {"values", values}});
  }
  return json;
}

nlohmann::json sweep_json(const study::SweepResult& sweep) {
  nlohmann::json json = {{"id", sweep.id}, {"title", sweep.title}, {"x_label", sweep.x_label}, {"log_x", sweep.log_x},
                         {"seconds", sweep.seconds}, {"failures", sweep.failures()}, {"points_total", sweep.points.size()}};
  json["metrics"] = nlohmann::json::array();
  for (const study::SweepMetric& m : sweep.metrics)
    json["metrics"].push_back({{"name", m.name}, {"unit", m.unit}, {"threshold", json_number(m.threshold)}});
  json["points"] = nlohmann::json::array();
  for (const study::SweepPoint& p : sweep.points)
    json["points"].push_back({{"method", p.method}, {"series", p.series}, {"x", p.x}, {"metric", p.metric},
                              {"value", json_number(p.value)}, {"pass", p.pass}});
  const study::BoundsCounts& b = sweep.bounds;
  json["bounds"] = {{"outputs", b.pixels}, {"negative", b.negative}, {"over_unshadowed", b.over_unshadowed},
                    {"non_finite", b.non_finite}, {"max_overshoot_u", b.max_overshoot_u}, {"min_value", b.min_value}};
  json["notes"] = sweep.notes;
  json["trace_x_label"] = sweep.trace_x_label;
  json["traces"] = traces_array(sweep);  // the curves of stability-<id>-traces.png
  return json;
}

}  // namespace

MethodTimings timings_from_chart_csv(const std::string& path, double* best_proxy_relative_mse) {
  MethodTimings timings;
  std::ifstream file(path);
  if (!file) return timings;
  std::string line;
  std::getline(file, line);
  const std::vector<std::string> header = split_csv_line(line);
  auto column = [&](const char* name) { return std::size_t(std::find(header.begin(), header.end(), name) - header.begin()); };
  const std::size_t scene = column("scene"), label = column("label"), ms = column("ms_per_frame"), error = column("relative_mse"),
                    method = column("method");
  double best = INFINITY;
  while (std::getline(file, line)) {
    const std::vector<std::string> cells = split_csv_line(line);
    if (cells.size() < header.size() || cells[scene] != "all") continue;
    for (const auto& [name, row] : kChartRowOf)
      if (cells[label] == row) timings[name] = std::stod(cells[ms]);
    if (cells[method] == "proxy") best = std::min(best, std::stod(cells[error]));
  }
  if (best_proxy_relative_mse != nullptr) *best_proxy_relative_mse = std::isfinite(best) ? best : 0.0;
  return timings;
}

nlohmann::json stability_json(const std::vector<study::SweepResult>& sweeps, const MethodTimings& timings) {
  nlohmann::json json;
  json["sweeps"] = nlohmann::json::array();
  std::map<std::string, std::pair<std::size_t, std::size_t>> per_method;  // points, failures
  std::vector<std::string> order;
  for (const study::SweepResult& sweep : sweeps) {
    json["sweeps"].push_back(sweep_json(sweep));
    for (const study::SweepPoint& p : sweep.points) {
      if (!per_method.count(p.method)) order.push_back(p.method);
      per_method[p.method].first += 1;
      per_method[p.method].second += p.pass ? 0 : 1;
    }
  }
  json["methods"] = nlohmann::json::array();
  for (const std::string& m : order) {
    const auto t = timings.find(m);
    json["methods"].push_back({{"method", m}, {"points", per_method[m].first}, {"failures", per_method[m].second},
                               {"ms_per_frame", t == timings.end() ? nlohmann::json(nullptr) : nlohmann::json(t->second)}});
  }
  return json;
}

std::string stability_markdown(const std::vector<study::SweepResult>& sweeps) {
  std::ostringstream md;
  for (const study::SweepResult& sweep : sweeps) {
    md << "### " << sweep.id << ": " << sweep.title << "\n\n";
    md << "| method | metric | worst | threshold | failing points | result |\n|---|---|---|---|---|---|\n";
    for (const auto& [key, worst] : worst_per_method(sweep)) {
      const study::SweepMetric& metric = sweep.metrics[std::size_t(key.second)];
      md << "| " << key.first << " | " << cell(metric.name) << " (" << metric.unit << ") | " << number(worst.value) << " | "
         << (std::isfinite(metric.threshold) ? number(metric.threshold) : std::string("none")) << " | " << worst.failures << "/"
         << worst.points << " | " << (!std::isfinite(metric.threshold) ? "measured" : worst.failures == 0 ? "pass" : "fail") << " |\n";
    }
    const study::BoundsCounts& b = sweep.bounds;
    if (b.pixels > 0)
      md << "\nFrame outputs: " << b.pixels << ", negative " << b.negative << ", above unshadowed + 1u " << b.over_unshadowed
         << ", NaN/Inf " << b.non_finite << ".\n";
    for (const std::string& note : sweep.notes) md << "- " << note << "\n";
    if (!sweep.traces.empty()) md << "- traces: stability-" << sweep.id << "-traces.png\n";
    if (!sweep.heat_maps.empty()) md << "- error at each method's worst point: stability-" << sweep.id << "-heatmaps.png\n";
    md << "\n";
  }
  return md.str();
}

std::string stability_summary_text(const std::vector<study::SweepResult>& sweeps) {
  std::ostringstream text;
  for (const study::SweepResult& sweep : sweeps) {
    text << sweep.id << " (" << number(sweep.seconds) << " s): " << sweep.failures() << "/" << sweep.points.size() << " points fail\n";
    for (const auto& [key, worst] : worst_per_method(sweep)) {
      const study::SweepMetric& metric = sweep.metrics[std::size_t(key.second)];
      text << "  " << key.first << ", " << metric.name << ": worst " << number(worst.value) << " " << metric.unit << " (threshold "
           << number(metric.threshold) << ") " << (!std::isfinite(metric.threshold) ? "measured" : worst.failures == 0 ? "pass" : "FAIL")
           << "\n";
    }
    const study::BoundsCounts& b = sweep.bounds;
    if (b.pixels > 0)
      text << "  outputs " << b.pixels << ": negative " << b.negative << ", above unshadowed " << b.over_unshadowed << ", NaN/Inf "
           << b.non_finite << "\n";
    for (const std::string& note : sweep.notes) text << "  - " << note << "\n";
  }
  return text.str();
}

Status write_stability_report(const std::string& out_dir, const std::vector<study::SweepResult>& sweeps,
                              const MethodTimings& timings) {
  std::error_code error;
  std::filesystem::create_directories(out_dir, error);
  if (error) return make_error(out_dir + ": cannot create: " + error.message());
  const std::filesystem::path dir(out_dir);
  const nlohmann::json json = stability_json(sweeps, timings);
  if (Status s = write_file_atomically(dir / "bench-stability.json", std::string_view(json.dump(1))); !s) return s;
  if (Status s = write_file_atomically(dir / "bench-stability.md", std::string_view(stability_markdown(sweeps))); !s) return s;
  for (const study::SweepResult& sweep : sweeps) {
    const std::string base = (dir / ("stability-" + sweep.id)).string();
    if (Status s = draw_matplotlib_chart(kSweepChart, sweep_json(sweep), base + ".png"); !s) return s;
    if (!sweep.traces.empty())
      if (Status s = draw_matplotlib_chart(kTraceChart, traces_json(sweep), base + "-traces.png"); !s) return s;
    if (!sweep.heat_maps.empty())
      if (Status s = draw_matplotlib_chart(kHeatMapChart, heat_maps_json(sweep), base + "-heatmaps.png"); !s) return s;
  }
  return draw_matplotlib_chart(kRobustnessChart, json, (dir / "stability-robustness-speed.png").string());
}

}  // namespace proxygi::app
