#include "apps/bench_chart_bounce.h"

#include <algorithm>
#include <filesystem>
#include <sstream>

#include "apps/matplotlib_chart.h"
#include "base/atomic_file.h"

namespace proxygi::app {
namespace {

// Reads {"scenes": [...], "rows": [{scene, indirect, bounce, ms}]} on stdin; argv[1] = PNG.
constexpr const char* kBounceScript = R"PY(
import json, sys
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
data = json.load(sys.stdin)
scenes = data["scenes"]
methods = []
for row in data["rows"]:
    if row["indirect"] not in methods:
        methods.append(row["indirect"])
fig, (top, bottom) = plt.subplots(2, 1, figsize=(max(7.0, 0.9 * len(scenes) + 3.0), 8.0), sharex=True,
                                  gridspec_kw={"height_ratios": [3, 1.4]})
x = list(range(len(scenes)))
for index, method in enumerate(methods):
    by_scene = {r["scene"]: r for r in data["rows"] if r["indirect"] == method}
    ys = [by_scene[s]["bounce"] if s in by_scene and by_scene[s]["bounce"] > 0 else float("nan") for s in scenes]
    ms = [by_scene[s]["ms"] if s in by_scene else float("nan") for s in scenes]
    style = "--" if method == "none" else ("-" if method.startswith("vsgl") else "-.")
    top.plot(x, ys, style, marker="o", label=method, color="C%d" % (index % 10))
    bottom.plot(x, ms, style, marker="o", color="C%d" % (index % 10))
top.set_yscale("log")
top.set_ylabel("bounce relative MSE (none = 1)")
top.grid(True, which="both", alpha=0.3)
top.legend(fontsize=8, ncol=2)
top.set_title("Bounce alone: sum (x - r)^2 / sum r^2\nover the pixels with a significant reference bounce", fontsize=10)
bottom.set_ylabel("ms per frame")
bottom.grid(True, alpha=0.3)
bottom.set_xticks(x)
bottom.set_xticklabels(scenes, rotation=30, ha="right")
fig.tight_layout()
fig.savefig(sys.argv[1], dpi=110, format="png")
)PY";

}  // namespace

Status write_bounce_report(const std::string& folder, const std::vector<study::BounceRow>& rows,
                           const ChartReportContext& context) {
  std::error_code error;
  std::filesystem::create_directories(folder, error);
  if (error) return make_error(folder + ": cannot create: " + error.message());
  const std::filesystem::path base = std::filesystem::path(folder) / "bench-chart-bounce";
  if (Status s = write_file_atomically(base.string() + ".csv", study::to_bounce_csv(rows)); !s) return s;
  std::ostringstream markdown;
  markdown << "# Bounce chart (`proxygi bench chart`)\n\n"
           << context.size << "x" << context.size << " pixels, " << context.frames << " frames per scene, "
           << context.reference_spp << " spp references under the " << context.lighting << "; Vulkan device "
           << context.device << ".\n\n"
           << "Reference bounce = path trace minus the same path trace (same seed and samples) in which the characters "
              "reflect nothing after the first vertex; a row's bounce = its frame minus the frame with "
              "`render.indirect_method none` (default SH order, receiver scale and upsampling). bounce relMSE = "
              "sum (x - r)^2 / sum r^2 over the receivers whose reference bounce is at least "
           << 100.0 * study::kSignificantBounce
           << " % of their radiance (none scores 1); character / contact / ground / other: the same over the whole region (other: "
              "what the pixel centre sees is neither a character nor the ground, e.g. the wall; contact: ground within "
           << study::kContactRadiusM << " m of a character). Brightness: sum of the row's bounce luminance over the "
              "reference's. image relMSE: the main chart's whole-image error.\n";
  markdown << study::to_bounce_markdown(rows);
  if (Status s = write_file_atomically(base.string() + ".md", markdown.str()); !s) return s;
  nlohmann::json data;
  std::vector<std::string> scenes;
  data["rows"] = nlohmann::json::array();
  for (const study::BounceRow& row : rows) {
    if (std::find(scenes.begin(), scenes.end(), row.row.scene) == scenes.end()) scenes.push_back(row.row.scene);
    data["rows"].push_back({{"scene", row.row.scene}, {"indirect", row.row.indirect},
                            {"bounce", row.bounce.significant.relative_mse}, {"ms", row.row.milliseconds}});
  }
  data["scenes"] = scenes;
  return draw_matplotlib_chart(kBounceScript, data, base.string() + ".png");
}

}  // namespace proxygi::app
