#include "study/chart_rows.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>

namespace proxygi::study {

double RegionErrors::relative_mse(ChartRegion region) const {
  const auto r = std::size_t(region);
  return pixels[r] > 0.0 ? error_sum[r] / pixels[r] : std::numeric_limits<double>::quiet_NaN();
}

void RegionErrors::add(const RegionErrors& other, double weight) {
  if (!other.measured) return;
  measured = true;
  for (std::size_t r = 0; r < std::size_t(kChartRegionCount); ++r) {
    error_sum[r] += weight * other.error_sum[r];
    pixels[r] += weight * other.pixels[r];
  }
  negative += weight * other.negative;
  above_unshadowed += weight * other.above_unshadowed;
  non_finite += weight * other.non_finite;
}

namespace {

// Per region, the mean over the rows where it is not empty; the pixel count is the mean over all.
RegionErrors mean_regions(const std::vector<const ChartRow*>& group) {
  RegionErrors mean;
  const double count = double(group.size());
  for (const ChartRow* row : group) {
    if (!row->regions.measured) continue;
    mean.measured = true;
    mean.negative += row->regions.negative / count;
    mean.above_unshadowed += row->regions.above_unshadowed / count;
    mean.non_finite += row->regions.non_finite / count;
  }
  for (int r = 0; r < kChartRegionCount; ++r) {
    double ratio_sum = 0.0, pixels = 0.0;
    int present = 0;
    for (const ChartRow* row : group) {
      pixels += row->regions.pixels[std::size_t(r)] / count;
      const double value = row->regions.relative_mse(ChartRegion(r));
      if (!std::isnan(value)) ratio_sum += value, ++present;
    }
    if (present > 0 && pixels > 0.0) {
      mean.pixels[std::size_t(r)] = pixels;
      mean.error_sum[std::size_t(r)] = ratio_sum / double(present) * pixels;
    }
  }
  return mean;
}

bool any_regions(const std::vector<ChartRow>& rows) {
  return std::any_of(rows.begin(), rows.end(), [](const ChartRow& row) { return row.regions.measured; });
}

}  // namespace

std::string row_label(const ChartRow& row) {
  std::ostringstream text;
  text << row.method;
  if (row.method == "path" || row.method == "path+guided") {
    text << ' ' << row.samples << " spp";
    return text.str();
  }
  if (row.method == "quality") return text.str() + " " + row.quality;
  if (row.sh_order > 0) text << " n" << row.sh_order;
  if (row.receiver_scale > 0) text << " k" << row.receiver_scale;
  if (!row.upsampling.empty()) text << ' ' << row.upsampling;
  if (!row.indirect.empty()) text << ' ' << row.indirect;
  if (!row.ground_bounce) text << " no-ground-bounce";
  if (!row.antialiasing.empty()) text << ' ' << row.antialiasing;
  if (row.static_transfer != "l0") text << " static-" << row.static_transfer;
  if (!row.mask_sender_light) text << " paper-senders";
  return text.str();
}

void mark_pareto_fronts(std::vector<ChartRow>& rows) {
  for (ChartRow& row : rows) {
    row.pareto = true;
    for (const ChartRow& other : rows) {
      if (&other == &row || other.scene != row.scene) continue;
      const bool no_worse = other.milliseconds <= row.milliseconds && other.relative_mse <= row.relative_mse;
      const bool better = other.milliseconds < row.milliseconds || other.relative_mse < row.relative_mse;
      if (no_worse && better) {
        row.pareto = false;
        break;
      }
    }
  }
}

std::vector<ChartRow> mean_over_scenes(const std::vector<ChartRow>& rows) {
  std::set<std::string> scenes;
  for (const ChartRow& row : rows)
    if (row.scene != kAllScenes) scenes.insert(row.scene);
  std::map<std::string, std::vector<const ChartRow*>> by_setting;  // label -> rows over scenes
  std::vector<std::string> order;
  for (const ChartRow& row : rows) {
    if (row.scene == kAllScenes) continue;
    const std::string label = row_label(row);
    if (!by_setting.count(label)) order.push_back(label);
    by_setting[label].push_back(&row);
  }
  std::vector<ChartRow> means;
  for (const std::string& label : order) {
    const std::vector<const ChartRow*>& group = by_setting[label];
    std::set<std::string> covered;
    for (const ChartRow* row : group) covered.insert(row->scene);
    if (covered != scenes || group.size() != scenes.size()) continue;
    ChartRow mean = *group.front();
    mean.scene = kAllScenes;
    mean.frames.clear();  // frames belong to one scene
    mean.milliseconds = mean.relative_mse = mean.rmse = mean.ssim = mean.flip = 0.0;
    mean.character_relative_mse = mean.character_luminance_ratio = 0.0;
    for (const ChartRow* row : group) {
      mean.character_relative_mse += row->character_relative_mse;
      mean.character_luminance_ratio += row->character_luminance_ratio;
      mean.milliseconds += row->milliseconds;
      mean.relative_mse += row->relative_mse;
      mean.rmse += row->rmse;
      mean.ssim += row->ssim;
      mean.flip += row->flip;
    }
    const double count = double(group.size());
    mean.milliseconds /= count;
    mean.relative_mse /= count;
    mean.rmse /= count;
    mean.ssim /= count;
    mean.flip /= count;
    mean.character_relative_mse /= count;
    mean.character_luminance_ratio /= count;
    mean.regions = mean_regions(group);
    mean.pareto = false;
    means.push_back(mean);
  }
  return means;
}

namespace {

std::string format_note(const char* format, double a, double b, double c) {
  char text[256];
  std::snprintf(text, sizeof text, format, a, b, c);
  return text;
}

}  // namespace

GoalResult path_tracing_goal(const std::vector<ChartRow>& rows, const std::string& scene) {
  GoalResult goal;
  const ChartRow* proxy = nullptr;
  std::vector<const ChartRow*> guided;
  for (const ChartRow& row : rows) {
    if (row.scene != scene) continue;
    if (row.is_default && row.method == "proxy") proxy = &row;
    if (row.method == "path+guided") guided.push_back(&row);
  }
  if (proxy == nullptr || guided.empty() || proxy->milliseconds <= 0.0) return goal;
  goal.evaluated = true;
  const ChartRow* best = nullptr;
  for (const ChartRow* row : guided)
    if (row->relative_mse >= proxy->relative_mse && (best == nullptr || row->milliseconds > best->milliseconds))
      best = row;
  if (best != nullptr) {
    goal.ratio = best->milliseconds / proxy->milliseconds;
    goal.met = goal.ratio >= 50.0;
    goal.compared = row_label(*best);
    goal.note = format_note("default proxy setting: relative MSE %.4g at %.3g ms; matched error at %.3gx less time",
                            proxy->relative_mse, proxy->milliseconds, goal.ratio);
    return goal;
  }
  const ChartRow* cheapest = *std::min_element(guided.begin(), guided.end(), [](const ChartRow* a, const ChartRow* b) {
    return a->milliseconds < b->milliseconds;
  });
  goal.ratio = cheapest->milliseconds / proxy->milliseconds;
  goal.compared = row_label(*cheapest);
  goal.note = format_note("every guided path-tracing row beats the default proxy setting's relative MSE %.4g; "
                          "the cheapest (%.3g ms) is %.3gx slower",
                          proxy->relative_mse, cheapest->milliseconds, goal.ratio);
  return goal;
}

GoalResult vertex_goal(const std::vector<ChartRow>& rows, const std::string& scene, int sh_order) {
  GoalResult goal;
  const ChartRow* vertex = nullptr;
  for (const ChartRow& row : rows)
    if (row.scene == scene && row.method == "vertex" && row.sh_order == sh_order) vertex = &row;
  if (vertex == nullptr) return goal;
  const ChartRow* fastest = nullptr;
  for (const ChartRow& row : rows)
    if (row.scene == scene && row.method == "proxy" && row.sh_order == vertex->sh_order &&
        row.relative_mse <= vertex->relative_mse && (fastest == nullptr || row.milliseconds < fastest->milliseconds))
      fastest = &row;
  goal.evaluated = true;
  if (fastest == nullptr || fastest->milliseconds <= 0.0) {
    goal.note = format_note("no image-space row at order %.0f reaches the vertex baseline's relative MSE %.4g (%.3g ms)",
                            vertex->sh_order, vertex->relative_mse, vertex->milliseconds);
    return goal;
  }
  goal.ratio = vertex->milliseconds / fastest->milliseconds;
  goal.met = goal.ratio >= 2.0;
  goal.compared = row_label(*fastest);
  goal.note = format_note("vertex baseline %.3g ms at relative MSE %.4g; the fastest image-space row at equal or "
                          "lower error is %.3gx faster",
                          vertex->milliseconds, vertex->relative_mse, goal.ratio);
  return goal;
}

std::string to_csv(const std::vector<ChartRow>& rows) {
  const bool regions = any_regions(rows);
  std::ostringstream csv;
  csv << "scene,method,label,sh_order,receiver_scale,upsampling,indirect,samples,ms_per_frame,relative_mse,rmse,ssim,"
         "flip,character_relative_mse,character_luminance_ratio,pareto,default";
  if (regions) {
    for (const char* name : kChartRegionNames) csv << ',' << name << "_relative_mse," << name << "_pixels";
    csv << ",negative_pixels,above_unshadowed_pixels,non_finite_pixels";
  }
  csv << '\n';
  csv.precision(6);
  for (const ChartRow& row : rows) {
    csv << row.scene << ',' << row.method << ',' << row_label(row) << ',' << row.sh_order << ',' << row.receiver_scale
        << ',' << row.upsampling << ',' << row.indirect << ',' << row.samples << ',' << row.milliseconds << ','
        << row.relative_mse << ',' << row.rmse << ',' << row.ssim << ',' << row.flip << ',' << row.character_relative_mse
        << ',' << row.character_luminance_ratio << ',' << int(row.pareto) << ','
        << int(row.is_default);
    if (regions) {
      for (int r = 0; r < kChartRegionCount; ++r) {
        const double value = row.regions.relative_mse(ChartRegion(r));
        csv << ',';
        if (!std::isnan(value)) csv << value;  // empty: no pixel in the region
        csv << ',' << row.regions.pixels[std::size_t(r)];
      }
      csv << ',' << row.regions.negative << ',' << row.regions.above_unshadowed << ',' << row.regions.non_finite;
    }
    csv << '\n';
  }
  return csv.str();
}

std::string to_markdown(const std::vector<ChartRow>& rows, const std::string& scene) {
  std::vector<const ChartRow*> selected;
  for (const ChartRow& row : rows)
    if (row.scene == scene) selected.push_back(&row);
  std::stable_sort(selected.begin(), selected.end(), [](const ChartRow* a, const ChartRow* b) {
    if (a->pareto != b->pareto) return a->pareto;
    return a->milliseconds < b->milliseconds;
  });
  std::ostringstream text;
  text << "| method | ms/frame | relative MSE | RMSE | SSIM | HDR-FLIP | character relMSE | character brightness | Pareto |\n";
  text << "|---|---:|---:|---:|---:|---:|---:|---:|:---:|\n";
  char line[320];
  for (const ChartRow* row : selected) {
    std::string label = row_label(*row);
    if (row->is_default) label += " (default)";
    std::snprintf(line, sizeof line, "| %s | %.2f | %.4g | %.4g | %.4f | %.4f | %.4g | %.3f | %s |\n", label.c_str(),
                  row->milliseconds, row->relative_mse, row->rmse, row->ssim, row->flip, row->character_relative_mse,
                  row->character_luminance_ratio, row->pareto ? "yes" : "");
    text << line;
  }
  return text.str();
}

std::string to_region_markdown(const std::vector<ChartRow>& rows, const std::string& scene) {
  std::vector<const ChartRow*> selected;
  for (const ChartRow& row : rows)
    if (row.scene == scene && row.regions.measured) selected.push_back(&row);
  std::stable_sort(selected.begin(), selected.end(), [](const ChartRow* a, const ChartRow* b) {
    if (a->pareto != b->pareto) return a->pareto;
    return a->milliseconds < b->milliseconds;
  });
  std::ostringstream text;
  text << "| method | all";
  for (const char* name : kChartRegionNames) text << " | " << name;
  text << " | negative px | above unshadowed px | NaN/Inf px |\n|---|---:";
  for (int r = 0; r < kChartRegionCount + 3; ++r) text << "|---:";
  text << "|\n";
  char cell[64];
  for (const ChartRow* row : selected) {
    std::string label = row_label(*row);
    if (row->is_default) label += " (default)";
    text << "| " << label;
    std::snprintf(cell, sizeof cell, " | %.4g", row->relative_mse);
    text << cell;
    for (int r = 0; r < kChartRegionCount; ++r) {
      const double value = row->regions.relative_mse(ChartRegion(r));
      if (std::isnan(value))
        text << " | n/a";
      else
        std::snprintf(cell, sizeof cell, " | %.4g", value), text << cell;
    }
    std::snprintf(cell, sizeof cell, " | %.4g | %.4g | %.4g |\n", row->regions.negative, row->regions.above_unshadowed,
                  row->regions.non_finite);
    text << cell;
  }
  return text.str();
}

std::string to_json(const std::vector<ChartRow>& rows) {
  nlohmann::json out = nlohmann::json::array();
  for (const ChartRow& row : rows) {
    nlohmann::json regions = nullptr;
    if (row.regions.measured) {
      regions = nlohmann::json::object();
      for (int r = 0; r < kChartRegionCount; ++r) {
        const double value = row.regions.relative_mse(ChartRegion(r));
        regions[kChartRegionNames[std::size_t(r)]] = {
            {"relative_mse", std::isnan(value) ? nlohmann::json(nullptr) : nlohmann::json(value)},
            {"pixels", row.regions.pixels[std::size_t(r)]}};
      }
      regions["bounds"] = {{"negative_pixels", row.regions.negative},
                           {"above_unshadowed_pixels", row.regions.above_unshadowed},
                           {"non_finite_pixels", row.regions.non_finite}};
    }
    out.push_back({{"scene", row.scene},
                   {"method", row.method},
                   {"label", row_label(row)},
                   {"sh_order", row.sh_order},
                   {"receiver_scale", row.receiver_scale},
                   {"upsampling", row.upsampling},
                   {"indirect", row.indirect},
                   {"samples", row.samples},
                   {"ms_per_frame", row.milliseconds},
                   {"relative_mse", row.relative_mse},
                   {"rmse", row.rmse},
                   {"ssim", row.ssim},
                   {"flip", row.flip},
                   {"character_relative_mse", row.character_relative_mse},
                   {"character_luminance_ratio", row.character_luminance_ratio},
                   {"ground_bounce", row.ground_bounce},
                   {"antialiasing", row.antialiasing.empty() ? std::string("off") : row.antialiasing},
                   {"static_transfer", row.static_transfer},
                   {"mask_sender_light", row.mask_sender_light},
                   {"pareto", row.pareto},
                   {"default", row.is_default}});
    if (row.regions.measured) out.back()["regions"] = regions;
    if (row.method == "quality") {
      out.back()["quality"] = row.quality;
      out.back()["quality_target"] = row.quality_target;
    }
    if (!row.frames.empty()) {
      nlohmann::json frames = nlohmann::json::array();
      for (const ChartFrame& frame : row.frames) {
        frames.push_back({{"relative_mse", frame.relative_mse}});
        if (row.method == "quality")
          frames.back().update({{"ms_per_frame", frame.milliseconds},
                                {"sh_order", frame.sh_order},
                                {"receiver_scale", frame.receiver_scale},
                                {"upsampling", frame.upsampling}});
      }
      out.back()["frames"] = frames;
    }
  }
  return out.dump(2);
}

}  // namespace proxygi::study
