#pragma once
// Issue 18 item 5: render.quality's choices scored against the chart's own sweep, frame by frame.
// Pure data, no rendering: tests build rows by hand.
//
// For each "quality" row (study/chart_rows.h) and each of its frames, the oracle is the cheapest
// swept setting of the chooser's space (proxy rows with the averaged operator, ground bounce on,
// no anti-aliasing, no static transfer: SH order × k × upsampler) whose relative MSE on that frame
// is <= the target. A frame then
//   meets the target        when its own relative MSE <= target;
//   costs                   its own ms / the oracle row's ms (cost_ratio; its settings as rendered,
//                           η auto and sphere LOD included) and, without timing noise, the swept row
//                           of the chosen (order, k, upsampler)'s ms / the oracle's (swept_cost_ratio);
//   over-models             when the choice is costlier than the oracle's on every axis: order >=
//                           the oracle's and k <= the oracle's, not both equal (the upsampler is not
//                           an axis: neither is cheaper on every scene).
// A frame no swept setting meets is unreachable: it counts for "met" but not for the cost figures.
#include <string>
#include <vector>

#include "study/chart_rows.h"

namespace proxygi::study {

// The goals, per target over all scenes' frames.
inline constexpr double kQualityMetFractionGoal = 0.95;      // frames meeting the target
inline constexpr double kQualityCostRatioGoal = 1.2;         // cost over the oracle, each reachable frame
inline constexpr double kQualityOverModelFractionGoal = 0.10; // reachable frames over-modeled

struct QualityFrameResult {
  std::size_t frame = 0;  // index into the scene's chart frames
  ChartFrame chosen;      // the quality row's frame (its error, ms and chosen settings)
  bool met = false;
  bool reachable = false;
  std::string oracle;     // row_label of the oracle; empty when unreachable
  double oracle_milliseconds = 0.0;
  double oracle_relative_mse = 0.0;
  double cost_ratio = 0.0;        // reachable only
  double swept_cost_ratio = 0.0;  // reachable and the chosen setting swept; else 0
  bool over_modeled = false;
};

struct QualityEvaluation {
  std::string scene;
  std::string quality;  // level name
  double target = 0.0;
  std::vector<QualityFrameResult> frames;
};

// One evaluation per quality row of a scene (scene "all" skipped), in row order. A quality row
// whose frame count differs from the swept rows' is skipped.
std::vector<QualityEvaluation> evaluate_quality_rows(const std::vector<ChartRow>& rows);

// Per target, over every scene's frames.
struct QualitySummary {
  std::string quality;
  double target = 0.0;
  int frames = 0;
  int met = 0;
  int reachable = 0;
  int within_cost = 0;         // reachable frames with cost_ratio <= kQualityCostRatioGoal
  int swept_within_cost = 0;   // the same with swept_cost_ratio
  int over_modeled = 0;
  std::vector<double> cost_ratios;  // of the reachable frames, ascending (the regret distribution)
  bool goals_met() const;  // met, cost (every reachable frame) and over-modeling goals together
};
std::vector<QualitySummary> summarize_quality(const std::vector<QualityEvaluation>& evaluations);

// Markdown: the summary per target (goals, regret quantiles), then one line per scene and frame.
std::string to_quality_markdown(const std::vector<QualityEvaluation>& evaluations);
std::string to_quality_json(const std::vector<QualityEvaluation>& evaluations);  // {"summary": [...], "frames": [...]}

}  // namespace proxygi::study
