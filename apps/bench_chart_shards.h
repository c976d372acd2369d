#pragma once
// `proxygi bench chart --shard I/N` and `bench chart --merge DIR...`: the chart's work units, the
// partial file each shard writes, and the merge back into the rows a single run measures.
//
// Units, in order: per chart scene (chart order) first its path tracing (every sample count,
// plain and guided), then each setting of the method grid in grid order, so unit
//   u = scene_index · (grid size + 1) + (0 for path tracing, 1 + grid index for a setting).
// Shard I of N measures run::shard_slice(units, I/N), a contiguous run, so a scene's references
// are traced by as few shards as possible. Every unit's errors are deterministic (seeded tracing,
// one renderer per scene); only its ms per frame are measured. The merge orders rows by unit,
// which is the order of a single run, so derived rows (means, Pareto fronts) follow the same rules.
//
//   bench chart --quick --shard 0/2 --out s0 ; bench chart --quick --shard 1/2 --out s1
//   bench chart --merge s0 s1 --out merged   # merged/bench-chart-scores.json == a single run's
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "apps/bench_chart_report.h"
#include "base/result.h"
#include "run/frame_plan.h"
#include "study/bounce_rows.h"
#include "study/chart_rows.h"

namespace proxygi::app {

inline constexpr const char* kChartShardFile = "bench-chart-shard.json";

struct UnitRow {
  std::size_t unit = 0;
  study::ChartRow row;
};

// A bounce chart row (study/bounce_rows.h) of the unit whose setting it scores.
struct UnitBounceRow {
  std::size_t unit = 0;
  study::BounceRow row;
};

// What one shard measured. `context.cpu` is not kept (the merge names its own machine).
struct ChartShard {
  ChartReportContext context;
  bool quick = false;
  run::Shard shard;
  std::size_t units = 0;  // units of the whole chart
  std::vector<UnitRow> rows;
  // The bounce rows of the shard's units (a shard renders the scene's none setting too, unscored
  // in the main chart, when it holds other bounce settings of that scene but not none).
  std::vector<UnitBounceRow> bounce_rows;
};

std::string shard_to_json(const ChartShard& shard);
Result<ChartShard> shard_from_json(std::string_view text, const std::string& where);

// The rows of all shards in unit order, with the context they share; `bounce_rows` (when not
// null) gets the bounce rows in unit order, as a single run lists them. Errors: shards of different
// charts (device, size, frames, spp, lighting, scenes, grid) or counts, a shard twice or missing,
// a unit outside its shard's slice.
Result<std::vector<study::ChartRow>> merge_shards(const std::vector<ChartShard>& shards, ChartReportContext& context,
                                                  std::vector<study::BounceRow>* bounce_rows = nullptr);

// Replaces each row's ms per frame by the one a bench-chart-timings.json (timings_json) gives for
// its scene and label; every row must be found. Used to check a merge against a single run.
Status replace_timings(std::vector<study::ChartRow>& rows, std::string_view timings_text, const std::string& where);
Status replace_timings(std::vector<study::BounceRow>& rows, std::string_view timings_text, const std::string& where);

}  // namespace proxygi::app
