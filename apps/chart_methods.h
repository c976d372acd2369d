#pragma once
// The GPU rows of `proxygi bench chart`: every rasterized method and setting rendered through
// gpu::SceneRenderer, timed (whole frames, pipelined) and scored against the chart references.
#include <string>
#include <vector>

#include "base/result.h"
#include "gpu/context.h"
#include "scene/scene.h"
#include "study/chart_rows.h"
#include "study/chart_scenes.h"
#include "study/reference_study.h"

namespace proxygi::app {

struct MethodSetting {
  scene::ShadingMethod method = scene::ShadingMethod::image_space;
  int sh_order = 4;
  int receiver_scale = 4;
  scene::Upsampling upsampling = scene::Upsampling::bilateral;
  scene::IndirectOperator indirect = scene::IndirectOperator::averaged;
};

// The grid: the proxy method at SH orders 3–6 × receivers 1/1, 1/2, 1/4, 1/8 × bilateral
// or bilinear (1/1 has nothing to upsample: bilateral only) × indirect point, averaged, exact; the
// vertex baseline at orders 3–6; AO at 1/1 .. 1/8 (bilateral). `quick`: order 4, 1/4, averaged,
// and each baseline once (for tests).
std::vector<MethodSetting> method_grid(bool quick);

// The chart row's identity of a setting (times and errors still zero).
study::ChartRow describe_setting(const MethodSetting& setting, const std::string& scene);

struct MethodRunOptions {
  int timing_frames = 4;  // pipelined frames timed after two warm-up frames
};

// Renders `chart` with `setting`: ms per frame from a pipelined run starting at the scene's
// first frame, errors averaged over chart.frames (references[i] belongs to chart.frames[i]).
Result<study::ChartRow> run_raster_method(gpu::Context& context, const study::ChartScene& chart,
                                          const MethodSetting& setting,
                                          const std::vector<study::FrameReference>& references,
                                          const MethodRunOptions& options);

}  // namespace proxygi::app
