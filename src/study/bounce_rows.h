#pragma once
// Rows of the bounce chart (`proxygi bench chart`'s second chart, bench-chart-bounce.*): each
// indirect method at the default SH order, receiver scale and upsampling (proxy point / averaged
// / exact, vsgl1..8, none) on one scene, scored on the bounce alone (bounce_scores.h). Pure data.
#include <string>
#include <vector>

#include "study/bounce_scores.h"
#include "study/chart_rows.h"

namespace proxygi::study {

struct BounceRow {
  ChartRow row;          // identity, ms per frame and the whole-image errors
  BounceScores bounce;   // the bounce alone, mean over the chart's frames
};

// One row per indirect method present on every scene, scene = kAllScenes: the row part as
// mean_over_scenes, each region's scores the mean over the scenes where it was not empty
// (mean_bounce_scores). Rows already of kAllScenes are ignored.
std::vector<BounceRow> mean_bounce_over_scenes(const std::vector<BounceRow>& rows);

// One line per row: scene, indirect, ms, whole-image and character relMSE, then per region
// (significant, character, contact, ground, other) bounce relMSE, luminance ratio and pixels; -1 = empty.
std::string to_bounce_csv(const std::vector<BounceRow>& rows);
// One table per scene (in first-seen order), rows by bounce relMSE; empty regions print "–".
std::string to_bounce_markdown(const std::vector<BounceRow>& rows);
// For each scene, the row with the lowest bounce relMSE over the significant pixels ("" if none).
std::string best_bounce_method(const std::vector<BounceRow>& rows, const std::string& scene);

}  // namespace proxygi::study
