#include "apps/chart_methods.h"

#include "apps/commands.h"
#include "apps/frame_timing.h"
#include "gpu/scene_renderer.h"
#include "scene/scene_defaults.h"

namespace proxygi::app {
namespace {

const char* upsampling_name(scene::Upsampling upsampling) {
  return upsampling == scene::Upsampling::bilateral ? "bilateral" : "bilinear";
}

const char* indirect_name(scene::IndirectOperator indirect) {
  switch (indirect) {
    case scene::IndirectOperator::point: return "point";
    case scene::IndirectOperator::averaged: return "averaged";
    case scene::IndirectOperator::exact: return "exact";
  }
  return "?";
}

}  // namespace

std::vector<MethodSetting> method_grid(bool quick) {
  const scene::RenderSettings defaults;
  std::vector<MethodSetting> grid;
  const std::vector<int> orders = quick ? std::vector<int>{defaults.sh_order} : std::vector<int>{3, 4, 5, 6};
  const std::vector<int> scales = quick ? std::vector<int>{defaults.receiver_scale} : std::vector<int>{1, 2, 4, 8};
  const std::vector<scene::IndirectOperator> operators =
      quick ? std::vector<scene::IndirectOperator>{defaults.indirect_operator}
            : std::vector<scene::IndirectOperator>{scene::IndirectOperator::point, scene::IndirectOperator::averaged,
                                                   scene::IndirectOperator::exact};
  for (int order : orders)
    for (int scale : scales)
      for (scene::Upsampling upsampling : {scene::Upsampling::bilateral, scene::Upsampling::bilinear}) {
        if (scale == 1 && upsampling == scene::Upsampling::bilinear) continue;
        if (quick && upsampling != defaults.upsampling) continue;
        for (scene::IndirectOperator indirect : operators)
          grid.push_back({scene::ShadingMethod::image_space, order, scale, upsampling, indirect});
      }
  for (int order : orders)
    grid.push_back({scene::ShadingMethod::vertex, order, 1, scene::Upsampling::bilateral, defaults.indirect_operator});
  for (int scale : scales)
    grid.push_back({scene::ShadingMethod::ambient_occlusion, defaults.sh_order, scale, scene::Upsampling::bilateral,
                    defaults.indirect_operator});
  return grid;
}

study::ChartRow describe_setting(const MethodSetting& setting, const std::string& scene) {
  const scene::RenderSettings defaults;
  study::ChartRow row;
  row.scene = scene;
  switch (setting.method) {
    case scene::ShadingMethod::image_space:
      row.method = "proxy";
      row.sh_order = setting.sh_order;
      row.receiver_scale = setting.receiver_scale;
      if (setting.receiver_scale > 1) row.upsampling = upsampling_name(setting.upsampling);
      row.indirect = indirect_name(setting.indirect);
      row.is_default = setting.sh_order == defaults.sh_order && setting.receiver_scale == defaults.receiver_scale &&
                       setting.upsampling == defaults.upsampling && setting.indirect == defaults.indirect_operator;
      break;
    case scene::ShadingMethod::vertex:
      row.method = "vertex";
      row.sh_order = setting.sh_order;
      break;
    case scene::ShadingMethod::ambient_occlusion:
      row.method = "ao";
      row.receiver_scale = setting.receiver_scale;
      if (setting.receiver_scale > 1) row.upsampling = upsampling_name(setting.upsampling);
      break;
  }
  return row;
}

Result<study::ChartRow> run_raster_method(gpu::Context& context, const study::ChartScene& chart,
                                          const MethodSetting& setting,
                                          const std::vector<study::FrameReference>& references,
                                          const MethodRunOptions& options) {
  scene::Scene scene = chart.scene;
  scene.render.method = setting.method;
  scene.render.sh_order = setting.sh_order;
  scene.render.receiver_scale = setting.receiver_scale;
  scene.render.upsampling = setting.upsampling;
  scene.render.indirect_operator = setting.indirect;
  auto renderer = gpu::SceneRenderer::create(context, scene, {assets_dir(), true});
  if (!renderer) return renderer.error();
  study::ChartRow row = describe_setting(setting, chart.name);
  auto milliseconds = time_pipelined_frames(**renderer, scene.output.first_frame, options.timing_frames);
  if (!milliseconds) return milliseconds.error();
  row.milliseconds = *milliseconds;
  for (std::size_t i = 0; i < chart.frames.size(); ++i) {
    auto finished = (*renderer)->render(chart.frames[i]);
    if (!finished) return finished.error();
    auto scores = study::score_image(finished->hdr, references[i]);
    if (!scores) return make_error("frame " + std::to_string(chart.frames[i]) + ": " + scores.message());
    study::add_scores(row, *scores, 1.0 / double(chart.frames.size()));
  }
  return row;
}

}  // namespace proxygi::app
