#pragma once
// The GPU rows of `proxygi bench chart`: every rasterized method and setting rendered through
// gpu::SceneRenderer, timed (whole frames, pipelined) and scored against the chart references.
#include <functional>
#include <utility>
#include <string>
#include <vector>

#include "base/result.h"
#include "gpu/context.h"
#include "scene/scene.h"
#include "study/bounce_rows.h"
#include "study/chart_rows.h"
#include "study/chart_scenes.h"
#include "study/reference_study.h"

namespace proxygi::app {

struct MethodSetting {
  settings::ShadingMethod method = settings::ShadingMethod::image_space;
  int sh_order = 4;
  int receiver_scale = 4;
  settings::Upsampling upsampling = settings::Upsampling::bilateral;
  settings::IndirectOperator indirect = settings::IndirectOperator::averaged;
  settings::IndirectMethod indirect_method = settings::IndirectMethod::proxy;  // vsgl, none: `indirect` unused
  int vsgl_lights = 1;  // vsgl: lights per character (render.vsgl_lights)
  bool ground_bounce = true;  // render.ground_bounce
  settings::VsglGrouping vsgl_grouping = settings::VsglGrouping::vertex_ranges;  // vsgl: render.vsgl_grouping
  settings::Antialiasing antialiasing = settings::Antialiasing::off;  // render.antialiasing
  settings::StaticTransfer static_transfer = settings::StaticTransfer::l0;  // render.static_transfer
  // render.quality: a target makes the row method "quality", each chart frame rendered with the
  // settings chosen for its shot (the fields above are then only what is requested).
  float quality = settings::kQualityManual;
  bool mask_sender_light = true;  // render.mask_sender_light (false: the paper's sender light)
};

// The grid: the proxy method at SH orders 3–6 × receivers 1/1, 1/2, 1/4, 1/8 × bilateral
// or bilinear (1/1 has nothing to upsample: bilateral only) × indirect point, averaged, exact; the
// vertex baseline at orders 3–6; AO at 1/1 .. 1/8 (bilateral); at the default order and k the
// other bounce methods, indirect_method vsgl (K = 1, 2, 4, 8 lights per character by index range,
// K = 2, 4, 8 by bone group) and none (no bounce); and the default proxy setting without the
// ground bounce; the default setting supersampled (render.antialiasing ssaa2 and ssaa4: what the
// edge region's error and the frame time do with anti-aliasing); the default proxy setting with
// render.static_transfer ratio and l1 (on scenes without static meshes they render as l0); and
// render.quality at its three named levels (draft, balanced, high), requested on the default setting;
// and the default setting with the paper's sender light (render.mask_sender_light off).
// `quick`: order 4, 1/4, bilateral with the three operators, the seven vsgl rows, none, no ground
// bounce, ssaa2 and ssaa4, the two static-transfer rows, the three quality rows, the paper's sender
// light, and each baseline once.
std::vector<MethodSetting> method_grid(bool quick);

// The chart row's identity of a setting (times and errors still zero).
study::ChartRow describe_setting(const MethodSetting& setting, const std::string& scene);

struct MethodRunOptions {
  int timing_frames = 4;  // pipelined frames timed after two warm-up frames
  // When set (one per chart frame, as `references`): the bounce chart's rows with their grid
  // index, appended to `bounce_rows` after the sweep, for each setting bounce_row_setting
  // accepts, scored against the grid's indirect_method none setting (which the grid must hold).
  const std::vector<study::BounceReference>* bounce_references = nullptr;
  std::vector<std::pair<std::size_t, study::BounceRow>>* bounce_rows = nullptr;
};

// The settings the bounce chart scores: the proxy method at the default SH order, receiver scale
// and upsampling, with the ground bounce, any indirect method (none included: its bounce is 0),
// without anti-aliasing.
bool bounce_row_setting(const MethodSetting& setting);

// Renders `chart` with every setting of `grid` on one renderer, each setting applied in place
// (run::sweep_settings: the scene's models are imported and its rigs obtained once): ms per frame
// from a pipelined run starting at the scene's first frame, errors averaged over chart.frames
// (references[i] belongs to chart.frames[i]). on_row gets each row as it is measured.
Status run_raster_methods(gpu::Context& context, const study::ChartScene& chart, const std::vector<MethodSetting>& grid,
                          const std::vector<study::FrameReference>& references, const MethodRunOptions& options,
                          const std::function<void(std::size_t index, const study::ChartRow& row)>& on_row);

}  // namespace proxygi::app
