#include "apps/bench_chart_report.h"

#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

#include "apps/matplotlib_chart.h"
#include "base/atomic_file.h"
#include "scene/scene.h"
#include "study/quality_rows.h"

namespace proxygi::app {
namespace {

std::string cpu_model() {
  std::ifstream info("/proc/cpuinfo");
  std::string line;
  while (std::getline(info, line))
    if (line.rfind("model name", 0) == 0) {
      const std::size_t colon = line.find(':');
      if (colon != std::string::npos) return line.substr(colon + 2);
    }
  return "unknown CPU";
}

std::string machine_line(const ChartReportContext& context) {
  std::ostringstream text;
  text << "Measured on " << (context.cpu.empty() ? cpu_model() : context.cpu) << " (" << std::thread::hardware_concurrency() << " hardware threads), Vulkan "
       << "device " << context.device << " (" << context.driver << "); " << context.size << "x" << context.size
       << " pixels, " << context.frames << " frames of motion per scene, " << context.timing_frames
       << " pipelined frames timed per setting; references: one-bounce path tracing at " << context.reference_spp
       << " spp under the " << context.lighting << ".";
  return text.str();
}

std::string goal_line(const char* name, const study::GoalResult& goal) {
  std::ostringstream text;
  text << "- **" << name << "**: ";
  if (!goal.evaluated) return text.str() + "not evaluated (rows missing)\n";
  text << (goal.met ? "met" : "not met");
  if (!goal.compared.empty()) text << " (" << goal.ratio << "x against " << goal.compared << ")";
  text << ". " << goal.note << ".\n";
  return text.str();
}

// Reads the rows as JSON on stdin; one log–log panel per scene; argv[1] = PNG.
constexpr const char* kChartScript = R"PY(
import json, sys, math
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
data = json.load(sys.stdin)
rows = data["rows"]
scenes = data["scenes"]
columns = min(3, len(scenes))
lines = math.ceil(len(scenes) / columns)
fig, axes = plt.subplots(lines, columns, figsize=(6.2 * columns, 5.0 * lines), squeeze=False)
style = {"proxy": ("tab:blue", "o"), "quality": ("tab:purple", "*"), "vertex": ("tab:red", "s"), "ao": ("tab:orange", "^"),
         "path": ("tab:gray", "x"), "path+guided": ("tab:green", "D")}
for index, scene in enumerate(scenes):
    ax = axes[index // columns][index % columns]
    mine = [r for r in rows if r["scene"] == scene]
    for method, (color, marker) in style.items():
        points = [r for r in mine if r["method"] == method]
        if points:
            ax.scatter([r["ms_per_frame"] for r in points], [r["relative_mse"] for r in points], color=color,
                       marker=marker, s=18, alpha=0.75, label=method)
    front = sorted([r for r in mine if r["pareto"]], key=lambda r: r["ms_per_frame"])
    ax.plot([r["ms_per_frame"] for r in front], [r["relative_mse"] for r in front], color="black", lw=0.8,
            label="Pareto front")
    # Front members are numbered on the plot and named in a box (labels would overlap).
    names = []
    for number, r in enumerate(front, start=1):
        ax.annotate(str(number), (r["ms_per_frame"], r["relative_mse"]), fontsize=6, xytext=(2, -8),
                    textcoords="offset points")
        names.append(f'{number}: {r["label"]}')
    ax.text(0.99, 0.99, "Pareto front\n" + "\n".join(names), transform=ax.transAxes, fontsize=5.5,
            va="top", ha="right", family="monospace", bbox=dict(facecolor="white", alpha=0.85, lw=0.3))
    for r in mine:
        if r["default"] and r["method"] == "proxy":
            ax.scatter([r["ms_per_frame"]], [r["relative_mse"]], facecolors="none", edgecolors="black", s=90,
                       label="default setting")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("ms per frame (this machine)")
    ax.set_ylabel("relative MSE vs reference")
    ax.set_title("mean over scenes" if scene == "all" else scene, fontsize=10)
    ax.grid(True, which="both", alpha=0.25)
    if index == 0:
        ax.legend(fontsize=7, loc="upper left")
for index in range(len(scenes), lines * columns):
    axes[index // columns][index % columns].axis("off")
fig.suptitle(data["machine"], fontsize=7, wrap=True)
fig.tight_layout(rect=(0, 0, 1, 0.95))
fig.savefig(sys.argv[1], dpi=110, format="png")
)PY";

// Reads bench-chart-quality.json on stdin; argv[1] = PNG. Left: each reachable frame's cost over
// the oracle (the regret), right: each frame's error over its target, per level.
constexpr const char* kQualityChartScript = R"PY(
import json, sys
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
data = json.load(sys.stdin)
levels = [s["quality"] for s in data["summary"]]
scenes = sorted({f["scene"] for f in data["frames"]})
markers = "osD^v<>"
fig, (cost, error) = plt.subplots(1, 2, figsize=(10, 4.2))
for si, scene in enumerate(scenes):
    for li, level in enumerate(levels):
        frames = [f for f in data["frames"] if f["scene"] == scene and f["quality"] == level]
        x = [li + (si - (len(scenes) - 1) / 2) * 0.12 for _ in frames]
        reach = [(xx, f) for xx, f in zip(x, frames) if f["reachable"]]
        cost.scatter([xx for xx, f in reach], [f["cost_ratio"] for xx, f in reach], marker=markers[si % len(markers)],
                     facecolors=["tab:blue" if f["met"] else "none" for xx, f in reach], edgecolors="tab:blue", s=28,
                     label=scene if li == 0 else None)
        error.scatter(x, [f["relative_mse"] / f["target"] for f in frames], marker=markers[si % len(markers)],
                      facecolors=["tab:green" if f["met"] else "none" for f in frames], edgecolors="tab:green", s=28,
                      label=scene if li == 0 else None)
for ax, line, label in ((cost, 1.2, "cost / oracle: ms of the choice over the cheapest swept setting that meets the target"),
                        (error, 1.0, "relative MSE / target")):
    ax.axhline(line, color="black", lw=0.8, ls="--")
    ax.set_xticks(range(len(levels)))
    ax.set_xticklabels([f'{s["quality"]}\n{s["target"]:g}' for s in data["summary"]])
    ax.set_yscale("log")
    ax.set_ylabel(label, fontsize=7)
    ax.grid(True, which="both", alpha=0.25)
    ax.legend(fontsize=7)
cost.set_title("regret per frame (filled: target met; unreachable frames left out)", fontsize=8)
error.set_title("error per frame against its target (filled: met)", fontsize=8)
fig.tight_layout()
fig.savefig(sys.argv[1], dpi=110, format="png")
)PY";

constexpr const char* kQualitySectionIntro =
    "Each quality row renders every chart frame with the settings render.quality chose for that frame's shot. "
    "The oracle is the cheapest swept setting (proxy rows, averaged operator: SH order x k x upsampler) whose "
    "relative MSE on that frame meets the target; cost / oracle is the frame's own ms (eta auto included) over "
    "the oracle row's, swept cost the same with the swept row of the chosen order, k and upsampler. "
    "Over-modeled: the choice's order >= the oracle's and k <= the oracle's, not both equal. Goals (issue 18 item 5): "
    "met on >= 95 % of frames, cost <= 1.2x the oracle, over-modeled on <= 10 % of frames.";

}  // namespace

nlohmann::json chart_context_json(const ChartReportContext& context) {
  nlohmann::json out = {{"device", context.device},   {"driver", context.driver},
                        {"size", context.size},       {"frames", context.frames},
                        {"timing_frames", context.timing_frames}, {"reference_spp", context.reference_spp},
                        {"lighting", context.lighting}, {"scenes", context.scenes}};
  if (context.regions) out["regions"] = true;  // absent without --regions: files as before
  return out;
}

Result<ChartReportContext> chart_context_from_json(const nlohmann::json& json) {
  try {
    ChartReportContext context;
    context.device = json.at("device").get<std::string>();
    context.driver = json.at("driver").get<std::string>();
    context.size = json.at("size").get<int>();
    context.frames = json.at("frames").get<int>();
    context.timing_frames = json.at("timing_frames").get<int>();
    context.reference_spp = json.at("reference_spp").get<int>();
    context.lighting = json.at("lighting").get<std::string>();
    context.scenes = json.at("scenes").get<std::vector<std::string>>();
    context.regions = json.value("regions", false);
    return context;
  } catch (const nlohmann::json::exception& e) {
    return make_error(std::string("chart context: ") + e.what());
  }
}

std::string chart_scores_json(const std::vector<study::ChartRow>& rows, const ChartReportContext& context) {
  nlohmann::json out;
  out["context"] = chart_context_json(context);
  out["rows"] = nlohmann::json::array();
  const nlohmann::json full = nlohmann::json::parse(study::to_json(rows));
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const study::ChartRow& row = rows[i];
    out["rows"].push_back({{"scene", row.scene}, {"label", study::row_label(row)}, {"default", row.is_default},
                           {"relative_mse", row.relative_mse}, {"rmse", row.rmse}, {"ssim", row.ssim}, {"flip", row.flip}});
    if (row.regions.measured) out["rows"].back()["regions"] = full[i].at("regions");
    // Per-frame errors (the quality rows' oracle) and what render.quality chose: no time.
    if (!row.frames.empty()) {
      nlohmann::json frames = full[i].at("frames");
      for (nlohmann::json& frame : frames) frame.erase("ms_per_frame");
      out["rows"].back()["frames"] = frames;
    }
  }
  return out.dump(1) + "\n";
}

std::string chart_timings_json(const std::vector<study::ChartRow>& rows) {
  nlohmann::json out;
  out["rows"] = nlohmann::json::array();
  for (const study::ChartRow& row : rows) {
    out["rows"].push_back({{"scene", row.scene}, {"label", study::row_label(row)}, {"ms_per_frame", row.milliseconds}});
    if (row.method != "quality" || row.frames.empty()) continue;
    std::vector<double> frame_ms;
    for (const study::ChartFrame& frame : row.frames) frame_ms.push_back(frame.milliseconds);
    out["rows"].back()["frame_ms"] = frame_ms;
  }
  return out.dump(1) + "\n";
}

std::string goal_scene(const std::vector<study::ChartRow>& rows) {
  for (const study::ChartRow& row : rows)
    if (row.scene == study::kAllScenes) return study::kAllScenes;
  return rows.empty() ? std::string() : rows.front().scene;
}

nlohmann::json chart_report_json(const std::vector<study::ChartRow>& rows, const ChartReportContext& context) {
  nlohmann::json out;
  out["machine"] = machine_line(context);
  out["rows"] = nlohmann::json::parse(study::to_json(rows));
  std::vector<std::string> scenes;
  const std::string summary = goal_scene(rows);
  if (summary == study::kAllScenes) scenes.push_back(summary);
  for (const std::string& scene : context.scenes) scenes.push_back(scene);
  out["scenes"] = scenes;
  auto goal_json = [](const study::GoalResult& goal) {
    return nlohmann::json{{"evaluated", goal.evaluated}, {"met", goal.met}, {"ratio", goal.ratio},
                          {"compared", goal.compared}, {"note", goal.note}};
  };
  if (const auto quality = study::evaluate_quality_rows(rows); !quality.empty())
    out["quality"] = nlohmann::json::parse(study::to_quality_json(quality));
  out["goals"]["scene"] = summary;
  out["goals"]["path_tracing_50x"] = goal_json(study::path_tracing_goal(rows, summary));
  out["goals"]["vertex_2x"] = goal_json(study::vertex_goal(rows, summary, settings::RenderSettings{}.sh_order));
  for (const std::string& scene : context.scenes)
    out["goals_per_scene"][scene] = {
        {"path_tracing_50x", goal_json(study::path_tracing_goal(rows, scene))},
        {"vertex_2x", goal_json(study::vertex_goal(rows, scene, settings::RenderSettings{}.sh_order))}};
  return out;
}

std::string chart_summary_text(const std::vector<study::ChartRow>& rows, const ChartReportContext& context) {
  const std::string scene = goal_scene(rows);
  std::ostringstream text;
  text << machine_line(context) << "\n\nGoals (scene " << scene << "):\n"
       << goal_line("proxy default vs guided path tracing, >= 50x less time at its error",
                    study::path_tracing_goal(rows, scene))
       << goal_line("image space >= 2x faster than vertex-based at equal or lower error", study::vertex_goal(rows, scene, settings::RenderSettings{}.sh_order));
  for (const study::QualitySummary& q : study::summarize_quality(study::evaluate_quality_rows(rows)))
    text << "- **render.quality " << q.quality << " (" << q.target << ")**: " << (q.goals_met() ? "met" : "not met")
         << ": target met on " << q.met << "/" << q.frames << " frames; of " << q.reachable << " reachable, " << q.within_cost
         << " within " << study::kQualityCostRatioGoal << "x the oracle's time, " << q.over_modeled << " over-modeled.\n";
  text << "\n" << study::to_markdown(rows, scene);
  return text.str();
}

Status write_chart_report(const std::string& folder, const std::vector<study::ChartRow>& rows,
                          const ChartReportContext& context) {
  std::error_code error;
  std::filesystem::create_directories(folder, error);
  if (error) return make_error(folder + ": cannot create: " + error.message());
  const std::filesystem::path base = std::filesystem::path(folder) / "bench-chart";
  if (Status s = write_file_atomically(base.string() + ".csv", study::to_csv(rows)); !s) return s;
  if (Status s = write_file_atomically(base.string() + "-scores.json", chart_scores_json(rows, context)); !s) return s;
  if (Status s = write_file_atomically(base.string() + "-timings.json", chart_timings_json(rows)); !s) return s;

  std::ostringstream markdown;
  markdown << "# Speed–accuracy chart (`proxygi bench chart`)\n\n" << chart_summary_text(rows, context);
  const int order = settings::RenderSettings{}.sh_order;
  for (const std::string& scene : context.scenes)
    markdown << "\n## " << scene << "\n\n"
             << goal_line("50x", study::path_tracing_goal(rows, scene))
             << goal_line("2x", study::vertex_goal(rows, scene, order)) << "\n"
             << study::to_markdown(rows, scene);
  if (context.regions) {
    markdown << "\n## Error by region\n\n"
             << "Relative MSE over each region of the reference (study/chart_regions.h): shadow (ground and other "
                "non-character receivers whose reference direct light is > 5 % below unshadowed), edge (2 px around "
                "depth or normal jumps), thin (character parts narrower than 4 px), character (the body as receiver), "
                "contact (ground within 0.3 m of a character), near_wall and open_floor (ground within 0.5 m of a "
                "static mesh, farther than 1 m from all; scenes with static meshes); n/a = empty region. Bounds: "
                "pixels per frame with a "
                "channel < 0, above unshadowed + the reference's bounce by > 1/255, or NaN/Inf.\n";
    std::vector<std::string> scenes;
    if (goal_scene(rows) == study::kAllScenes) scenes.push_back(study::kAllScenes);
    for (const std::string& scene : context.scenes) scenes.push_back(scene);
    for (const std::string& scene : scenes)
      markdown << "\n### " << (scene == study::kAllScenes ? "mean over scenes" : scene) << "\n\n"
               << study::to_region_markdown(rows, scene);
  }
  const std::vector<study::QualityEvaluation> quality = study::evaluate_quality_rows(rows);
  if (!quality.empty()) {
    markdown << "\n## render.quality against the sweep\n\n" << kQualitySectionIntro << "\n\n" << study::to_quality_markdown(quality);
    const std::string quality_json = study::to_quality_json(quality);
    if (Status s = write_file_atomically(base.string() + "-quality.json", quality_json); !s) return s;
    if (Status s = draw_matplotlib_chart(kQualityChartScript, nlohmann::json::parse(quality_json), base.string() + "-quality.png");
        !s)
      return s;
    markdown << "\n![render.quality per frame](bench-chart-quality.png)\n";
  }
  if (Status s = write_file_atomically(base.string() + ".md", markdown.str()); !s) return s;
  return draw_matplotlib_chart(kChartScript, chart_report_json(rows, context), base.string() + ".png");
}

}  // namespace proxygi::app
