#include "gpu/frame_pass_set.h"

#include "base/log.h"

namespace proxygi::gpu {

// The order-dependent shaders are compiled for every order the settings allow (shaders/CMakeLists.txt).
static_assert(PROXYGI_SHADER_FIRST_ORDER <= settings::kMinShOrder && PROXYGI_SHADER_LAST_ORDER >= settings::kMaxShOrder);

bool uses_raster_splat(const FrameConfig& config) {
  return config.render.splat == settings::SplatMethod::raster &&
         config.render.method == settings::ShadingMethod::image_space;
}

namespace {

// Assigns a created pass to its slot or returns its error.
template <class Pass>
Status emplace(std::optional<Pass>& slot, Result<Pass> made) {
  if (!made) return made.error();
  slot.emplace(std::move(*made));
  return {};
}

}  // namespace

Result<FramePassSet> FramePassSet::create(Context& context, const FrameConfig& config) {
  const settings::RenderSettings& render = config.render;
  const int order = render.sh_order;
  if (order < settings::kMinShOrder || order > settings::kMaxShOrder)
    return make_error("frame: SH order " + std::to_string(order) + " is not in " +
                      std::to_string(settings::kMinShOrder) + ".." + std::to_string(settings::kMaxShOrder));
  FramePassSet set;
  const bool vertex = render.method == settings::ShadingMethod::vertex;
  const bool ambient_occlusion = render.method == settings::ShadingMethod::ambient_occlusion;
  if (Status s = emplace(set.gbuffer, GbufferPass::create(context, vertex)); !s) return s.error();
  if (Status s = emplace(set.upsample_composite, UpsampleCompositePass::create(context)); !s) return s.error();
  if (vertex) {
    if (Status s = emplace(set.vertex_receivers, VertexReceiversPass::create(context)); !s) return s.error();
  } else {
    if (Status s = emplace(set.receivers, ReceiversPass::create(context)); !s) return s.error();
  }
  if (ambient_occlusion) {
    if (Status s = emplace(set.ambient_occlusion, AmbientOcclusionPass::create(context, order)); !s) return s.error();
    if (Status s = set.rebuild_sized(context, config); !s) return s.error();
    return set;
  }
  if (!uses_raster_splat(config))
    if (Status s = emplace(set.shadow_gather, ShadowGatherPass::create(context, order)); !s) return s.error();
  if (Status s = emplace(set.exponentiate, ExponentiatePass::create(context, order, render.static_transfer)); !s) return s.error();
  if (Status s = emplace(set.indirect, IndirectPass::create(context, render)); !s) return s.error();
  if (render.indirect_method == settings::IndirectMethod::vsgl)
    if (Status s = emplace(set.vsgl_lights, VsglLightsPass::create(context)); !s) return s.error();
  if (render.indirect_method == settings::IndirectMethod::vsgl && render.vsgl_sun == settings::VsglSun::automatic)
    if (Status s = emplace(set.rsm, RsmPass::create(context)); !s) return s.error();
  if (Status s = set.rebuild_sized(context, config); !s) return s.error();
  return set;
}

Status FramePassSet::rebuild_sized(Context& context, const FrameConfig& config) {
  shadow_splat.reset();
  if (config.supersampling() == 1) supersample_resolve.reset();
  else if (!supersample_resolve)
    if (Status s = emplace(supersample_resolve, SupersampleResolvePass::create(context)); !s) return s;
  if (!uses_raster_splat(config)) return {};
  auto splat = ShadowSplatPass::create(context, config.render.sh_order, config.shading_width(), config.shading_height(),
                                       std::uint32_t(config.render.receiver_scale));
  if (!splat) return splat.error();
  shadow_splat = std::move(*splat);
  return {};
}

}  // namespace proxygi::gpu
