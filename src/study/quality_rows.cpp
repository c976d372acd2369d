#include "study/quality_rows.h"

#include <algorithm>
#include <cstdio>
#include <map>
#include <sstream>

#include <nlohmann/json.hpp>

namespace proxygi::study {
namespace {

// The chooser's space (quality/choose.h): order × k × upsampler with everything else as default.
bool in_chooser_space(const ChartRow& row) {
  return row.method == "proxy" && row.indirect == "averaged" && row.ground_bounce && row.antialiasing.empty() &&
         row.static_transfer == "l0" && row.mask_sender_light;
}

bool same_setting(const ChartRow& row, const ChartFrame& chosen) {
  return row.sh_order == chosen.sh_order && row.receiver_scale == chosen.receiver_scale &&
         row.upsampling == chosen.upsampling;
}

std::string choice_label(const ChartFrame& frame) {
  std::ostringstream label;  // (a stream: GCC 12's -Wrestrict misfires on "n" + std::to_string)
  label << 'n' << frame.sh_order << " k" << frame.receiver_scale;
  if (!frame.upsampling.empty()) label << ' ' << frame.upsampling;
  return label.str();
}

// Nearest-rank quantile of an ascending list.
double quantile(const std::vector<double>& sorted, double q) {
  if (sorted.empty()) return 0.0;
  const std::size_t index = std::min(sorted.size() - 1, std::size_t(q * double(sorted.size() - 1) + 0.5));
  return sorted[index];
}

std::string format(const char* pattern, double value) {
  char text[64];
  std::snprintf(text, sizeof text, pattern, value);
  return text;
}

}  // namespace

bool QualitySummary::goals_met() const {
  if (frames == 0) return false;
  const bool met_goal = double(met) >= kQualityMetFractionGoal * double(frames);
  const bool cost_goal = within_cost == reachable;
  const bool over_goal = double(over_modeled) <= kQualityOverModelFractionGoal * double(reachable);
  return met_goal && cost_goal && over_goal;
}

std::vector<QualityEvaluation> evaluate_quality_rows(const std::vector<ChartRow>& rows) {
  std::vector<QualityEvaluation> evaluations;
  for (const ChartRow& quality : rows) {
    if (quality.method != "quality" || quality.scene == kAllScenes || quality.frames.empty()) continue;
    std::vector<const ChartRow*> swept;
    for (const ChartRow& row : rows)
      if (row.scene == quality.scene && in_chooser_space(row) && row.frames.size() == quality.frames.size())
        swept.push_back(&row);
    QualityEvaluation evaluation{quality.scene, quality.quality, quality.quality_target, {}};
    for (std::size_t f = 0; f < quality.frames.size(); ++f) {
      QualityFrameResult result;
      result.frame = f;
      result.chosen = quality.frames[f];
      result.met = result.chosen.relative_mse <= quality.quality_target;
      const ChartRow* oracle = nullptr;
      const ChartRow* chosen_row = nullptr;
      for (const ChartRow* row : swept) {
        if (same_setting(*row, result.chosen)) chosen_row = row;
        if (row->frames[f].relative_mse <= quality.quality_target &&
            (oracle == nullptr || row->milliseconds < oracle->milliseconds))
          oracle = row;
      }
      if (oracle != nullptr && oracle->milliseconds > 0.0) {
        result.reachable = true;
        result.oracle = row_label(*oracle);
        result.oracle_milliseconds = oracle->milliseconds;
        result.oracle_relative_mse = oracle->frames[f].relative_mse;
        result.cost_ratio = result.chosen.milliseconds / oracle->milliseconds;
        if (chosen_row != nullptr) result.swept_cost_ratio = chosen_row->milliseconds / oracle->milliseconds;
        const bool same = result.chosen.sh_order == oracle->sh_order && result.chosen.receiver_scale == oracle->receiver_scale;
        result.over_modeled =
            !same && result.chosen.sh_order >= oracle->sh_order && result.chosen.receiver_scale <= oracle->receiver_scale;
      }
      evaluation.frames.push_back(std::move(result));
    }
    evaluations.push_back(std::move(evaluation));
  }
  return evaluations;
}

std::vector<QualitySummary> summarize_quality(const std::vector<QualityEvaluation>& evaluations) {
  std::vector<QualitySummary> summaries;
  std::map<std::string, std::size_t> index;
  for (const QualityEvaluation& evaluation : evaluations) {
    if (!index.count(evaluation.quality)) {
      index[evaluation.quality] = summaries.size();
      summaries.push_back({evaluation.quality, evaluation.target});
    }
    QualitySummary& summary = summaries[index[evaluation.quality]];
    for (const QualityFrameResult& frame : evaluation.frames) {
      ++summary.frames;
      summary.met += frame.met ? 1 : 0;
      if (!frame.reachable) continue;
      ++summary.reachable;
      summary.within_cost += frame.cost_ratio <= kQualityCostRatioGoal ? 1 : 0;
      summary.swept_within_cost += frame.swept_cost_ratio > 0.0 && frame.swept_cost_ratio <= kQualityCostRatioGoal ? 1 : 0;
      summary.over_modeled += frame.over_modeled ? 1 : 0;
      summary.cost_ratios.push_back(frame.cost_ratio);
    }
  }
  for (QualitySummary& summary : summaries) std::sort(summary.cost_ratios.begin(), summary.cost_ratios.end());
  return summaries;
}

std::string to_quality_markdown(const std::vector<QualityEvaluation>& evaluations) {
  std::ostringstream text;
  text << "| quality | target | frames | met | reachable | cost <= " << kQualityCostRatioGoal
       << "x oracle | (swept cost) | over-modeled | cost / oracle: min | median | 90 % | max | goals |\n"
       << "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|:---:|\n";
  for (const QualitySummary& s : summarize_quality(evaluations)) {
    text << "| " << s.quality << " | " << s.target << " | " << s.frames << " | " << s.met << " | " << s.reachable << " | "
         << s.within_cost << " | " << s.swept_within_cost << " | " << s.over_modeled;
    for (double q : {0.0, 0.5, 0.9, 1.0}) text << " | " << (s.cost_ratios.empty() ? "n/a" : format("%.2f", quantile(s.cost_ratios, q)));
    text << " | " << (s.goals_met() ? "met" : "not met") << " |\n";
  }
  text << "\n| scene | quality | frame | chosen | relative MSE | met | ms | oracle | oracle relMSE | oracle ms | cost / oracle "
          "| swept cost / oracle | over-modeled |\n"
       << "|---|---|---:|---|---:|:---:|---:|---|---:|---:|---:|---:|:---:|\n";
  for (const QualityEvaluation& evaluation : evaluations)
    for (const QualityFrameResult& f : evaluation.frames) {
      text << "| " << evaluation.scene << " | " << evaluation.quality << " | " << f.frame << " | " << choice_label(f.chosen)
           << " | " << format("%.4g", f.chosen.relative_mse) << " | " << (f.met ? "yes" : "**no**") << " | "
           << format("%.2f", f.chosen.milliseconds) << " | ";
      if (f.reachable)
        text << f.oracle << " | " << format("%.4g", f.oracle_relative_mse) << " | " << format("%.2f", f.oracle_milliseconds)
             << " | " << format("%.2f", f.cost_ratio) << " | "
             << (f.swept_cost_ratio > 0.0 ? format("%.2f", f.swept_cost_ratio) : std::string("n/a")) << " | "
             << (f.over_modeled ? "yes" : "") << " |\n";
      else
        text << "none meets it | | | | | |\n";
    }
  return text.str();
}

std::string to_quality_json(const std::vector<QualityEvaluation>& evaluations) {
  nlohmann::json out;
  out["summary"] = nlohmann::json::array();
  for (const QualitySummary& s : summarize_quality(evaluations))
    out["summary"].push_back({{"quality", s.quality},
                              {"target", s.target},
                              {"frames", s.frames},
                              {"met", s.met},
                              {"reachable", s.reachable},
                              {"within_cost", s.within_cost},
                              {"swept_within_cost", s.swept_within_cost},
                              {"over_modeled", s.over_modeled},
                              {"cost_ratios", s.cost_ratios},
                              {"goals_met", s.goals_met()}});
  out["frames"] = nlohmann::json::array();
  for (const QualityEvaluation& evaluation : evaluations)
    for (const QualityFrameResult& f : evaluation.frames)
      out["frames"].push_back({{"scene", evaluation.scene},
                               {"quality", evaluation.quality},
                               {"target", evaluation.target},
                               {"frame", f.frame},
                               {"chosen", choice_label(f.chosen)},
                               {"relative_mse", f.chosen.relative_mse},
                               {"ms_per_frame", f.chosen.milliseconds},
                               {"met", f.met},
                               {"reachable", f.reachable},
                               {"oracle", f.oracle},
                               {"oracle_relative_mse", f.oracle_relative_mse},
                               {"oracle_ms_per_frame", f.oracle_milliseconds},
                               {"cost_ratio", f.cost_ratio},
                               {"swept_cost_ratio", f.swept_cost_ratio},
                               {"over_modeled", f.over_modeled}});
  return out.dump(1) + "\n";
}

}  // namespace proxygi::study
