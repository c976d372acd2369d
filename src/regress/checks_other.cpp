// Tracks, temporal, differential and budget checks.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include <nlohmann/json.hpp>

#include "base/atomic_file.h"
#include "regress/checks.h"
#include "regress/image_compare.h"
#include "regress/tracks.h"
#include "run/frame_loop.h"

namespace proxygi::regress {
namespace {

Status write_golden_text(const std::filesystem::path& path, const std::string& text) {
  std::error_code error;
  std::filesystem::create_directories(path.parent_path(), error);
  if (error) return make_error(path.parent_path().string() + ": " + error.message());
  return write_file_atomically(path, std::string_view(text));
}

std::string fixed(double value, int digits = 3) {
  char text[64];
  std::snprintf(text, sizeof(text), "%.*f", digits, value);
  return text;
}

// Mean |change| (codes, RGB) between two frames over the later frame's region.
double mean_change(const RenderedFrame& a, const RenderedFrame& b, Region region) {
  const std::vector<std::uint8_t> mask = region_mask(b.classes, region);
  double sum = 0.0;
  std::size_t count = 0;
  for (std::size_t i = 0; i < mask.size(); ++i) {
    if (!mask[i]) continue;
    for (std::size_t ch = 0; ch < 3; ++ch) sum += std::abs(int(a.final_frame.pixels[i * 4 + ch]) - int(b.final_frame.pixels[i * 4 + ch]));
    ++count;
  }
  return count ? sum / double(count * 3) : 0.0;
}

// Blessing writes `text` as the golden `file`; without a golden the check is "new". True when
// either happened (the check is done), else the caller compares against the golden's tier.
Result<bool> bless_or_new(CheckContext& c, bool has_golden, const char* file, const std::string& text,
                          const std::string& blessed, const std::string& missing) {
  if (c.bless) {
    if (Status s = write_golden_text(c.store.bless_path(c.result.scenario, c.check.name, file), text); !s) return s.error();
    c.result.outcome = Outcome::blessed;
    c.result.message = blessed;
    return true;
  }
  if (!has_golden) {
    c.result.outcome = Outcome::new_golden;
    c.result.message = missing + " (device family " + c.store.family + ")";
    return true;
  }
  return false;
}

}  // namespace

Status run_tracks_check(CheckContext& c) {
  auto tracks = compute_tracks(c.run, c.check);
  if (!tracks) return tracks.error();
  const auto tier = c.store.find_tier(c.result.scenario, c.check.name, "tracks.json");
  std::optional<Tracks> golden;
  if (tier) {
    auto text = read_text(c.store.dir(c.result.scenario, *tier, c.check.name) / "tracks.json");
    if (!text) return text.error();
    auto parsed = tracks_from_json(**text, c.result.scenario + "/" + c.check.name);
    if (!parsed) return parsed.error();
    golden = std::move(*parsed);
  }
  if (c.bless && golden) {
    CheckResult before = c.result;
    compare_tracks(*tracks, *golden, c.check, 1.0, before);
    c.result.details.push_back("was: " + before.message);
  }
  auto done = bless_or_new(c, golden.has_value(), "tracks.json", tracks_to_json(*tracks),
                           "blessed tracks of " + std::to_string(tracks->size()) + " frames into the " + c.store.family + " tier",
                           "no tracks golden");
  if (!done) return done.error();
  if (*done) return {};
  c.result.tier = *tier;
  compare_tracks(*tracks, *golden, c.check, *tier == std::string(kFallbackTier) ? c.check.fallback_scale : 1.0, c.result);
  return {};
}

Status run_temporal_check(CheckContext& c) {
  std::vector<double> change;
  for (std::size_t i = 0; i + 1 < c.check.frames.size(); ++i) {
    auto a = c.run.frame(c.check.frames[i]);
    if (!a) return a.error();
    const RenderedFrame first = **a;  // copy: the cache may grow
    auto b = c.run.frame(c.check.frames[i + 1]);
    if (!b) return b.error();
    change.push_back(mean_change(first, **b, c.check.region));
  }
  nlohmann::json document = {{"frames", c.check.frames}, {"change", change}};
  const auto tier = c.store.find_tier(c.result.scenario, c.check.name, "temporal.json");
  std::optional<std::vector<double>> golden;
  if (tier) {
    auto text = read_text(c.store.dir(c.result.scenario, *tier, c.check.name) / "temporal.json");
    if (!text) return text.error();
    try {
      const auto parsed = nlohmann::json::parse(**text);
      if (parsed.at("frames").get<std::vector<int>>() == c.check.frames) golden = parsed.at("change").get<std::vector<double>>();
    } catch (const nlohmann::json::exception& e) {
      return make_error(c.result.scenario + "/" + c.check.name + ": temporal.json: " + e.what());
    }
  }
  auto done = bless_or_new(c, golden.has_value(), "temporal.json", document.dump() + "\n",
                           "blessed the frame-to-frame change of " + std::to_string(change.size()) + " frame pairs",
                           "no temporal golden for these frames");
  if (!done) return done.error();
  if (*done) return {};
  c.result.tier = *tier;
  const double tolerance = c.check.temporal_tolerance * (*tier == std::string(kFallbackTier) ? c.check.fallback_scale : 1.0);
  c.result.metric = "|change - golden change| (codes)";
  c.result.threshold = tolerance;
  double worst = 0.0;
  for (std::size_t i = 0; i < change.size(); ++i) {
    const double d = std::abs(change[i] - (*golden)[i]);
    const bool failed = d > tolerance;
    worst = std::max(worst, d);
    c.result.series.push_back({c.check.frames[i + 1], d, failed});
    if (failed) {
      c.result.details.push_back("frames " + std::to_string(c.check.frames[i]) + "->" + std::to_string(c.check.frames[i + 1]) +
                                 ": mean change " + fixed(change[i]) + " codes, golden " + fixed((*golden)[i]));
      if (c.result.first_failing_frame < 0) c.result.first_failing_frame = c.check.frames[i + 1];
    }
  }
  c.result.outcome = c.result.first_failing_frame >= 0 ? Outcome::fail : Outcome::pass;
  c.result.message = c.result.first_failing_frame >= 0 ? c.result.details.front()
                                                        : "frame-to-frame change within " + fixed(tolerance) + " codes of the golden's (worst " + fixed(worst) + ")";
  return {};
}

Status run_differential_check(CheckContext& c) {
  const Check& check = c.check;
  std::vector<RenderedFrame> a, b;
  if (check.kind == DifferentialKind::settings) {
    if (Status s = c.run.apply_overrides(check.a); !s) return s;
    for (int f : check.frames) {
      auto r = c.run.render(f, false);
      if (!r) return r.error();
      a.push_back(std::move(*r));
    }
    if (Status s = c.run.apply_overrides(check.b); !s) return s;
    for (int f : check.frames) {
      auto r = c.run.render(f, false);
      if (!r) return r.error();
      b.push_back(std::move(*r));
    }
    if (Status s = c.run.apply_overrides({}); !s) return s;
  } else if (check.kind == DifferentialKind::repeat) {
    for (int f : check.frames) {
      auto first = c.run.render(f, false);
      if (!first) return first.error();
      auto between = c.run.render(check.frames.front() == f ? check.frames.back() : check.frames.front(), false);
      if (!between) return between.error();
      auto second = c.run.render(f, false);
      if (!second) return second.error();
      a.push_back(std::move(*first));
      b.push_back(std::move(*second));
    }
  } else {  // shard: a fresh renderer takes the frames as two shards would (odd positions, then even)
    auto other = ScenarioRun::create(c.context, c.run.scenario(), c.options.assets_dir, c.run.fault());
    if (!other) return other.error();
    std::vector<std::size_t> order;
    for (std::size_t i = 1; i < check.frames.size(); i += 2) order.push_back(i);
    for (std::size_t i = 0; i < check.frames.size(); i += 2) order.push_back(i);
    b.resize(check.frames.size());
    for (std::size_t i : order) {
      auto r = (*other)->render(check.frames[i], false);
      if (!r) return r.error();
      b[i] = std::move(*r);
    }
    for (int f : check.frames) {
      auto r = c.run.frame(f);
      if (!r) return r.error();
      a.push_back(**r);
    }
  }
  c.result.metric = "failing fraction";
  c.result.threshold = check.image.max_failing_fraction;
  std::string worst_summary;
  double worst = -1.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const auto mask = region_mask(a[i].classes, check.region);
    auto comparison = compare_images(b[i].final_frame, a[i].final_frame, mask, check.image);
    if (!comparison) return comparison.error();
    c.result.series.push_back({a[i].frame, comparison->failing_fraction, !comparison->passed});
    if (!comparison->passed) {
      c.result.details.push_back("frame " + std::to_string(a[i].frame) + ": " + comparison->summary);
      if (c.result.first_failing_frame < 0) {
        c.result.first_failing_frame = a[i].frame;
        const image::ImageF first = to_linear(a[i].final_frame), second = to_linear(b[i].final_frame);
        if (Status s = attach_images(c, a[i].frame, &first, second, &comparison->diff, nullptr); !s) return s;
      }
    }
    if (comparison->failing_fraction > worst) worst = comparison->failing_fraction, worst_summary = comparison->summary;
  }
  c.result.outcome = c.result.first_failing_frame >= 0 ? Outcome::fail : Outcome::pass;
  c.result.message = c.result.first_failing_frame >= 0 ? c.result.details.front() : "the two sides agree (worst: " + worst_summary + ")";
  return {};
}

Status run_budget_check(CheckContext& c) {
  const std::string device = c.context.report().name;
  std::string lower = device;
  std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char ch) { return char(std::tolower(ch)); });
  // The device family's budget, else a pattern found in the device name, else "*".
  std::optional<std::pair<std::string, double>> budget;
  for (int pass = 0; pass < 3 && !budget; ++pass)
    for (const auto& [pattern, ms] : c.check.budgets) {
      std::string p = pattern;
      std::transform(p.begin(), p.end(), p.begin(), [](unsigned char ch) { return char(std::tolower(ch)); });
      const bool hit = pass == 0 ? p == c.store.family : pass == 1 ? (p != "*" && lower.find(p) != std::string::npos) : p == "*";
      if (hit) {
        budget = std::make_pair(pattern, ms);
        break;
      }
    }
  if (!budget) {
    c.result.outcome = Outcome::skipped;
    c.result.message = "no budget for this device (" + c.store.family + ")";
    return {};
  }
  std::vector<double> runs;
  for (int i = 0; i < c.check.runs; ++i) {
    auto ms = run::time_pipelined_frames(c.run.renderer(), c.check.frames.front(), c.check.timed_frames);
    if (!ms) return ms.error();
    runs.push_back(*ms);
  }
  // The times go to timings.json only: the message and outcome name the budget, not the time,
  // so results.json stays byte-identical between runs that pass (or fail) alike.
  const double median = median_ms(runs);
  c.result.timings_ms = runs;
  c.result.metric = "ms per frame (median of runs, in timings.json)";
  c.result.threshold = budget->second;
  c.result.tier = budget->first;
  const bool failed = median > budget->second;
  c.result.first_failing_frame = failed ? c.check.frames.front() : -1;
  c.result.outcome = failed ? Outcome::fail : Outcome::pass;
  c.result.message = std::string(failed ? "median over" : "median within") + " the " + fixed(budget->second, 1) +
                     " ms per frame budget for \"" + budget->first + "\" (" + std::to_string(runs.size()) + " runs of " +
                     std::to_string(c.check.timed_frames) + " frames; times in timings.json)";
  return {};
}

}  // namespace proxygi::regress
