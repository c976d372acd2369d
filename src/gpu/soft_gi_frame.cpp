#include "gpu/soft_gi_frame.h"

#include <cstring>
#include <limits>

#include "gpu/context.h"
#include "gpu/transfer.h"
#include "settings/fields.h"
#include "shaders/shared/layouts.h"
#include "sh/vsgl_sun.h"

namespace proxygi::gpu {
namespace {

Status check_config(const FrameConfig& config) {
  if (config.width < 1 || config.height < 1) return make_error("frame: empty output size");
  if (!settings::is_receiver_scale(config.render.receiver_scale))
    return make_error("frame: receiver scale " + std::to_string(config.render.receiver_scale) + " is not 1, 2, 4 or 8");
  if (auto invalid = settings::check_settings(config.render)) return make_error("frame: render." + *invalid);
  return {};
}

std::uint32_t composite_mode(const FrameConfig& config) {
  if (config.render.method == settings::ShadingMethod::vertex) return gpu_layout::kCompositeDisplayIrradiance;
  return config.render.upsampling == settings::Upsampling::bilinear ? gpu_layout::kCompositeBilinear
                                                                     : gpu_layout::kCompositeBilateral;
}

std::uint32_t tonemap_code(settings::Tonemap tonemap) {
  switch (tonemap) {
    case settings::Tonemap::reinhard: return gpu_layout::kTonemapReinhard;
    case settings::Tonemap::clamp: return gpu_layout::kTonemapClamp;
    case settings::Tonemap::aces: break;
  }
  return gpu_layout::kTonemapAces;
}

}  // namespace

Result<std::unique_ptr<SoftGiFrame>> SoftGiFrame::create(Context& context, const FrameConfig& config,
                                                         const render::FrameTables& tables,
                                                         const image::ImageF& environment) {
  if (Status valid = check_config(config); !valid) return valid.error();
  if (environment.width < 1 || environment.height < 1) return make_error("frame: empty environment image");
  std::unique_ptr<SoftGiFrame> frame(new SoftGiFrame(context));
  frame->config_ = config;
  auto passes = FramePassSet::create(context, config);
  if (!passes) return passes.error();
  frame->passes_ = std::move(*passes);
  if (Status s = frame->build_targets(); !s) return s.error();
  if (Status s = frame->upload_tables(tables); !s) return s.error();
  auto environment_buffer =
      create_buffer_with_data(context, as_bytes(std::span<const glm::vec4>(environment.pixels)),
                              VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT);
  if (!environment_buffer) return environment_buffer.error();
  if (Status s = environment_buffer->add_texel_view(context, VK_FORMAT_R32G32B32A32_SFLOAT); !s) return s.error();
  frame->environment_ = std::move(*environment_buffer);
  frame->environment_width_ = std::uint32_t(environment.width);
  frame->environment_height_ = std::uint32_t(environment.height);
  if (Status s = frame->build_slots(); !s) return s.error();
  if (Status s = frame->set_static_transfer(nullptr, {}, nullptr); !s) return s.error();
  return frame;
}

Status SoftGiFrame::apply(const FrameConfig& config, const render::FrameTables& tables) {
  if (Status valid = check_config(config); !valid) return valid;
  settings::Needs needs = settings::classify_change(config_.render, config.render);
  const bool resized = config.width != config_.width || config.height != config_.height;
  if (resized || config.vertex_receivers != config_.vertex_receivers) needs |= settings::kNeedTargets;
  const bool reslot = resized || config.frames_in_flight != config_.frames_in_flight;
  const FrameConfig previous = config_;
  config_ = config;
  Status applied = [&]() -> Status {
    if (needs & settings::kNeedPipelines) {
      auto passes = FramePassSet::create(context_, config_);
      if (!passes) return passes.error();
      passes_ = std::move(*passes);
    } else if (needs & settings::kNeedTargets) {
      if (Status s = passes_.rebuild_sized(context_, config_); !s) return s;
    }
    if (needs & settings::kNeedTargets)
      if (Status s = build_targets(); !s) return s;
    if (needs & settings::kNeedTables)
      if (Status s = upload_tables(tables); !s) return s;
    if (reslot)
      if (Status s = build_slots(); !s) return s;
    return {};
  }();
  if (!applied) config_ = previous;  // what failed is rebuilt again on the next apply
  return applied;
}

FrameView frame_view(const scene::CameraState& camera, float aspect) {
  FrameView view;
  view.view = scene::view_matrix(camera);
  view.projection = scene::projection_matrix(camera, aspect);
  view.eye = camera.eye;
  view.forward = glm::normalize(camera.target - camera.eye);
  return view;
}

Status SoftGiFrame::write_slot(std::uint32_t slot, const FrameView& view, std::span<const render::Sphere> spheres) {
  if (slot >= slots_.size()) return make_error("frame: slot " + std::to_string(slot) + " out of range");
  if (spheres.size() > gpu_layout::kMaxProxies)
    return make_error("frame: " + std::to_string(spheres.size()) + " proxies, at most " +
                      std::to_string(gpu_layout::kMaxProxies) + " per frame");
  const settings::RenderSettings& render = config_.render;
  gpu_layout::FrameConstants constants{};
  constants.view_projection = view.projection * view.view;
  constants.inverse_view_projection = glm::inverse(constants.view_projection);
  constants.eye_position = glm::vec4(view.eye, 1.0f);
  constants.eye_forward = glm::vec4(glm::normalize(view.forward), 0.0f);
  constants.debug_view = view.debug_view;
  slots_[slot].debug_view = view.debug_view != gpu_layout::kDebugViewFinal;
  // The heat map reads the tile lists of the gather and the AO pass (the raster splat keeps none;
  // the vertex method's receivers are vertices, not screen tiles).
  constants.tile_counts_valid = render.method == settings::ShadingMethod::ambient_occlusion ||
                                        (render.method == settings::ShadingMethod::image_space &&
                                         render.splat == settings::SplatMethod::compute)
                                    ? 1u
                                    : 0u;
  constants.occlusion_scale = render.method == settings::ShadingMethod::ambient_occlusion ? 1.0f : 1.0f / 3.5449077018110318f;
  constants.display_width = config_.shading_width();  // the passes' "display" is the shading grid
  constants.display_height = config_.shading_height();
  constants.receiver_width = config_.receiver_width();
  constants.receiver_height = config_.receiver_height();
  constants.proxy_count = std::uint32_t(spheres.size());
  constants.receiver_scale = std::uint32_t(render.receiver_scale);
  constants.sh_order = std::uint32_t(render.sh_order);
  constants.composite_mode = composite_mode(config_);
  constants.shadow_eta = tables_.shadow_eta;
  constants.indirect_eta = render.indirect_eta;
  constants.hybrid_tau = render.exponential == settings::Exponential::ol ? std::numeric_limits<float>::max() : render.hyb_tau;
  constants.log_table_rows = tables_.log_table_rows;
  constants.optimal_linear_max_norm = tables_.optimal_linear_max;
  constants.optimal_linear_rows = tables_.optimal_linear_rows;
  constants.visibility_table_rows = tables_.visibility_rows;
  constants.lighting_cube_face_size = tables_.cube_size;
  constants.exposure = settings::exposure_multiplier(render);
  constants.tonemap = tonemap_code(render.tonemap);
  constants.bilateral_depth_epsilon = render.bilateral_depth_epsilon;
  constants.indirect_enabled = render.indirect_method != settings::IndirectMethod::none ? 1u : 0u;
  // The sun variant: the map fitted to the proxies' box (sh::rsm_margin); without it the vertex
  // VPLs keep the whole L̃.
  slots_[slot].rsm = passes_.rsm && tables_.vsgl_sun && !spheres.empty();
  const auto& sender = slots_[slot].rsm ? tables_.vsgl_sender_order3 : tables_.irradiance_order3;
  for (int channel = 0; channel < 3; ++channel)
    for (int i = 0; i < 9; ++i)
      constants.vsgl_sender_sh[channel * 9 + i] = glm::vec4(sender[std::size_t(channel)][std::size_t(i)], 0, 0, 0);
  if (slots_[slot].rsm) {
    glm::dvec3 low(std::numeric_limits<double>::max()), high(-std::numeric_limits<double>::max());
    for (const render::Sphere& sphere : spheres) {
      low = glm::min(low, glm::dvec3(sphere.center) - double(sphere.radius));
      high = glm::max(high, glm::dvec3(sphere.center) + double(sphere.radius));
    }
    const sh::RsmView rsm = sh::fit_rsm_view(glm::dvec3(tables_.sun_direction), low, high, int(gpu_layout::kRsmSize),
                                             sh::rsm_margin(low, high));
    constants.rsm_view_projection = glm::mat4(rsm.view_projection());
    constants.rsm_inverse_view_projection = glm::mat4(glm::inverse(rsm.view_projection()));
    constants.rsm_toward_sun = glm::vec4(glm::vec3(rsm.toward_sun), 1.0f);
    constants.rsm_texel_flux = glm::vec4(tables_.sun_irradiance * float(rsm.texel_area()), 0.0f);
  }
  std::memcpy(slots_[slot].constants.mapped(), &constants, sizeof(constants));

  slots_[slot].proxy_count = std::uint32_t(spheres.size());
  auto* proxies = static_cast<gpu_layout::ProxySphere*>(slots_[slot].proxies.mapped());
  for (std::size_t i = 0; i < spheres.size(); ++i) {
    proxies[i].center_radius = glm::vec4(spheres[i].center, spheres[i].radius);
    proxies[i].albedo = glm::vec4(spheres[i].albedo, spheres[i].weight);
  }
  return {};
}

void SoftGiFrame::record_pass(VkCommandBuffer commands, std::uint32_t slot_index, FramePass pass,
                              std::span<const DrawItem> draws, PassBarriers& barriers,
                              const FrameOutput& output) const {
  const Slot& slot = slots_[slot_index];
  const Targets& t = targets_;
  const std::uint32_t rw = config_.receiver_width(), rh = config_.receiver_height();
  // Barriers from the pass's declared accesses, a debug label, the pass.
  auto run = [&](const auto& object, const auto& in, const auto& out) {
    barriers.before(commands, object.accesses(in, out));
    context_.begin_label(commands, frame_pass_name(pass));
    object.record(context_, commands, in, out);
    context_.end_label(commands);
  };
  switch (pass) {
    case FramePass::gbuffer:
      run(*passes_.gbuffer, GbufferPass::Inputs{&slot.constants, draws, &t.shaded, config_.vertex_receivers,
                                        config_.shading_width(), config_.shading_height()},
          GbufferPass::Outputs{&t.position_depth, &t.normal, &t.albedo, &t.depth});
      break;
    case FramePass::receivers:
      if (passes_.vertex_receivers)
        run(*passes_.vertex_receivers, VertexReceiversPass::Inputs{draws, config_.vertex_receivers},
            VertexReceiversPass::Outputs{&t.receivers});
      else
        run(*passes_.receivers, ReceiversPass::Inputs{&slot.constants, &t.position_depth, &t.normal, rw, rh},
            ReceiversPass::Outputs{&t.receivers});
      break;
    case FramePass::shadow:
      if (passes_.ambient_occlusion) {
        run(*passes_.ambient_occlusion,
            AmbientOcclusionPass::Inputs{&slot.constants, &t.receivers, &slot.proxies, &tables_.lighting_cube, rw, rh},
            AmbientOcclusionPass::Outputs{&t.direct, &t.indirect, &t.shaded, &t.tile_counts});
      } else if (passes_.shadow_splat) {
        const ShadowSplatInputs inputs{&slot.constants, &t.receivers, &slot.proxies, slot.proxy_count,
                                       &tables_.log_table, &t.log_occlusion};
        barriers.before(commands, passes_.shadow_splat->accesses(inputs));
        context_.begin_label(commands, frame_pass_name(pass));
        passes_.shadow_splat->record(commands, inputs);
        context_.end_label(commands);
      } else {
        run(*passes_.shadow_gather,
            ShadowGatherPass::Inputs{&slot.constants, &t.receivers, &slot.proxies, &tables_.log_table, rw, rh},
            ShadowGatherPass::Outputs{&t.log_occlusion, &t.tile_counts});
      }
      break;
    case FramePass::exponentiate:
      run(*passes_.exponentiate,
          ExponentiatePass::Inputs{&slot.constants, &t.receivers, &t.log_occlusion, &tables_.optimal_linear,
                                   &tables_.lighting_cube, rw, rh, &static_.positions, &static_.triangles,
                                   &static_.grid, &static_.records, &static_.visibility},
          ExponentiatePass::Outputs{&t.direct});
      break;
    case FramePass::indirect:
      if (passes_.vsgl_lights) {
        const std::uint32_t per_sender = std::uint32_t(config_.render.vsgl_lights);
        std::uint32_t sun_partials = 0;
        if (passes_.rsm && slot.rsm) {
          run(*passes_.rsm, RsmPass::Inputs{&slot.constants, draws, per_sender},
              RsmPass::Outputs{&t.rsm_position, &t.rsm_normal, &t.rsm_flux, &t.rsm_depth, &t.vsgl_partials});
          sun_partials = RsmPass::partial_count(draws, per_sender);
        }
        run(*passes_.vsgl_lights, VsglLightsPass::Inputs{&slot.constants, draws, per_sender, sun_partials},
            VsglLightsPass::Outputs{&t.vsgl_partials, &t.vsgl_lights});
      }
      run(*passes_.indirect,
          IndirectPass::Inputs{&slot.constants, &t.receivers, &slot.proxies, &tables_.visibility_table, &t.direct,
                               &tables_.exact_indirect, &t.vsgl_lights, &tables_.sender_light, rw, rh},
          IndirectPass::Outputs{&t.indirect, &t.shaded});
      break;
    case FramePass::upsample_composite: {
      // Supersampled: the composite writes the samples in RGBA order, the resolve the display frame.
      const bool supersampled = passes_.supersample_resolve.has_value();
      // The views' pipeline writes every output; otherwise only what the caller reads.
      const bool aov = output.float_targets || slot.debug_view;
      const bool hdr = aov || output.readback_hdr || supersampled;
      irradiance_written_ = aov;
      hdr_written_ = hdr;
      run(*passes_.upsample_composite,
          UpsampleCompositePass::Inputs{&slot.constants, &t.position_depth, &t.normal, &t.albedo, &t.receivers,
                                        &t.shaded, &t.direct, &t.indirect, &t.tile_counts, &environment_,
                                        environment_width_, environment_height_,
                                        config_.shading_width(), config_.shading_height(), ldr_bgra_ && !supersampled,
                                        slot.debug_view, aov, hdr},
          UpsampleCompositePass::Outputs{&t.irradiance, supersampled ? &t.sample_hdr : &t.hdr,
                                         supersampled ? &t.sample_ldr : &t.ldr});
      break;
    }
    case FramePass::supersample_resolve:
      if (passes_.supersample_resolve)
        run(*passes_.supersample_resolve,
            SupersampleResolvePass::Inputs{&t.sample_hdr, &t.sample_ldr, config_.width, config_.height,
                                           config_.supersampling(), ldr_bgra_},
            SupersampleResolvePass::Outputs{&t.hdr, &t.ldr});
      break;
    case FramePass::skin:
    case FramePass::count:
      break;
  }
}

void SoftGiFrame::record(VkCommandBuffer commands, std::uint32_t slot, std::span<const DrawItem> draws,
                         const FrameOutput& output, const TimestampQueries* timestamps,
                         std::uint32_t first_timestamp) const {
  memory_barrier(commands);  // the previous frame on the queue may still read these targets
  PassBarriers barriers;
  std::uint32_t timestamp = first_timestamp;
  for (FramePass pass : frame_pass_order(config_.render.method)) {
    record_pass(commands, slot, pass, draws, barriers, output);
    if (timestamps) timestamps->write(commands, timestamp++);
  }
  const ResourceAccess copied[] = {reads(&targets_.ldr, VK_PIPELINE_STAGE_2_COPY_BIT | VK_PIPELINE_STAGE_2_BLIT_BIT),
                                   reads(&targets_.hdr, VK_PIPELINE_STAGE_2_COPY_BIT)};
  barriers.before(commands, copied);
  record_output(commands, slot, output);
}

std::span<const std::uint8_t> SoftGiFrame::slot_ldr(std::uint32_t slot) const {
  const Buffer& buffer = slots_[slot].ldr_readback;
  return {static_cast<const std::uint8_t*>(buffer.mapped()), std::size_t(buffer.size())};
}

image::ImageF SoftGiFrame::slot_hdr(std::uint32_t slot) const {
  image::ImageF out{int(config_.width), int(config_.height)};
  std::memcpy(out.pixels.data(), slots_[slot].hdr_readback.mapped(), out.pixels.size() * sizeof(glm::vec4));
  return out;
}

}  // namespace proxygi::gpu
