#include "gpu/scene_frame_settings.h"

#include <cmath>

namespace proxygi::gpu {

render::FrameTableSettings scene_table_settings(const scene::RenderSettings& render) {
  render::FrameTableSettings settings;
  settings.order = render.sh_order;
  settings.eta_shadow = render.shadow_eta;
  settings.eta_indirect = render.indirect_eta;
  return settings;
}

FrameSettings scene_frame_settings(const scene::Scene& scene) {
  FrameSettings settings;
  settings.method = scene.render.method == scene::ShadingMethod::vertex              ? ShadingMethod::vertex
                    : scene.render.method == scene::ShadingMethod::ambient_occlusion ? ShadingMethod::ambient_occlusion
                                                                                      : ShadingMethod::image_space;
  settings.width = std::uint32_t(scene.output.width);
  settings.height = std::uint32_t(scene.output.height);
  settings.receiver_scale = std::uint32_t(scene.render.receiver_scale);
  settings.hybrid_tau = scene.render.hyb_tau;
  settings.optimal_linear_only = scene.render.exponential == scene::Exponential::ol;
  settings.upsample = scene.render.upsampling == scene::Upsampling::bilinear ? render::UpsampleMode::bilinear
                                                                              : render::UpsampleMode::bilateral;
  settings.indirect = scene.render.indirect;
  settings.indirect_operator = scene.render.indirect_operator == scene::IndirectOperator::point   ? render::IndirectOperator::point
                               : scene.render.indirect_operator == scene::IndirectOperator::exact ? render::IndirectOperator::exact
                                                                                                  : render::IndirectOperator::averaged;
  settings.splat = scene.render.splat == scene::SplatMethod::raster ? SplatMethod::raster : SplatMethod::compute;
  settings.tonemap = scene.render.tonemap == scene::Tonemap::reinhard ? render::Tonemap::reinhard
                     : scene.render.tonemap == scene::Tonemap::clamp  ? render::Tonemap::clamp
                                                                      : render::Tonemap::aces;
  settings.exposure = std::exp2(scene.render.exposure_ev);
  return settings;
}

}  // namespace proxygi::gpu
