// The chart's derived results: Pareto fronts, means over scenes, the two goals and the tables.
#include "study/chart_rows.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace proxygi::study {
namespace {

ChartRow make_row(const std::string& scene, const std::string& method, double ms, double error, int order = 4,
                  int scale = 4, int samples = 0) {
  ChartRow row;
  row.scene = scene;
  row.method = method;
  row.milliseconds = ms;
  row.relative_mse = error;
  if (method == "proxy") {
    row.sh_order = order;
    row.receiver_scale = scale;
    row.upsampling = scale > 1 ? "bilateral" : "";
    row.indirect = "averaged";
  } else if (method == "vertex") {
    row.sh_order = order;
  } else {
    row.samples = samples;
  }
  return row;
}

TEST(ChartRows, LabelsNameMethodAndSetting) {
  EXPECT_EQ(row_label(make_row("s", "proxy", 1, 1, 5, 2)), "proxy n5 k2 bilateral averaged");
  EXPECT_EQ(row_label(make_row("s", "proxy", 1, 1, 3, 1)), "proxy n3 k1 averaged");
  EXPECT_EQ(row_label(make_row("s", "path+guided", 1, 1, 0, 0, 16)), "path+guided 16 spp");
  EXPECT_EQ(row_label(make_row("s", "vertex", 1, 1, 4)), "vertex n4");
  ChartRow supersampled = make_row("s", "proxy", 1, 1, 4, 4);
  supersampled.antialiasing = "ssaa2";
  EXPECT_EQ(row_label(supersampled), "proxy n4 k4 bilateral averaged ssaa2");
}

TEST(ChartRows, ParetoFrontIsPerSceneAndKeepsOnlyUndominatedRows) {
  std::vector<ChartRow> rows = {
      make_row("a", "proxy", 1.0, 0.5, 4, 8),  // fastest: front
      make_row("a", "proxy", 2.0, 0.2, 4, 4),  // front
      make_row("a", "proxy", 3.0, 0.3, 4, 2),  // dominated by the 2 ms row
      make_row("a", "path", 50.0, 0.01, 0, 0, 64),  // most accurate: front
      make_row("a", "path", 60.0, 0.01, 0, 0, 65),  // same error, slower: dominated
      make_row("b", "proxy", 3.0, 0.3, 4, 2),  // alone in its scene: front
  };
  mark_pareto_fronts(rows);
  EXPECT_TRUE(rows[0].pareto);
  EXPECT_TRUE(rows[1].pareto);
  EXPECT_FALSE(rows[2].pareto);
  EXPECT_TRUE(rows[3].pareto);
  EXPECT_FALSE(rows[4].pareto);
  EXPECT_TRUE(rows[5].pareto);
}

TEST(ChartRows, MeanOverScenesAveragesSettingsPresentEverywhere) {
  std::vector<ChartRow> rows = {make_row("a", "proxy", 2.0, 0.1), make_row("b", "proxy", 4.0, 0.3),
                                make_row("a", "vertex", 9.0, 0.2)};  // vertex missing on b: skipped
  rows[0].ssim = 0.8;
  rows[1].ssim = 0.6;
  const std::vector<ChartRow> means = mean_over_scenes(rows);
  ASSERT_EQ(means.size(), 1u);
  EXPECT_EQ(means[0].scene, kAllScenes);
  EXPECT_EQ(means[0].method, "proxy");
  EXPECT_DOUBLE_EQ(means[0].milliseconds, 3.0);
  EXPECT_DOUBLE_EQ(means[0].relative_mse, 0.2);
  EXPECT_DOUBLE_EQ(means[0].ssim, 0.7);
}

TEST(ChartRows, PathTracingGoalComparesAgainstGuidedRowsAtLeastAsBad) {
  std::vector<ChartRow> rows = {make_row("all", "proxy", 2.0, 0.05),
                                make_row("all", "path+guided", 40.0, 0.2, 0, 0, 1),
                                make_row("all", "path+guided", 150.0, 0.06, 0, 0, 4),
                                make_row("all", "path+guided", 600.0, 0.01, 0, 0, 16)};
  rows[0].is_default = true;
  GoalResult goal = path_tracing_goal(rows, "all");
  ASSERT_TRUE(goal.evaluated);
  EXPECT_TRUE(goal.met);  // 150 / 2 = 75x at the 4 spp row, whose error 0.06 >= 0.05
  EXPECT_DOUBLE_EQ(goal.ratio, 75.0);
  EXPECT_EQ(goal.compared, "path+guided 4 spp");

  rows[0].relative_mse = 0.5;  // worse than every guided row: not met
  goal = path_tracing_goal(rows, "all");
  EXPECT_FALSE(goal.met);
  EXPECT_EQ(goal.compared, "path+guided 1 spp");
  EXPECT_DOUBLE_EQ(goal.ratio, 20.0);

  rows[0].relative_mse = 0.15;  // only the 1 spp row is as bad: 20x is short of 50x
  goal = path_tracing_goal(rows, "all");
  EXPECT_FALSE(goal.met);
  EXPECT_DOUBLE_EQ(goal.ratio, 20.0);
}

TEST(ChartRows, VertexGoalPicksFastestImageSpaceRowAtEqualOrLowerError) {
  std::vector<ChartRow> rows = {make_row("all", "vertex", 10.0, 0.1, 4),
                                make_row("all", "proxy", 2.0, 0.2, 4, 8),  // too inaccurate
                                make_row("all", "proxy", 4.0, 0.1, 4, 4),  // equal error: 2.5x
                                make_row("all", "proxy", 1.0, 0.05, 3, 8)};  // other order: ignored
  GoalResult goal = vertex_goal(rows, "all", 4);
  ASSERT_TRUE(goal.evaluated);
  EXPECT_TRUE(goal.met);
  EXPECT_DOUBLE_EQ(goal.ratio, 2.5);
  rows[2].milliseconds = 6.0;
  goal = vertex_goal(rows, "all", 4);
  EXPECT_FALSE(goal.met);
  rows[2].relative_mse = 0.3;
  goal = vertex_goal(rows, "all", 4);
  EXPECT_FALSE(goal.met);
  EXPECT_TRUE(goal.compared.empty());
  EXPECT_FALSE(vertex_goal(rows, "missing", 4).evaluated);
}

TEST(ChartRows, TablesCarryEveryRow) {
  std::vector<ChartRow> rows = {make_row("a", "proxy", 2.0, 0.1), make_row("a", "path", 30.0, 0.4, 0, 0, 1)};
  mark_pareto_fronts(rows);
  const std::string csv = to_csv(rows);
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 3);
  EXPECT_NE(csv.find("a,proxy,proxy n4 k4 bilateral averaged,4,4,bilateral,averaged,0,2,0.1"), std::string::npos);
  const std::string markdown = to_markdown(rows, "a");
  EXPECT_NE(markdown.find("| proxy n4 k4 bilateral averaged | 2.00 | 0.1 |"), std::string::npos);
  EXPECT_EQ(markdown.find("path 1 spp | 30.00 | 0.4 | 0 | 0.0000 | 0.0000 | yes"), std::string::npos);  // dominated
}

}  // namespace
}  // namespace proxygi::study
