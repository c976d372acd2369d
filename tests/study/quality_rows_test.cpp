// render.quality's chart rows against the sweep (issue 18 item 5): oracle, met, cost, over-modeling.
#include "study/quality_rows.h"

#include <gtest/gtest.h>

namespace proxygi::study {
namespace {

// A swept proxy row of the chooser's space with one error per frame.
ChartRow swept(int order, int scale, double ms, std::vector<double> errors, const std::string& scene = "s") {
  ChartRow row;
  row.scene = scene;
  row.method = "proxy";
  row.sh_order = order;
  row.receiver_scale = scale;
  row.upsampling = scale > 1 ? "bilinear" : "";
  row.indirect = "averaged";
  row.milliseconds = ms;
  for (double error : errors) row.frames.push_back({error});
  return row;
}

ChartFrame chosen(int order, int scale, double ms, double error) {
  return {error, ms, order, scale, scale > 1 ? "bilinear" : ""};
}

ChartRow quality_row(double target, std::vector<ChartFrame> frames, const std::string& scene = "s") {
  ChartRow row;
  row.scene = scene;
  row.method = "quality";
  row.quality = "balanced";
  row.quality_target = target;
  row.frames = std::move(frames);
  return row;
}

TEST(QualityRows, LabelNamesTheLevel) { EXPECT_EQ(row_label(quality_row(0.015, {})), "quality balanced"); }

TEST(QualityRows, OracleIsTheCheapestSweptSettingMeetingTheTargetOnThatFrame) {
  std::vector<ChartRow> rows = {swept(4, 8, 4.0, {0.020, 0.012}), swept(5, 4, 7.0, {0.014, 0.011}),
                                swept(6, 2, 15.0, {0.010, 0.009})};
  // Frame 0: n5 k4 is the cheapest at <= 0.015; frame 1: n4 k8 already meets it.
  rows.push_back(quality_row(0.015, {chosen(5, 4, 7.7, 0.014), chosen(5, 4, 7.0, 0.011)}));
  const auto evaluations = evaluate_quality_rows(rows);
  ASSERT_EQ(evaluations.size(), 1u);
  ASSERT_EQ(evaluations[0].frames.size(), 2u);
  const QualityFrameResult& first = evaluations[0].frames[0];
  EXPECT_TRUE(first.met);
  EXPECT_TRUE(first.reachable);
  EXPECT_EQ(first.oracle, "proxy n5 k4 bilinear averaged");
  EXPECT_DOUBLE_EQ(first.cost_ratio, 7.7 / 7.0);
  EXPECT_DOUBLE_EQ(first.swept_cost_ratio, 1.0);
  EXPECT_FALSE(first.over_modeled);  // the oracle's own setting
  const QualityFrameResult& second = evaluations[0].frames[1];
  EXPECT_EQ(second.oracle, "proxy n4 k8 bilinear averaged");
  EXPECT_DOUBLE_EQ(second.cost_ratio, 7.0 / 4.0);
  EXPECT_TRUE(second.over_modeled);  // order 5 >= 4 and k 4 <= 8, not both equal
}

TEST(QualityRows, ACheaperAxisIsNotOverModeling) {
  // The oracle is n6 k8; n4 k4 is finer in k but lower in order: not costlier on every axis.
  std::vector<ChartRow> rows = {swept(6, 8, 5.0, {0.010}), swept(4, 4, 6.0, {0.012})};
  rows.push_back(quality_row(0.013, {chosen(4, 4, 6.0, 0.012)}));
  const auto evaluations = evaluate_quality_rows(rows);
  ASSERT_EQ(evaluations.size(), 1u);
  EXPECT_EQ(evaluations[0].frames[0].oracle, "proxy n6 k8 bilinear averaged");
  EXPECT_FALSE(evaluations[0].frames[0].over_modeled);
  EXPECT_DOUBLE_EQ(evaluations[0].frames[0].cost_ratio, 6.0 / 5.0);
}

TEST(QualityRows, AFrameNoSweptSettingMeetsIsUnreachableAndMissed) {
  std::vector<ChartRow> rows = {swept(6, 1, 40.0, {0.02})};
  rows.push_back(quality_row(0.01, {chosen(6, 1, 41.0, 0.02)}));
  const auto evaluations = evaluate_quality_rows(rows);
  ASSERT_EQ(evaluations.size(), 1u);
  EXPECT_FALSE(evaluations[0].frames[0].met);
  EXPECT_FALSE(evaluations[0].frames[0].reachable);
  EXPECT_TRUE(evaluations[0].frames[0].oracle.empty());
  const auto summaries = summarize_quality(evaluations);
  ASSERT_EQ(summaries.size(), 1u);
  EXPECT_EQ(summaries[0].frames, 1);
  EXPECT_EQ(summaries[0].met, 0);
  EXPECT_EQ(summaries[0].reachable, 0);
  EXPECT_TRUE(summaries[0].cost_ratios.empty());
  EXPECT_FALSE(summaries[0].goals_met());
}

TEST(QualityRows, RowsOutsideTheChoosersSpaceAreNeverTheOracle) {
  ChartRow supersampled = swept(4, 8, 2.0, {0.001});
  supersampled.antialiasing = "ssaa2";
  ChartRow other_scene = swept(4, 8, 1.0, {0.001}, "t");
  ChartRow exact = swept(4, 8, 1.5, {0.001});
  exact.indirect = "exact";
  std::vector<ChartRow> rows = {supersampled, other_scene, exact, swept(5, 4, 7.0, {0.010})};
  rows.push_back(quality_row(0.015, {chosen(5, 4, 7.0, 0.010)}));
  const auto evaluations = evaluate_quality_rows(rows);
  ASSERT_EQ(evaluations.size(), 1u);
  EXPECT_EQ(evaluations[0].frames[0].oracle, "proxy n5 k4 bilinear averaged");
}

TEST(QualityRows, SummaryCountsEveryScenesFramesPerTargetAndChecksTheGoals) {
  std::vector<ChartRow> rows = {swept(4, 8, 4.0, {0.012, 0.012}, "a"), swept(4, 8, 4.0, {0.012}, "b")};
  rows.push_back(quality_row(0.015, {chosen(4, 8, 4.2, 0.012), chosen(4, 8, 4.4, 0.012)}, "a"));
  rows.push_back(quality_row(0.015, {chosen(4, 8, 4.0, 0.012)}, "b"));
  const auto summaries = summarize_quality(evaluate_quality_rows(rows));
  ASSERT_EQ(summaries.size(), 1u);
  EXPECT_EQ(summaries[0].frames, 3);
  EXPECT_EQ(summaries[0].met, 3);
  EXPECT_EQ(summaries[0].reachable, 3);
  EXPECT_EQ(summaries[0].within_cost, 3);
  EXPECT_EQ(summaries[0].over_modeled, 0);
  ASSERT_EQ(summaries[0].cost_ratios.size(), 3u);
  EXPECT_DOUBLE_EQ(summaries[0].cost_ratios.front(), 1.0);
  EXPECT_DOUBLE_EQ(summaries[0].cost_ratios.back(), 1.1);
  EXPECT_TRUE(summaries[0].goals_met());
  // One frame 1.3x the oracle's time breaks the cost goal.
  rows.back().frames[0].milliseconds = 5.2;
  EXPECT_FALSE(summarize_quality(evaluate_quality_rows(rows))[0].goals_met());
}

TEST(QualityRows, TablesAndJsonNameEachFrame) {
  std::vector<ChartRow> rows = {swept(4, 8, 4.0, {0.012})};
  rows.push_back(quality_row(0.015, {chosen(4, 8, 4.0, 0.012)}));
  const auto evaluations = evaluate_quality_rows(rows);
  const std::string markdown = to_quality_markdown(evaluations);
  EXPECT_NE(markdown.find("| s | balanced | 0 | n4 k8 bilinear | 0.012 | yes |"), std::string::npos) << markdown;
  const std::string json = to_quality_json(evaluations);
  EXPECT_NE(json.find("\"oracle\": \"proxy n4 k8 bilinear averaged\""), std::string::npos) << json;
}

}  // namespace
}  // namespace proxygi::study
