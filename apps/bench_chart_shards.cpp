#include "apps/bench_chart_shards.h"

#include <array>
#include <algorithm>
#include <map>
#include <tuple>

#include <nlohmann/json.hpp>

namespace proxygi::app {
namespace {

using nlohmann::json;

// A new ChartRow member stops the build here until row_json and row_from_json carry it (a member
// left out was dropped from merged charts without a word). `pareto` is recomputed by the merge.
[[maybe_unused]] void every_row_member_is_carried(const study::ChartRow& row) {
  const auto& [scene, method, sh_order, receiver_scale, upsampling, indirect, samples, milliseconds, relative_mse, rmse,
               ssim, flip, character_relative_mse, character_luminance_ratio, regions, ground_bounce, antialiasing,
               static_transfer, mask_sender_light, quality, quality_target, frames, pareto, is_default] = row;
  (void)scene, (void)method, (void)sh_order, (void)receiver_scale, (void)upsampling, (void)indirect, (void)samples;
  (void)milliseconds, (void)relative_mse, (void)rmse, (void)ssim, (void)flip, (void)character_relative_mse;
  (void)character_luminance_ratio, (void)regions, (void)ground_bounce, (void)antialiasing, (void)static_transfer;
  (void)mask_sender_light, (void)quality, (void)quality_target, (void)frames, (void)pareto, (void)is_default;
}

// Region sums exactly as measured (the merge's means and ratios then equal a single run's).
json regions_json(const study::RegionErrors& regions) {
  return {{"error_sum", regions.error_sum}, {"pixels", regions.pixels}, {"negative", regions.negative},
          {"above_unshadowed", regions.above_unshadowed}, {"non_finite", regions.non_finite}};
}

study::RegionErrors regions_from_json(const json& j) {
  study::RegionErrors regions;
  regions.measured = true;
  regions.error_sum = j.at("error_sum").get<std::array<double, study::kChartRegionCount>>();
  regions.pixels = j.at("pixels").get<std::array<double, study::kChartRegionCount>>();
  regions.negative = j.at("negative").get<double>();
  regions.above_unshadowed = j.at("above_unshadowed").get<double>();
  regions.non_finite = j.at("non_finite").get<double>();
  return regions;
}

// Every field of a row: the shard file must carry it back exactly (doubles round-trip in JSON).
json row_json(const study::ChartRow& row) {
  json out = {{"scene", row.scene},        {"method", row.method},   {"sh_order", row.sh_order},
          {"receiver_scale", row.receiver_scale}, {"upsampling", row.upsampling}, {"indirect", row.indirect},
          {"samples", row.samples},    {"ms_per_frame", row.milliseconds}, {"relative_mse", row.relative_mse},
          {"rmse", row.rmse},          {"ssim", row.ssim},       {"flip", row.flip},
          {"character_relative_mse", row.character_relative_mse},
          {"character_luminance_ratio", row.character_luminance_ratio},
          {"ground_bounce", row.ground_bounce}, {"static_transfer", row.static_transfer},
          {"mask_sender_light", row.mask_sender_light}, {"default", row.is_default}};
  if (!row.antialiasing.empty()) out["antialiasing"] = row.antialiasing;
  if (row.regions.measured) out["regions"] = regions_json(row.regions);
  if (row.method == "quality") out["quality"] = {{"name", row.quality}, {"target", row.quality_target}};
  if (!row.frames.empty()) {
    out["frames"] = json::array();
    for (const study::ChartFrame& frame : row.frames)
      out["frames"].push_back({{"relative_mse", frame.relative_mse}, {"ms_per_frame", frame.milliseconds},
                               {"sh_order", frame.sh_order}, {"receiver_scale", frame.receiver_scale},
                               {"upsampling", frame.upsampling}});
  }
  return out;
}

study::ChartRow row_from_json(const json& j) {
  study::ChartRow row;
  row.scene = j.at("scene").get<std::string>();
  row.method = j.at("method").get<std::string>();
  row.sh_order = j.at("sh_order").get<int>();
  row.receiver_scale = j.at("receiver_scale").get<int>();
  row.upsampling = j.at("upsampling").get<std::string>();
  row.indirect = j.at("indirect").get<std::string>();
  row.samples = j.at("samples").get<int>();
  row.milliseconds = j.at("ms_per_frame").get<double>();
  row.relative_mse = j.at("relative_mse").get<double>();
  row.rmse = j.at("rmse").get<double>();
  row.ssim = j.at("ssim").get<double>();
  row.flip = j.at("flip").get<double>();
  row.character_relative_mse = j.at("character_relative_mse").get<double>();
  row.character_luminance_ratio = j.at("character_luminance_ratio").get<double>();
  row.ground_bounce = j.at("ground_bounce").get<bool>();
  row.static_transfer = j.at("static_transfer").get<std::string>();
  row.mask_sender_light = j.at("mask_sender_light").get<bool>();
  row.is_default = j.at("default").get<bool>();
  if (j.contains("antialiasing")) row.antialiasing = j.at("antialiasing").get<std::string>();
  if (j.contains("regions")) row.regions = regions_from_json(j.at("regions"));
  if (j.contains("quality")) {
    row.quality = j.at("quality").at("name").get<std::string>();
    row.quality_target = j.at("quality").at("target").get<double>();
  }
  if (j.contains("frames"))
    for (const json& frame : j.at("frames"))
      row.frames.push_back({frame.at("relative_mse").get<double>(), frame.at("ms_per_frame").get<double>(),
                            frame.at("sh_order").get<int>(), frame.at("receiver_scale").get<int>(),
                            frame.at("upsampling").get<std::string>()});
  return row;
}

// Every region of a bounce row's scores, as row_json: exactly (BounceError has three members).
json error_json(const study::BounceError& e) {
  return {{"relative_mse", e.relative_mse}, {"luminance_ratio", e.luminance_ratio}, {"pixels", e.pixels}};
}

study::BounceError error_from_json(const json& j) {
  return {j.at("relative_mse").get<double>(), j.at("luminance_ratio").get<double>(), j.at("pixels").get<std::size_t>()};
}

[[maybe_unused]] void every_bounce_member_is_carried(const study::BounceScores& scores, const study::BounceError& error) {
  const auto& [significant, character, contact, ground, other] = scores;
  const auto& [relative_mse, luminance_ratio, pixels] = error;
  (void)significant, (void)character, (void)contact, (void)ground, (void)other;
  (void)relative_mse, (void)luminance_ratio, (void)pixels;
}

json bounce_json(const study::BounceScores& b) {
  return {{"significant", error_json(b.significant)}, {"character", error_json(b.character)},
          {"contact", error_json(b.contact)},         {"ground", error_json(b.ground)},
          {"other", error_json(b.other)}};
}

study::BounceScores bounce_from_json(const json& j) {
  return {error_from_json(j.at("significant")), error_from_json(j.at("character")), error_from_json(j.at("contact")),
          error_from_json(j.at("ground")), error_from_json(j.at("other"))};
}

std::string shard_name(const run::Shard& shard) { return std::to_string(shard.index) + "/" + std::to_string(shard.count); }

}  // namespace

std::string shard_to_json(const ChartShard& shard) {
  json out;
  out["context"] = chart_context_json(shard.context);
  out["quick"] = shard.quick;
  out["shard"] = {shard.shard.index, shard.shard.count};
  out["units"] = shard.units;
  out["rows"] = json::array();
  for (const UnitRow& r : shard.rows) {
    json row = row_json(r.row);
    row["unit"] = r.unit;
    out["rows"].push_back(row);
  }
  out["bounce_rows"] = json::array();
  for (const UnitBounceRow& r : shard.bounce_rows) {
    json row = row_json(r.row.row);
    row["unit"] = r.unit;
    row["bounce"] = bounce_json(r.row.bounce);
    out["bounce_rows"].push_back(row);
  }
  return out.dump(1) + "\n";
}

Result<ChartShard> shard_from_json(std::string_view text, const std::string& where) {
  try {
    const json j = json::parse(text.begin(), text.end());
    ChartShard shard;
    auto context = chart_context_from_json(j.at("context"));
    if (!context) return make_error(where + ": " + context.message());
    shard.context = std::move(*context);
    shard.quick = j.at("quick").get<bool>();
    shard.shard = {j.at("shard").at(0).get<int>(), j.at("shard").at(1).get<int>()};
    if (shard.shard.count < 1 || shard.shard.index < 0 || shard.shard.index >= shard.shard.count)
      return make_error(where + ": shard " + shard_name(shard.shard) + " is invalid");
    shard.units = j.at("units").get<std::size_t>();
    for (const json& row : j.at("rows")) shard.rows.push_back({row.at("unit").get<std::size_t>(), row_from_json(row)});
    if (j.contains("bounce_rows"))  // shard files from before the bounce chart was sharded have none
      for (const json& row : j.at("bounce_rows"))
        shard.bounce_rows.push_back(
            {row.at("unit").get<std::size_t>(), study::BounceRow{row_from_json(row), bounce_from_json(row.at("bounce"))}});
    return shard;
  } catch (const json::exception& e) {
    return make_error(where + ": not a " + std::string(kChartShardFile) + ": " + e.what());
  }
}

Result<std::vector<study::ChartRow>> merge_shards(const std::vector<ChartShard>& shards, ChartReportContext& context,
                                                  std::vector<study::BounceRow>* bounce_rows) {
  if (shards.empty()) return make_error("merge: no shards");
  const ChartShard& first = shards.front();
  const json first_context = chart_context_json(first.context);
  std::vector<bool> seen(std::size_t(first.shard.count), false);
  std::vector<UnitRow> all;
  std::vector<UnitBounceRow> all_bounce;
  for (const ChartShard& shard : shards) {
    const std::string name = "shard " + shard_name(shard.shard);
    if (chart_context_json(shard.context) != first_context || shard.quick != first.quick || shard.units != first.units)
      return make_error("merge: " + name + " measured another chart than shard " + shard_name(first.shard) +
                        " (device, size, frames, samples, lighting, scenes or grid differ)");
    if (shard.shard.count != first.shard.count)
      return make_error("merge: " + name + " is of " + std::to_string(shard.shard.count) + " shards, shard " +
                        shard_name(first.shard) + " of " + std::to_string(first.shard.count));
    if (seen[std::size_t(shard.shard.index)]) return make_error("merge: " + name + " given twice");
    seen[std::size_t(shard.shard.index)] = true;
    const run::IndexRange slice = run::shard_slice(shard.units, shard.shard);
    for (const UnitRow& row : shard.rows) {
      if (!slice.contains(row.unit))
        return make_error("merge: " + name + ": unit " + std::to_string(row.unit) + " is outside its slice [" +
                          std::to_string(slice.begin) + ", " + std::to_string(slice.end) + ")");
      all.push_back(row);
    }
    for (const UnitBounceRow& row : shard.bounce_rows) {
      if (!slice.contains(row.unit))
        return make_error("merge: " + name + ": bounce row of unit " + std::to_string(row.unit) + " is outside its slice [" +
                          std::to_string(slice.begin) + ", " + std::to_string(slice.end) + ")");
      all_bounce.push_back(row);
    }
  }
  for (std::size_t i = 0; i < seen.size(); ++i)
    if (!seen[i]) return make_error("merge: shard " + std::to_string(i) + "/" + std::to_string(seen.size()) + " is missing");
  // Slices tile the units in order, so ordering the shards' rows by unit (stable within a unit)
  // reproduces a single run's row order.
  std::stable_sort(all.begin(), all.end(), [](const UnitRow& a, const UnitRow& b) { return a.unit < b.unit; });
  context = first.context;
  std::vector<study::ChartRow> rows;
  for (UnitRow& r : all) rows.push_back(std::move(r.row));
  if (bounce_rows) {
    std::stable_sort(all_bounce.begin(), all_bounce.end(),
                     [](const UnitBounceRow& a, const UnitBounceRow& b) { return a.unit < b.unit; });
    bounce_rows->clear();
    for (UnitBounceRow& r : all_bounce) bounce_rows->push_back(std::move(r.row));
  }
  return rows;
}

Status replace_timings(std::vector<study::ChartRow>& rows, std::string_view timings_text, const std::string& where) {
  std::map<std::pair<std::string, std::string>, std::pair<double, std::vector<double>>> measured;
  try {
    const json j = json::parse(timings_text.begin(), timings_text.end());
    for (const json& row : j.at("rows"))
      measured[{row.at("scene").get<std::string>(), row.at("label").get<std::string>()}] = {
          row.at("ms_per_frame").get<double>(), row.value("frame_ms", std::vector<double>{})};
  } catch (const json::exception& e) {
    return make_error(where + ": not a bench-chart-timings.json: " + e.what());
  }
  for (study::ChartRow& row : rows) {
    const auto found = measured.find({row.scene, study::row_label(row)});
    if (found == measured.end()) return make_error(where + ": no time for " + row.scene + " / " + study::row_label(row));
    row.milliseconds = found->second.first;
    // Quality rows' frames are timed one by one (chart_timings_json writes them as frame_ms).
    if (row.method != "quality") continue;
    const std::vector<double>& frame_ms = found->second.second;
    if (frame_ms.size() != row.frames.size())
      return make_error(where + ": " + row.scene + " / " + study::row_label(row) + ": " + std::to_string(frame_ms.size()) +
                        " frame times for " + std::to_string(row.frames.size()) + " frames");
    for (std::size_t i = 0; i < frame_ms.size(); ++i) row.frames[i].milliseconds = frame_ms[i];
  }
  return {};
}

Status replace_timings(std::vector<study::BounceRow>& rows, std::string_view timings_text, const std::string& where) {
  std::vector<study::ChartRow> chart_rows;
  for (const study::BounceRow& row : rows) chart_rows.push_back(row.row);
  if (Status s = replace_timings(chart_rows, timings_text, where); !s) return s;
  for (std::size_t i = 0; i < rows.size(); ++i) rows[i].row.milliseconds = chart_rows[i].milliseconds;
  return {};
}

}  // namespace proxygi::app
