#include "study/bounce_rows.h"

#include <algorithm>
#include <cstdio>
#include <sstream>

namespace proxygi::study {
namespace {

std::vector<std::string> scene_order(const std::vector<BounceRow>& rows) {
  std::vector<std::string> scenes;
  for (const BounceRow& row : rows)
    if (std::find(scenes.begin(), scenes.end(), row.row.scene) == scenes.end()) scenes.push_back(row.row.scene);
  return scenes;
}

std::string cell(double value, const char* format) {
  if (value < 0.0) return "–";
  char text[32];
  std::snprintf(text, sizeof text, format, value);
  return text;
}

// The bounce method's name: the indirect column, and "paper-senders" for the paper's sender light.
std::string bounce_label(const ChartRow& row) { return row.mask_sender_light ? row.indirect : row.indirect + " paper-senders"; }

}  // namespace

std::vector<BounceRow> mean_bounce_over_scenes(const std::vector<BounceRow>& rows) {
  std::vector<ChartRow> chart_rows;
  for (const BounceRow& row : rows)
    if (row.row.scene != kAllScenes) chart_rows.push_back(row.row);
  std::vector<BounceRow> means;
  for (const ChartRow& mean : mean_over_scenes(chart_rows)) {
    std::vector<BounceScores> scenes;
    for (const BounceRow& row : rows)
      if (row.row.scene != kAllScenes && row_label(row.row) == row_label(mean)) scenes.push_back(row.bounce);
    means.push_back({mean, mean_bounce_scores(scenes)});
  }
  return means;
}

std::string to_bounce_csv(const std::vector<BounceRow>& rows) {
  std::ostringstream text;
  text << "scene,indirect,ms_per_frame,relative_mse,character_relative_mse";
  for (const char* region : {"significant", "character", "contact", "ground", "other"})
    text << ",bounce_" << region << "_relative_mse,bounce_" << region << "_luminance_ratio,bounce_" << region << "_pixels";
  text << "\n";
  char line[96];
  for (const BounceRow& r : rows) {
    std::snprintf(line, sizeof line, "%.4f,%.6g,%.6g", r.row.milliseconds, r.row.relative_mse, r.row.character_relative_mse);
    text << r.row.scene << ',' << bounce_label(r.row) << ',' << line;
    for (const BounceError* e :
         {&r.bounce.significant, &r.bounce.character, &r.bounce.contact, &r.bounce.ground, &r.bounce.other}) {
      std::snprintf(line, sizeof line, ",%.6g,%.6g,%zu", e->relative_mse, e->luminance_ratio, e->pixels);
      text << line;
    }
    text << "\n";
  }
  return text.str();
}

std::string to_bounce_markdown(const std::vector<BounceRow>& rows) {
  std::ostringstream text;
  for (const std::string& scene : scene_order(rows)) {
    std::vector<const BounceRow*> selected;
    for (const BounceRow& row : rows)
      if (row.row.scene == scene) selected.push_back(&row);
    std::stable_sort(selected.begin(), selected.end(), [](const BounceRow* a, const BounceRow* b) {
      const double x = a->bounce.significant.relative_mse, y = b->bounce.significant.relative_mse;
      if ((x < 0.0) != (y < 0.0)) return y < 0.0;
      return x < y;
    });
    const std::size_t pixels = selected.empty() ? 0 : selected.front()->bounce.significant.pixels;
    if (scene == kAllScenes)
      text << "\n### Mean over scenes (`" << kAllScenes << "`: each score the mean of the scenes where its region is not empty)\n\n";
    else
      text << "\n### " << scene << " (" << pixels << " pixels with a significant bounce)\n\n";
    text << "| indirect | ms/frame | bounce relMSE | bounce brightness | character | contact | ground | other | image relMSE | character image relMSE |\n"
         << "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
    for (const BounceRow* r : selected)
      text << "| " << bounce_label(r->row) << " | " << cell(r->row.milliseconds, "%.2f") << " | "
           << cell(r->bounce.significant.relative_mse, "%.3f") << " | " << cell(r->bounce.significant.luminance_ratio, "%.2f")
           << " | " << cell(r->bounce.character.relative_mse, "%.3f") << " | " << cell(r->bounce.contact.relative_mse, "%.3f")
           << " | " << cell(r->bounce.ground.relative_mse, "%.3f") << " | " << cell(r->bounce.other.relative_mse, "%.3f")
           << " | " << cell(r->row.relative_mse, "%.4g") << " | "
           << cell(r->row.character_relative_mse, "%.4g") << " |\n";
  }
  return text.str();
}

std::string best_bounce_method(const std::vector<BounceRow>& rows, const std::string& scene) {
  const BounceRow* best = nullptr;
  for (const BounceRow& row : rows)
    if (row.row.scene == scene && row.bounce.significant.relative_mse >= 0.0 &&
        (!best || row.bounce.significant.relative_mse < best->bounce.significant.relative_mse))
      best = &row;
  return best ? bounce_label(best->row) : std::string();
}

}  // namespace proxygi::study
