#include "gpu/scene_renderer.h"

#include <time.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <functional>

#include "anim/skinning.h"
#include "base/log.h"
#include "gpu/pass_timestamps.h"
#include "gpu/scene_renderer_parts.h"
#include "render/environment_lighting.h"
#include "gpu/transfer.h"
#include "settings/fields.h"
#include "shaders/shared/layouts.h"

namespace proxygi::gpu {

SceneRenderer::SceneRenderer(Context& context) : context_(context) {}
SceneRenderer::~SceneRenderer() { (void)wait_all(); }

std::size_t SceneRenderer::frames_in_flight() const {
  std::size_t busy = 0;
  for (const SlotState& slot : slots_) busy += slot.busy ? 1 : 0;
  return busy;
}

Result<std::unique_ptr<SceneRenderer>> SceneRenderer::create(Context& context, const scene::Scene& scene,
                                                             const SceneRendererOptions& options) {
  world::WorldOptions world_options;
  world_options.assets_dir = options.assets_dir;
  world_options.write_rig_cache = options.write_rig_cache;
  world_options.refit = options.refit;
  auto world = world::World::load(scene, world_options);
  if (!world) return world.error();
  return create(context, std::shared_ptr<const world::World>(std::move(*world)), scene.render,
                std::uint32_t(scene.output.width), std::uint32_t(scene.output.height), 2, options.static_transfer);
}

Result<std::unique_ptr<SceneRenderer>> SceneRenderer::create(Context& context, std::shared_ptr<const world::World> world,
                                                             const settings::RenderSettings& requested,
                                                             std::uint32_t width, std::uint32_t height,
                                                             std::uint32_t frames_in_flight,
                                                             const prt::StaticFieldOptions& static_transfer) {
  if (!world) return make_error("scene renderer: no world");
  // render.quality: the shot is the scene camera at the scene's first frame.
  const double first_time_s = scene::frame_time_s(world->scene().output, world->scene().output.first_frame);
  auto choice = quality::choose_for_shot(*world, requested, first_time_s, std::nullopt, height);
  if (!choice) return choice.error();
  const settings::RenderSettings& settings = choice->settings;
  if (settings.splat == settings::SplatMethod::raster && settings.method != settings::ShadingMethod::image_space)
    log_warning("render.splat: 'raster' splats onto image-space receivers only; this method does not use it");
  std::unique_ptr<SceneRenderer> renderer(new SceneRenderer(context));
  renderer->world_ = std::move(world);
  auto skin_pass = SkinPass::create(context);
  if (!skin_pass) return skin_pass.error();
  renderer->skin_pass_ = std::make_unique<SkinPass>(std::move(*skin_pass));
  const std::uint32_t slots = std::max(frames_in_flight, 1u);
  for (std::uint32_t slot = 0; slot < slots; ++slot) {
    auto in_flight = context.create_in_flight();
    if (!in_flight) return in_flight.error();
    renderer->slots_.push_back({});
    renderer->slots_.back().in_flight = std::move(*in_flight);
  }
  if (Status s = renderer->upload_instances(); !s) return s.error();
  if (settings.indirect_method == settings::IndirectMethod::vsgl)
    if (Status s = renderer->ensure_sender_exposure(); !s) return s.error();
  renderer->static_meshes_method_ = settings.method;
  if (Status s = renderer->upload_static_meshes(); !s) return s.error();
  auto config = renderer->make_config(settings, width, height);
  if (!config) return config.error();
  auto tables = renderer->make_tables(settings);
  if (!tables) return tables.error();
  auto environment = renderer->world_->environment(settings.sh_order);
  if (!environment) return environment.error();
  auto frame = SoftGiFrame::create(context, *config, *tables, (*environment)->background);
  if (!frame) return frame.error();
  renderer->frame_ = std::move(*frame);
  renderer->static_options_ = static_transfer;
  if (Status s = renderer->update_static_transfer(settings, *tables); !s) return s.error();
  renderer->quality_ = std::move(*choice);
  renderer->shot_time_s_ = first_time_s;
  return renderer;
}

Result<FrameConfig> SceneRenderer::make_config(const settings::RenderSettings& settings, std::uint32_t width,
                                               std::uint32_t height) const {
  FrameConfig config;
  config.render = settings;
  config.width = width;
  config.height = height;
  config.frames_in_flight = std::uint32_t(slots_.size());
  if (settings.method == settings::ShadingMethod::vertex) {
    // Every vertex of every draw is a receiver, each draw starting a group (frame_config.h).
    std::uint64_t receivers = 0;
    for (const auto& instance : instances_)
      for (const auto& mesh : instance->meshes)
        for (const auto& primitive : skin_groups_[mesh.group].primitives)
          receivers += round_up_to_receiver_group(primitive.bind_pose->vertex_count);
    for (const auto& mesh : static_meshes_) receivers += round_up_to_receiver_group(mesh.draw().vertex_count());
    // Receivers × n² floats of log occlusion must fit one storage buffer binding.
    const std::uint64_t order = std::uint64_t(settings.sh_order);
    const std::uint64_t limit = context_.report().max_storage_buffer_range / (sizeof(float) * order * order);
    if (receivers > limit)
      return make_error("render.method vertex: " + std::to_string(receivers) + " vertex receivers, at most " +
                        std::to_string(limit) + " fit this device's storage buffers at order " +
                        std::to_string(settings.sh_order));
    config.vertex_receivers = std::uint32_t(receivers);
  }
  return config;
}

Result<render::FrameTables> SceneRenderer::make_tables(const settings::RenderSettings& settings) const {
  auto environment = world_->environment(settings.sh_order);
  if (!environment) return environment.error();
  const scene::Ground& ground = world_->scene().ground;
  return render::make_frame_tables((*environment)->lighting, settings, render::GroundInput{ground.enabled, ground.albedo},
                                   {}, render::scene_sun(world_->scene(), (*environment)->lighting.order));
}

Status SceneRenderer::wait_all() {
  Status result;
  for (SlotState& slot : slots_)
    if (Status waited = slot.in_flight.wait(); !waited && result) result = waited;
  return result;
}

Status SceneRenderer::apply_settings(const settings::RenderSettings& settings, std::uint32_t width,
                                     std::uint32_t height) {
  auto choice = choose_quality(settings, shot_time_s_, shot_camera_, height);
  if (!choice) return choice.error();
  if (choice->automatic) return apply_choice(*choice, shot_time_s_, shot_camera_, width, height);
  if (Status applied = apply_resolved(settings, width, height); !applied) return applied;
  quality_ = std::move(*choice);
  return {};
}

Result<quality::QualityChoice> SceneRenderer::choose_quality(const settings::RenderSettings& requested, double time_s,
                                                             const std::optional<scene::CameraState>& camera,
                                                             std::uint32_t height) const {
  return quality::choose_for_shot(*world_, requested, time_s, camera, height);
}

Status SceneRenderer::apply_choice(const quality::QualityChoice& choice, double time_s,
                                   const std::optional<scene::CameraState>& camera, std::uint32_t width, std::uint32_t height) {
  const FrameConfig& current = frame_->config();
  if (choice.settings != frame_->settings() || width != current.width || height != current.height)
    if (Status applied = apply_resolved(choice.settings, width, height); !applied) return applied;
  quality_ = choice;
  shot_time_s_ = time_s;
  shot_camera_ = camera;
  return {};
}

Status SceneRenderer::apply_resolved(const settings::RenderSettings& settings, std::uint32_t width,
                                     std::uint32_t height) {
  if (auto invalid = settings::check_settings(settings)) return make_error("render." + *invalid);
  for (const SlotState& slot : slots_)
    if (slot.busy) return make_error("apply_settings: finish every begun frame first");
  if (Status waited = wait_all(); !waited) return waited;
  const settings::Needs needs = settings::classify_change(frame_->settings(), settings);
  if (settings.indirect_method == settings::IndirectMethod::vsgl)
    if (Status exposed = ensure_sender_exposure(); !exposed) return exposed;
  const bool method_changed = settings.method != frame_->settings().method;
  if (method_changed) {  // the vertex method draws a tessellated ground
    static_meshes_method_ = settings.method;
    const settings::ShadingMethod before = frame_->settings().method;
    if ((before == settings::ShadingMethod::vertex) != (settings.method == settings::ShadingMethod::vertex)) {
      auto previous = std::move(frame_);
      Status uploaded = upload_static_meshes();
      frame_ = std::move(previous);
      if (!uploaded) return uploaded;
    }
  }
  auto config = make_config(settings, width, height);
  if (!config) return config.error();
  render::FrameTables tables;
  if (needs & settings::kNeedTables) {
    auto made = make_tables(settings);
    if (!made) return made.error();
    tables = std::move(*made);
  }
  if (Status applied = frame_->apply(*config, tables); !applied) return applied;
  // render.static_transfer needs tables: a new level, order or lighting re-bakes the records.
  if (needs & settings::kNeedTables) return update_static_transfer(settings, tables);
  return {};
}

Result<std::vector<DrawItem>> SceneRenderer::prepare(const FrameRequest& request, std::uint32_t slot) {
  const auto start = std::chrono::steady_clock::now();
  const world::WorldState* state = request.state;
  if (state == nullptr) {
    if (Status evaluated = world_->evaluate(request.time_s, request.camera, state_); !evaluated)
      return evaluated.error();
    state = &state_;
  }
  if (state->instances.size() != instances_.size())
    return make_error("frame: the world state holds " + std::to_string(state->instances.size()) +
                      " characters, the renderer " + std::to_string(instances_.size()));
  const settings::RenderSettings& render = frame_->settings();
  if (render.indirect_method == settings::IndirectMethod::vsgl &&
      instances_.size() * std::size_t(render.vsgl_lights) > gpu_layout::kVsglMaxLights)
    return make_error("render.indirect_method vsgl: " + std::to_string(instances_.size()) + " characters × " +
                      std::to_string(render.vsgl_lights) + " lights, at most " +
                      std::to_string(gpu_layout::kVsglMaxLights) + " lights");
  // render.vsgl_grouping bone_groups: the triangle order uploaded for K = render.vsgl_lights.
  const bool by_bone_group = render.indirect_method == settings::IndirectMethod::vsgl &&
                             render.vsgl_grouping == settings::VsglGrouping::bone_groups;
  const std::size_t lights_order = std::size_t(
      std::find(settings::kVsglLightsPerCharacter.begin(), settings::kVsglLightsPerCharacter.end(), render.vsgl_lights) -
      settings::kVsglLightsPerCharacter.begin());
  if (by_bone_group && lights_order == settings::kVsglLightsPerCharacter.size())
    return make_error("render.vsgl_lights " + std::to_string(render.vsgl_lights) + " is not one of 1, 2, 4, 8");
  std::vector<DrawItem> draws;
  for (std::size_t index = 0; index < instances_.size(); ++index) {
    const anim::PoseBuffers& pose = state->instances[index].pose;
    for (auto& mesh : instances_[index]->meshes) {
      // Normals go through the inverse-transposes, as pose_meshes does (exact under any scale).
      const glm::mat4& node_world = pose.world[std::size_t(mesh.node)];
      const std::vector<glm::mat4> rigid = {node_world}, rigid_normals = {anim::normal_matrix(node_world)};
      const bool skinned = mesh.skin >= 0;
      const auto& palette = skinned ? pose.skin_matrices[std::size_t(mesh.skin)] : rigid;
      const auto& normals = skinned ? pose.normal_matrices[std::size_t(mesh.skin)] : rigid_normals;
      // This instance's ranges of its group's palettes and morph weights.
      SkinGroup& group = skin_groups_[mesh.group];
      const std::size_t palette_at = std::size_t(mesh.group_instance) * group.palette_joints * sizeof(glm::mat4);
      std::memcpy(static_cast<std::uint8_t*>(group.palettes[slot].mapped()) + palette_at, palette.data(),
                  palette.size() * sizeof(glm::mat4));
      std::memcpy(static_cast<std::uint8_t*>(group.normal_palettes[slot].mapped()) + palette_at, normals.data(),
                  normals.size() * sizeof(glm::mat4));
      if (!group.morph_weights.empty())
        std::memcpy(static_cast<std::uint8_t*>(group.morph_weights[slot].mapped()) +
                        std::size_t(mesh.group_instance) * group.morph_targets * sizeof(float),
                    pose.morph_weights.data() + mesh.morph_offset, group.morph_targets * sizeof(float));
      for (std::size_t i = 0; i < group.primitives.size(); ++i) {
        const SkinGroup::Primitive& skinned_primitive = group.primitives[i];
        draws.push_back({&skinned_primitive.world_positions, &skinned_primitive.world_normals, mesh.indices[i].get(),
                         mesh.index_counts[i], mesh.materials[i].base_color,
                         mesh.uvs[i].get(), mesh.materials[i].texture, int(index)});
        draws.back().first_vertex = mesh.group_instance * skinned_primitive.instance_stride;
        draws.back().vertices = skinned_primitive.bind_pose->vertex_count;
        draws.back().vsgl_exposure = mesh.vsgl_exposure[i].get();
        if (render.indirect_method == settings::IndirectMethod::vsgl && !draws.back().vsgl_exposure)
          return make_error("frame: instance " + std::to_string(index) + " has no sender exposure (internal)");
        if (by_bone_group) {
          draws.back().vsgl_indices = &mesh.vsgl_orders[i]->indices;
          draws.back().vsgl_group_first = mesh.vsgl_orders[i]->first[lights_order];
        }
      }
    }
  }
  for (const auto& mesh : static_meshes_) draws.push_back(mesh.draw());

  const scene::CameraState& camera = state->camera;
  const FrameConfig& config = frame_->config();
  const float aspect = float(config.width) / float(config.height);
  FrameView view = frame_view(camera, aspect);
  view.debug_view = request.debug_view;
  // render.proxy_lod auto: each character's level by its size on screen (world/proxy_lod.h).
  const std::vector<render::Sphere>* streamed = &state->spheres;
  if (render.proxy_lod == settings::ProxyLod::automatic) {
    if (!proxy_lod_) {
      auto built = world::ProxyLod::build(*world_);
      if (!built) return built.error();
      proxy_lod_ = std::move(*built);
    }
    lod_spheres_.clear();
    if (Status selected = proxy_lod_->select(*state, config.height, lod_spheres_); !selected) return selected.error();
    streamed = &lod_spheres_;
  }
  if (Status written = frame_->write_slot(slot, view, *streamed); !written) return written.error();

  SlotState& current = slots_[slot];
  current.spheres = *streamed;
  current.time_s = state->time_s;
  current.statistics = {};
  current.statistics.proxies = streamed->size();
  current.statistics.cpu_prepare_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return draws;
}

Result<FrameTicket> SceneRenderer::begin(const FrameRequest& request) {
  const std::uint32_t slot = next_slot_;
  SlotState& current = slots_[slot];
  if (current.busy)
    return make_error("frame " + std::to_string(current.frame) + " still holds ring slot " + std::to_string(slot) +
                      ": finish it before beginning another");
  if (Status prepared = frame_->prepare_output(request.output); !prepared) return prepared.error();
  auto draws = prepare(request, slot);
  if (!draws) return draws.error();
  const TimestampQueries* timestamps = request.pass_timestamps ? arm_timestamps(current) : nullptr;
  Status submitted = current.in_flight.submit([&](VkCommandBuffer commands) {
    if (timestamps) timestamps->reset(commands), timestamps->write(commands, 0);
    record_skinning(commands, slot);
    if (timestamps) timestamps->write(commands, 1);
    frame_->record(commands, slot, *draws, request.output, timestamps, 2);
  });
  if (!submitted) return submitted.error();
  current.submitted = std::chrono::steady_clock::now();
  current.busy = true;
  current.ticket = next_ticket_++;
  current.frame = request.frame;
  current.output = request.output;
  next_slot_ = (next_slot_ + 1) % std::uint32_t(slots_.size());
  return FrameTicket{current.ticket};
}

Result<FinishedFrame> SceneRenderer::finish(FrameTicket ticket) {
  std::uint32_t slot = 0;
  while (slot < slots_.size() && !(slots_[slot].busy && slots_[slot].ticket == ticket.id)) ++slot;
  if (slot == slots_.size()) return make_error("frame ticket " + std::to_string(ticket.id) + " was not begun");
  SlotState& current = slots_[slot];
  if (Status waited = current.in_flight.wait(); !waited) return waited.error();
  FinishedFrame finished;
  finished.frame = current.frame;
  finished.time_s = current.time_s;
  if (current.output.readback_ldr) {
    const auto ldr = frame_->slot_ldr(slot);
    finished.ldr.assign(ldr.begin(), ldr.end());
  }
  if (current.output.readback_hdr) finished.hdr = frame_->slot_hdr(slot);
  finished.statistics = current.statistics;
  finished.spheres = std::move(current.spheres);
  if (current.timestamps_written > 0 || !current.timestamps_note.empty()) finished.passes = read_timestamps(current);
  current.busy = false;
  return finished;
}

Result<FinishedFrame> SceneRenderer::render(const FrameRequest& request) {
  auto ticket = begin(request);
  if (!ticket) return ticket.error();
  return finish(*ticket);
}

namespace {

// CPU time of the whole process (every thread), milliseconds.
double process_cpu_ms() {
  timespec now{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &now);
  return double(now.tv_sec) * 1e3 + double(now.tv_nsec) * 1e-6;
}

FrameRequest scene_frame(const scene::Scene& scene, int frame) {
  FrameRequest request;
  request.time_s = scene::frame_time_s(scene.output, frame);
  request.frame = frame;
  return request;
}

}  // namespace

Status SceneRenderer::begin_frame(int frame) {
  auto ticket = begin(scene_frame(scene(), frame));
  if (!ticket) return ticket.error();
  return {};
}

Result<FinishedFrame> SceneRenderer::finish_frame(int frame) {
  const SlotState* oldest = nullptr;
  for (const SlotState& slot : slots_)
    if (slot.busy && slot.frame == frame && (oldest == nullptr || slot.ticket < oldest->ticket)) oldest = &slot;
  if (oldest == nullptr) return make_error("frame " + std::to_string(frame) + " was not begun");
  return finish({oldest->ticket});
}

Result<FinishedFrame> SceneRenderer::render(int frame) { return render(scene_frame(scene(), frame)); }

Result<PassTimings> SceneRenderer::time_passes(int frame, PassClock clock, bool hdr) {
  for (const SlotState& slot : slots_)
    if (slot.busy) return make_error("time_passes: finish every begun frame first");
  const auto start = std::chrono::steady_clock::now();
  auto draws = prepare(scene_frame(scene(), frame), 0);
  if (!draws) return draws.error();
  PassTimings timings;
  timings.cpu_prepare_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  timings.proxies = slots_[0].statistics.proxies;
  double last_cpu_ms = 0.0;  // the process CPU time of the last `timed` submit
  auto timed = [&](const std::function<void(VkCommandBuffer)>& record) -> Result<double> {
    const double begin_cpu = process_cpu_ms();
    const auto begin_time = std::chrono::steady_clock::now();
    if (Status done = context_.submit_and_wait(record); !done) return done.error();
    const auto end_time = std::chrono::steady_clock::now();
    last_cpu_ms = process_cpu_ms() - begin_cpu;
    return std::chrono::duration<double, std::milli>(end_time - begin_time).count();
  };
  const auto passes = frame_pass_order(frame_->settings().method);
  // The outputs of run::time_pipelined_frames' frames (no AOV, the HDR when asked): the same composite.
  FrameOutput output = FrameOutput::readback(hdr);
  output.float_targets = false;
  if (clock == PassClock::timestamps_if_valid) {
    // One submit: a timestamp before skinning and after it and each pass.
    auto queries = TimestampQueries::create(context_, std::uint32_t(passes.size()) + 2);
    if (!queries) {
      timings.note = queries.message();
    } else {
      auto fenced = timed([&](VkCommandBuffer commands) {
        queries->reset(commands);
        queries->write(commands, 0);
        record_skinning(commands, 0);
        queries->write(commands, 1);
        PassBarriers barriers;
        memory_barrier(commands);  // skinning wrote what the G-buffer reads
        for (std::size_t p = 0; p < passes.size(); ++p) {
          frame_->record_pass(commands, 0, passes[p], *draws, barriers, output);
          queries->write(commands, std::uint32_t(p) + 2);
        }
      });
      if (!fenced) return fenced.error();
      auto intervals = queries->intervals_ms();
      if (!intervals) return intervals.error();
      double sum = 0.0;
      for (double ms : *intervals) sum += ms;
      timings.frame_fenced_ms = *fenced;
      char note[160];
      std::snprintf(note, sizeof note, "timestamps implausible: %.3g ms of %.3g ms fenced", sum, *fenced);
      if (sum >= 0.25 * *fenced && sum <= *fenced) {
        timings.timestamps = true;
        timings.milliseconds[std::size_t(FramePass::skin)] = (*intervals)[0];
        for (std::size_t p = 0; p < passes.size(); ++p) timings.milliseconds[std::size_t(passes[p])] = (*intervals)[p + 1];
        return timings;
      }
      timings.note = note;
    }
  }
  auto skin = timed([&](VkCommandBuffer commands) { record_skinning(commands, 0); });
  if (!skin) return skin.error();
  timings.milliseconds[std::size_t(FramePass::skin)] = *skin;
  timings.cpu_milliseconds[std::size_t(FramePass::skin)] = last_cpu_ms;
  for (FramePass pass : passes) {
    auto ms = timed([&](VkCommandBuffer commands) {
      memory_barrier(commands);  // the previous pass's submission wrote what this one reads
      PassBarriers barriers;
      frame_->record_pass(commands, 0, pass, *draws, barriers, output);
    });
    if (!ms) return ms.error();
    timings.milliseconds[std::size_t(pass)] = *ms;
    timings.cpu_milliseconds[std::size_t(pass)] = last_cpu_ms;
  }
  return timings;
}

}  // namespace proxygi::gpu
