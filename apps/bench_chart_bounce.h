#pragma once
// The bounce chart `proxygi bench chart` writes beside the main one: bench-chart-bounce.csv
// (study::to_bounce_csv), .md (the machine line, how the bounce is scored, one table per scene)
// and .png (bounce relMSE per scene, one line per indirect method, log scale; and ms per frame).
#include <string>
#include <vector>

#include "apps/bench_chart_report.h"
#include "base/result.h"
#include "study/bounce_rows.h"

namespace proxygi::app {

Status write_bounce_report(const std::string& folder, const std::vector<study::BounceRow>& rows,
                           const ChartReportContext& context);

}  // namespace proxygi::app
