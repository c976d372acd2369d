#pragma once
// The check kinds (internal to the runner): each fills a CheckResult for one check of a
// scenario being run, reading goldens from the store or writing them when blessing.
#include <optional>
#include <string>

#include "base/result.h"
#include "regress/golden_store.h"
#include "regress/results.h"
#include "regress/runner.h"
#include "regress/scenario_run.h"

namespace proxygi::regress {

struct CheckContext {
  gpu::Context& context;
  ScenarioRun& run;
  const Check& check;
  const GoldenStore& store;
  bool bless = false;
  const RunOptions& options;
  CheckResult& result;
};

Status run_image_check(CheckContext& c);
Status run_tracks_check(CheckContext& c);
Status run_temporal_check(CheckContext& c);
Status run_differential_check(CheckContext& c);
Status run_budget_check(CheckContext& c);

// Writes the images (linear; PNGs clamp to [0, 1]) of one frame for the report (report_dir/<scenario>/<check>/frame_N_*.png)
// and keeps them as data URIs; no-op without a report folder.
Status attach_images(CheckContext& c, int frame, const image::ImageF* golden, const image::ImageF& actual,
                     const image::ImageF* diff, const image::ImageF* flip);

// Reads a text golden (tracks.json, temporal.json), or nothing when absent.
Result<std::optional<std::string>> read_text(const std::filesystem::path& path);

}  // namespace proxygi::regress
