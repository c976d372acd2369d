#include "apps/chart_methods.h"

#include <algorithm>
#include <map>
#include <optional>

#include "apps/commands.h"
#include "gpu/scene_renderer.h"
#include "run/frame_loop.h"
#include "run/settings_sweep.h"
#include "settings/fields.h"
#include "world/world.h"
#include "scene/scene_defaults.h"

namespace proxygi::app {

std::vector<MethodSetting> method_grid(bool quick) {
  const settings::RenderSettings defaults;
  std::vector<MethodSetting> grid;
  std::vector<int> orders = {defaults.sh_order};
  std::vector<int> scales = {defaults.receiver_scale};
  if (!quick) {
    orders.clear();
    for (int order = settings::kMinShOrder; order <= settings::kMaxShOrder; ++order) orders.push_back(order);
    scales.assign(settings::kReceiverScales.begin(), settings::kReceiverScales.end());
  }
  const std::vector<settings::IndirectOperator> operators = {
      settings::IndirectOperator::point, settings::IndirectOperator::averaged, settings::IndirectOperator::exact};
  for (int order : orders)
    for (int scale : scales)
      for (settings::Upsampling upsampling : {settings::Upsampling::bilateral, settings::Upsampling::bilinear}) {
        if (scale == 1 && upsampling == settings::Upsampling::bilinear) continue;
        if (quick && upsampling != defaults.upsampling) continue;
        for (settings::IndirectOperator indirect : operators)
          grid.push_back({settings::ShadingMethod::image_space, order, scale, upsampling, indirect});
      }
  for (settings::VsglGrouping grouping : {settings::VsglGrouping::vertex_ranges, settings::VsglGrouping::bone_groups})
    for (int lights : settings::kVsglLightsPerCharacter) {
      if (lights == 1 && grouping == settings::VsglGrouping::bone_groups) continue;  // one light: no grouping
      grid.push_back({settings::ShadingMethod::image_space, defaults.sh_order, defaults.receiver_scale,
                      defaults.upsampling, defaults.indirect_operator, settings::IndirectMethod::vsgl, lights, true,
                      grouping});
    }
  grid.push_back({settings::ShadingMethod::image_space, defaults.sh_order, defaults.receiver_scale, defaults.upsampling,
                  defaults.indirect_operator, settings::IndirectMethod::none});
  // What the lit ground adds: the default setting with render.ground_bounce off.
  grid.push_back({settings::ShadingMethod::image_space, defaults.sh_order, defaults.receiver_scale, defaults.upsampling,
                  defaults.indirect_operator, settings::IndirectMethod::proxy, 1, false});
  // The default setting supersampled: the edge region's error against the cost.
  for (settings::Antialiasing antialiasing : {settings::Antialiasing::ssaa2, settings::Antialiasing::ssaa4})
    grid.push_back({settings::ShadingMethod::image_space, defaults.sh_order, defaults.receiver_scale, defaults.upsampling,
                    defaults.indirect_operator, defaults.indirect_method, defaults.vsgl_lights, defaults.ground_bounce,
                    defaults.vsgl_grouping, antialiasing});
  // Static receivers' PRT and static geometry shadowing the characters (l0 is the default row).
  for (settings::StaticTransfer level : {settings::StaticTransfer::ratio, settings::StaticTransfer::l1})
    grid.push_back({settings::ShadingMethod::image_space, defaults.sh_order, defaults.receiver_scale, defaults.upsampling,
                    defaults.indirect_operator, settings::IndirectMethod::proxy, 1, true,
                    settings::VsglGrouping::vertex_ranges, settings::Antialiasing::off, level});
  // The paper's sender light: the proxies reflect the whole environment (render.mask_sender_light off).
  MethodSetting paper_senders;
  paper_senders.mask_sender_light = false;
  grid.push_back(paper_senders);
  // render.quality at each named level: the chooser against the sweep (study/quality_rows.h).
  for (const auto& [name, target] : settings::kQualityLevels) {
    if (target == settings::kQualityManual) continue;
    MethodSetting quality;
    quality.quality = target;
    grid.push_back(quality);
  }
  for (int order : orders)
    grid.push_back({settings::ShadingMethod::vertex, order, 1, settings::Upsampling::bilateral, defaults.indirect_operator});
  for (int scale : scales)
    grid.push_back({settings::ShadingMethod::ambient_occlusion, defaults.sh_order, scale, settings::Upsampling::bilateral,
                    defaults.indirect_operator});
  return grid;
}

bool bounce_row_setting(const MethodSetting& setting) {
  const settings::RenderSettings defaults;
  return setting.method == settings::ShadingMethod::image_space && setting.quality == settings::kQualityManual &&
         setting.sh_order == defaults.sh_order &&
         setting.receiver_scale == defaults.receiver_scale && setting.upsampling == defaults.upsampling &&
         setting.ground_bounce && setting.antialiasing == defaults.antialiasing &&
         setting.static_transfer == settings::StaticTransfer::l0;
}

study::ChartRow describe_setting(const MethodSetting& setting, const std::string& scene) {
  const settings::RenderSettings defaults;
  study::ChartRow row;
  row.scene = scene;
  row.ground_bounce = setting.ground_bounce;
  row.mask_sender_light = setting.mask_sender_light;
  if (setting.antialiasing != settings::Antialiasing::off) row.antialiasing = std::string(settings::name_of(setting.antialiasing));
  row.static_transfer = std::string(settings::name_of(setting.static_transfer));
  if (setting.quality != settings::kQualityManual) {
    row.method = "quality";
    row.quality_target = setting.quality;
    const auto name = settings::value_name(*settings::find_field("quality"), setting.quality);
    row.quality = name ? std::string(*name) : std::to_string(setting.quality);
    return row;
  }
  switch (setting.method) {
    case settings::ShadingMethod::image_space:
      row.method = "proxy";
      row.sh_order = setting.sh_order;
      row.receiver_scale = setting.receiver_scale;
      if (setting.receiver_scale > 1) row.upsampling = std::string(settings::name_of(setting.upsampling));
      // The bounce column: the proxy operator, "vsgl<K>" (K lights per character; "vsgl<K>-bones"
      // by bone group) or "none".
      row.indirect = setting.indirect_method == settings::IndirectMethod::proxy
                         ? std::string(settings::name_of(setting.indirect))
                         : std::string(settings::name_of(setting.indirect_method));
      if (setting.indirect_method == settings::IndirectMethod::vsgl) {
        row.indirect += std::to_string(setting.vsgl_lights);
        if (setting.vsgl_grouping == settings::VsglGrouping::bone_groups) row.indirect += "-bones";
      }
      row.is_default = setting.sh_order == defaults.sh_order && setting.receiver_scale == defaults.receiver_scale &&
                       setting.upsampling == defaults.upsampling && setting.indirect == defaults.indirect_operator &&
                       setting.indirect_method == defaults.indirect_method && setting.ground_bounce == defaults.ground_bounce &&
                       setting.antialiasing == defaults.antialiasing && setting.static_transfer == defaults.static_transfer &&
                       setting.mask_sender_light == defaults.mask_sender_light;
      break;
    case settings::ShadingMethod::vertex:
      row.method = "vertex";
      row.sh_order = setting.sh_order;
      break;
    case settings::ShadingMethod::ambient_occlusion:
      row.method = "ao";
      row.receiver_scale = setting.receiver_scale;
      if (setting.receiver_scale > 1) row.upsampling = std::string(settings::name_of(setting.upsampling));
      break;
  }
  return row;
}

namespace {

// render.quality's choice for scene frame `frame` (its time, the scene camera), applied in place
// and timed from that frame; the chosen order, k and upsampling go into `out`.
Status choose_for_frame(gpu::SceneRenderer& live, const settings::RenderSettings& requested, const scene::Scene& scene,
                        int frame, int timing_frames, study::ChartFrame& out) {
  const double time_s = scene::frame_time_s(scene.output, frame);
  const auto width = std::uint32_t(scene.output.width), height = std::uint32_t(scene.output.height);
  auto choice = live.choose_quality(requested, time_s, std::nullopt, height);
  if (!choice) return choice.error();
  if (Status applied = live.apply_choice(*choice, time_s, std::nullopt, width, height); !applied) return applied;
  auto milliseconds = run::time_pipelined_frames(live, frame, timing_frames);
  if (!milliseconds) return milliseconds.error();
  out.milliseconds = *milliseconds;
  out.sh_order = choice->settings.sh_order;
  out.receiver_scale = choice->settings.receiver_scale;
  if (out.receiver_scale > 1) out.upsampling = std::string(settings::name_of(choice->settings.upsampling));
  return {};
}

}  // namespace

Status run_raster_methods(gpu::Context& context, const study::ChartScene& chart, const std::vector<MethodSetting>& grid,
                          const std::vector<study::FrameReference>& references, const MethodRunOptions& options,
                          const std::function<void(std::size_t index, const study::ChartRow& row)>& on_row) {
  if (grid.empty()) return {};
  const scene::Scene& scene = chart.scene;
  auto world = world::World::load(scene, {.assets_dir = assets_dir(), .load_rigs = true, .write_rig_cache = true});
  if (!world) return world.error();
  std::vector<settings::RenderSettings> grid_settings;
  for (const MethodSetting& setting : grid) {
    settings::RenderSettings render = scene.render;
    render.method = setting.method;
    render.sh_order = setting.sh_order;
    render.receiver_scale = setting.receiver_scale;
    render.upsampling = setting.upsampling;
    render.indirect_operator = setting.indirect;
    render.ground_bounce = setting.ground_bounce;
    render.indirect_method = setting.indirect_method;
    render.vsgl_lights = setting.vsgl_lights;
    render.vsgl_grouping = setting.vsgl_grouping;
    render.antialiasing = setting.antialiasing;
    render.static_transfer = setting.static_transfer;
    render.quality = setting.quality;
    render.mask_sender_light = setting.mask_sender_light;
    grid_settings.push_back(render);
  }
  auto renderer = gpu::SceneRenderer::create(context, std::shared_ptr<const world::World>(std::move(*world)),
                                             grid_settings.front(), std::uint32_t(scene.output.width),
                                             std::uint32_t(scene.output.height));
  if (!renderer) return renderer.error();
  // Bounce chart: the frames of each scored setting, kept until the none setting's are known.
  const bool bounce = options.bounce_references && options.bounce_rows;
  std::vector<std::size_t> bounce_settings;
  std::optional<std::size_t> none_setting;
  std::map<std::size_t, std::pair<study::ChartRow, std::vector<image::ImageF>>> bounce_frames;
  if (bounce)
    for (std::size_t i = 0; i < grid.size(); ++i)
      if (bounce_row_setting(grid[i])) {
        bounce_settings.push_back(i);
        if (grid[i].indirect_method == settings::IndirectMethod::none) none_setting = i;
      }
  if (bounce && !none_setting) return make_error("the bounce chart needs the indirect_method none setting in the grid");
  const Status swept = run::sweep_settings(**renderer, grid_settings, [&](std::size_t index, gpu::SceneRenderer& live) -> Status {
    study::ChartRow row = describe_setting(grid[index], chart.name);
    const bool per_shot = row.method == "quality";
    if (!per_shot) {
      auto milliseconds = run::time_pipelined_frames(live, scene.output.first_frame, options.timing_frames);
      if (!milliseconds) return milliseconds.error();
      row.milliseconds = *milliseconds;
    }
    for (std::size_t i = 0; i < chart.frames.size(); ++i) {
      study::ChartFrame frame;
      if (per_shot) {  // the choice for this frame's shot, timed from this frame
        if (Status chosen = choose_for_frame(live, grid_settings[index], scene, chart.frames[i], options.timing_frames, frame); !chosen)
          return chosen;
        row.milliseconds += frame.milliseconds / double(chart.frames.size());
      }
      auto finished = live.render(chart.frames[i]);
      if (!finished) return finished.error();
      auto scores = study::score_image(finished->hdr, references[i]);
      if (!scores) return make_error("frame " + std::to_string(chart.frames[i]) + ": " + scores.message());
      study::add_scores(row, *scores, 1.0 / double(chart.frames.size()));
      frame.relative_mse = scores->relative_mse;
      row.frames.push_back(frame);
      if (std::find(bounce_settings.begin(), bounce_settings.end(), index) != bounce_settings.end())
        bounce_frames[index].second.push_back(std::move(finished->hdr));
    }
    if (bounce_frames.count(index)) bounce_frames[index].first = row;
    on_row(index, row);
    return {};
  });
  if (!swept || !bounce) return swept;
  const std::vector<image::ImageF>& none = bounce_frames.at(*none_setting).second;
  for (std::size_t index : bounce_settings) {
    auto& [row, frames] = bounce_frames.at(index);
    std::vector<study::BounceScores> scores;
    for (std::size_t i = 0; i < frames.size(); ++i) {
      auto frame_bounce = study::bounce_image(frames[i], none[i]);
      if (!frame_bounce) return frame_bounce.error();
      auto scored = study::score_bounce(*frame_bounce, (*options.bounce_references)[i]);
      if (!scored) return make_error("frame " + std::to_string(chart.frames[i]) + " bounce: " + scored.message());
      scores.push_back(*scored);
    }
    options.bounce_rows->push_back({index, study::BounceRow{row, study::mean_bounce_scores(scores)}});
  }
  return {};
}

}  // namespace proxygi::app
