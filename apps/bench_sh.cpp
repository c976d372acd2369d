// proxygi bench sh [--json] [--chart FILE.png] [--csv FILE.csv] [--receivers N] [--seed S]
//                  [--orders 3,4,5] [--min-time SECONDS]
// The SH exponential accuracy study (sh/accuracy_study.h): error and cost of every exponential
// method at each order against the projected true visibility, and the indirect operator errors
// (paper Figure 5). Text table by default; --json prints one JSON object on stdout. --chart draws
// error against cost with matplotlib (/usr/bin/python3, script embedded here, data on stdin).
// Exit codes: 0 ok, 1 chart/CSV failure, 2 bad options.
#include <cstdio>
#include <memory>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "apps/commands.h"
#include "settings/render_settings.h"
#include "apps/matplotlib_chart.h"
#include "base/atomic_file.h"
#include "sh/accuracy_study.h"

namespace proxygi::app {
namespace {

struct BenchShArgs {
  bool json = false;
  std::string chart;
  std::string csv;
  int receivers = 300;
  unsigned seed = 2007;
  std::vector<int> orders = {3, 4, 5};
  double min_time = 0.05;
};

nlohmann::json study_to_json(const sh::AccuracyStudyResult& study) {
  nlohmann::json json;
  const sh::AccuracyStudyOptions& o = study.options;
  json["config"] = {{"receivers", o.receivers},
                    {"min_spheres", o.min_spheres},
                    {"max_spheres", o.max_spheres},
                    {"min_half_angle_degrees", o.min_half_angle_degrees},
                    {"max_half_angle_degrees", o.max_half_angle_degrees},
                    {"orders", o.orders},
                    {"seed", o.seed},
                    {"reference_grid", {o.reference_z_nodes, o.reference_phi_samples}},
                    {"table_rows", o.table_rows},
                    {"mean_spheres_per_receiver", study.mean_spheres_per_receiver}};
  json["exponential"] = nlohmann::json::array();
  for (const sh::ExponentialMethodResult& r : study.exponential)
    json["exponential"].push_back({{"method", r.method},
                                   {"order", r.order},
                                   {"mean_relative_error", r.mean_error},
                                   {"median_relative_error", r.median_error},
                                   {"p95_relative_error", r.p95_error},
                                   {"ns_per_evaluation", r.ns_per_evaluation},
                                   {"mean_squarings", r.mean_squarings},
                                   {"max_squarings", r.max_squarings}});
  json["indirect"] = nlohmann::json::array();
  for (const sh::IndirectOperatorRow& r : study.indirect) {
    nlohmann::json row = {{"order", r.order}, {"sin_theta", r.sin_theta}, {"point_error", r.point_error}, {"averaged_error", r.averaged_error}};
    row["averaged_polynomial_error"] = r.averaged_polynomial_error < 0.0 ? nlohmann::json(nullptr) : nlohmann::json(r.averaged_polynomial_error);
    json["indirect"].push_back(row);
  }
  json["seconds"] = study.seconds;
  return json;
}

std::string study_to_text(const sh::AccuracyStudyResult& study) {
  std::ostringstream text;
  char line[256];
  std::snprintf(line, sizeof line, "SH exponential study: %d receivers, %.2f spheres each on average (%d-%d, %.0f-%.0f deg), seed %u\n",
                study.options.receivers, study.mean_spheres_per_receiver, study.options.min_spheres, study.options.max_spheres,
                study.options.min_half_angle_degrees, study.options.max_half_angle_degrees, study.options.seed);
  text << line << "relative L2 error of the visibility vector against the projected true visibility\n\n";
  text << "order  method      mean     median   p95      ns/eval   squarings(mean/max)\n";
  for (const sh::ExponentialMethodResult& r : study.exponential) {
    std::snprintf(line, sizeof line, "%5d  %-10s %6.2f%%  %6.2f%%  %6.2f%%  %8.0f", r.order, r.method.c_str(), 100 * r.mean_error,
                  100 * r.median_error, 100 * r.p95_error, r.ns_per_evaluation);
    text << line;
    if (r.method.rfind("hyb", 0) == 0) {
      std::snprintf(line, sizeof line, "   %.2f / %d", r.mean_squarings, r.max_squarings);
      text << line;
    }
    text << "\n";
  }
  text << "\nindirect operators: relative Frobenius error against exact (paper Figure 5)\n";
  text << "order  sin(theta)  point     averaged  averaged(polynomial fit)\n";
  for (const sh::IndirectOperatorRow& r : study.indirect) {
    std::snprintf(line, sizeof line, "%5d  %9.2f  %7.4f   %7.4f", r.order, r.sin_theta, r.point_error, r.averaged_error);
    text << line;
    if (r.averaged_polynomial_error >= 0.0) {
      std::snprintf(line, sizeof line, "   %7.4f", r.averaged_polynomial_error);
      text << line;
    }
    text << "\n";
  }
  std::snprintf(line, sizeof line, "\n(%.1f s)\n", study.seconds);
  text << line;
  return text.str();
}

std::string study_to_csv(const sh::AccuracyStudyResult& study) {
  std::ostringstream csv;
  csv << "kind,method,order,sin_theta,mean_relative_error,median_relative_error,p95_relative_error,ns_per_evaluation,"
         "point_error,averaged_error,averaged_polynomial_error\n";
  for (const sh::ExponentialMethodResult& r : study.exponential)
    csv << "exponential," << r.method << "," << r.order << ",," << r.mean_error << "," << r.median_error << "," << r.p95_error << ","
        << r.ns_per_evaluation << ",,,\n";
  for (const sh::IndirectOperatorRow& r : study.indirect) {
    csv << "indirect,," << r.order << "," << r.sin_theta << ",,,,," << r.point_error << "," << r.averaged_error << ",";
    if (r.averaged_polynomial_error >= 0.0) csv << r.averaged_polynomial_error;
    csv << "\n";
  }
  return csv.str();
}

// Reads the study JSON on stdin, writes the PNG named by argv[1].
constexpr const char* kChartScript = R"PY(
import json, sys
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
study = json.load(sys.stdin)
fig, (left, right) = plt.subplots(1, 2, figsize=(13, 5.2))
markers = {3: "o", 4: "s", 5: "^", 6: "D"}
methods = sorted({r["method"] for r in study["exponential"]})
colors = {m: plt.cm.tab10(i % 10) for i, m in enumerate(methods)}
for r in study["exponential"]:
    left.scatter(r["ns_per_evaluation"], 100 * r["mean_relative_error"], color=colors[r["method"]],
                 marker=markers.get(r["order"], "x"), s=48)
    left.annotate(f'{r["method"]} n={r["order"]}', (r["ns_per_evaluation"], 100 * r["mean_relative_error"]),
                  fontsize=7, xytext=(3, 3), textcoords="offset points")
left.set_xscale("log")
left.set_yscale("log")
left.set_xlabel("cost per receiver (ns, CPU, same run)")
left.set_ylabel("mean relative L2 error (%)")
c = study["config"]
left.set_title(f'SH exponential: {c["receivers"]} receivers, {c["min_spheres"]}-{c["max_spheres"]} spheres of '
               f'{c["min_half_angle_degrees"]:.0f}-{c["max_half_angle_degrees"]:.0f} deg', fontsize=9)
left.grid(True, which="both", alpha=0.3)
for order in sorted({r["order"] for r in study["indirect"]}):
    rows = [r for r in study["indirect"] if r["order"] == order]
    s = [r["sin_theta"] for r in rows]
    right.plot(s, [r["point_error"] for r in rows], marker=markers.get(order, "x"), label=f"point-sampled n={order}")
    right.plot(s, [r["averaged_error"] for r in rows], marker=markers.get(order, "x"), label=f"averaged n={order}")
    fit = [r["averaged_polynomial_error"] for r in rows]
    if all(v is not None for v in fit):
        right.plot(s, fit, linestyle="--", label=f"averaged, polynomial fit n={order}")
right.set_xlabel("sin(theta)")
right.set_ylabel("relative Frobenius error vs exact")
right.set_title("Indirect operators (paper Figure 5)", fontsize=9)
right.grid(True, alpha=0.3)
right.legend(fontsize=8)
fig.tight_layout()
fig.savefig(sys.argv[1], dpi=110, format="png")
)PY";

int draw_chart(const nlohmann::json& json, const std::string& path) {
  if (const Status drawn = draw_matplotlib_chart(kChartScript, json, path); !drawn)
    return fail_runtime("bench sh: " + path + ": " + drawn.message());
  return kExitOk;
}

int run_bench_sh(const BenchShArgs& args) {
  sh::AccuracyStudyOptions options;
  if (args.receivers < 1) return fail_bad_input("bench sh: --receivers must be >= 1");
  for (int order : args.orders)
    if (order < settings::kMinShOrder || order > settings::kMaxShOrder)
      return fail_bad_input("bench sh: --orders must be in " + std::to_string(settings::kMinShOrder) + ".." +
                            std::to_string(settings::kMaxShOrder));
  if (args.min_time <= 0.0) return fail_bad_input("bench sh: --min-time must be > 0");
  options.receivers = args.receivers;
  options.seed = args.seed;
  options.orders = args.orders;
  options.min_timing_seconds = args.min_time;
  const sh::AccuracyStudyResult study = sh::run_accuracy_study(options);
  const nlohmann::json json = study_to_json(study);
  if (args.json)
    std::printf("%s\n", json.dump(2).c_str());
  else
    std::printf("%s", study_to_text(study).c_str());
  if (!args.csv.empty()) {
    const Status written = write_file_atomically(args.csv, study_to_csv(study));
    if (!written) return fail_runtime("bench sh: " + written.message());
  }
  if (!args.chart.empty()) return draw_chart(json, args.chart);
  return kExitOk;
}

}  // namespace

void add_bench_sh_command(CLI::App& bench, CommandRunner& runner) {
  auto args = std::make_shared<BenchShArgs>();
  auto* command = bench.add_subcommand("sh", "Accuracy and cost of every SH exponential and indirect operator");
  command->add_flag("--json", args->json, "Print the results as one JSON object on stdout");
  command->add_option("--chart", args->chart, "Write a PNG chart of error against cost (needs matplotlib)");
  command->add_option("--csv", args->csv, "Write the results as CSV");
  command->add_option("--receivers", args->receivers, "Random receivers (default 300)");
  command->add_option("--seed", args->seed, "Random seed (default 2007)");
  command->add_option("--orders", args->orders, "SH orders, 3..6 (default 3,4,5)")->delimiter(',');
  command->add_option("--min-time", args->min_time, "Seconds of timing per method and order (default 0.05)");
  add_quiet_flag(*command);
  command->callback([&runner, args] { runner = [args] { return run_bench_sh(*args); }; });
}

}  // namespace proxygi::app
