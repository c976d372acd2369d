#pragma once
// SceneRenderer: a scene rendered on the GPU at any time, with any camera, into any output
// (DESIGN.md "One frame"). The CPU side is a world::World (models shared by file, rigs, clips,
// static meshes, environment SH), loaded once and evaluated per frame into a world state; the
// renderer uploads bind-pose meshes once, and per frame writes skin palettes and proxies into a
// ring slot and records the skin pass and the soft-GI passes.
//
// Frames in flight: begin(request) prepares and submits a frame into ring slot n mod N without
// waiting for the previous one; finish(ticket) waits for it and returns its pixels (or, for an
// image output, only its statistics). So a recorder keeps N frames on the GPU while it encodes
// finished ones, and a viewer renders into swapchain images.
//
// Settings change in place: apply_settings() rebuilds only what settings::classify_change says
// (pipelines, targets, tables) and the result equals a renderer created with those settings.
#include <array>
#include <chrono>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "base/result.h"
#include "gpu/context.h"
#include "gpu/material_textures.h"
#include "gpu/pass_timestamps.h"
#include "gpu/skin_pass.h"
#include "gpu/soft_gi_frame.h"
#include "prt/static_frame.h"
#include "quality/choose.h"
#include "scene/camera.h"
#include "scene/scene.h"
#include "world/proxy_lod.h"
#include "world/world.h"

namespace proxygi::gpu {

struct SceneRendererOptions {
  std::filesystem::path assets_dir;  // where assets/mannequin.glb and its rig live
  bool write_rig_cache = true;       // write fitted rigs next to their models
  bool refit = false;                // refit every rig, a scene's own rig file too (world::WorldOptions)
  prt::StaticFieldOptions static_transfer;  // how render.static_transfer ratio / l1 make the PRT
};

// The static receivers' PRT the frame uses (render.static_transfer; prt/static_frame.h).
struct StaticTransferReport {
  settings::StaticTransfer level = settings::StaticTransfer::l0;
  bool active = false;           // a PRT field is bound (level ratio or l1, and the scene has static meshes)
  bool from_cache = false;       // read from `file` (else computed and written there)
  std::filesystem::path file;
  double load_seconds = 0.0;     // subdivision, precompute or cache read, lookup grid
  double bake_ms = 0.0;          // the per-vertex records for the lighting, and their upload
  std::uint64_t rays = 0;        // traced by the precompute (0 from the cache)
  std::size_t vertices = 0, triangles = 0;
  std::size_t cpu_bytes = 0;     // the field (prt::StaticTransferField::bytes)
  std::size_t gpu_bytes = 0;     // its buffers on the GPU (SoftGiFrame::static_transfer_bytes)
  // The static meshes' visibility grid shading the other receivers (prt/visibility_grid.h).
  bool grid_from_cache = false;
  std::filesystem::path grid_file;
  double grid_seconds = 0.0;     // its compute or cache read (included in load_seconds)
  std::uint64_t grid_rays = 0;   // traced (0 from the cache)
  std::size_t grid_points = 0;
  std::size_t grid_bytes = 0;    // CPU (= GPU) memory of its values
};
// One line for summaries: "PRT (render.static_transfer l1): read prt-cache/prt-….bin, 21772 vertices, ...".
std::string describe(const StaticTransferReport& report);

struct FrameStatistics {
  std::size_t proxies = 0;           // proxies streamed this frame
  double cpu_prepare_ms = 0.0;       // world evaluation, skin palettes, tracking, uploads
};

// How time_passes measures:
//   fenced_cpu           each pass submitted and fenced on its own, timed with the CPU clock
//                        (their sum exceeds a pipelined frame's time by the per-submit overhead);
//   timestamps_if_valid  the whole frame in one submit with a GPU timestamp after each pass
//                        (pass_timestamps.h), fenced; used when the device's timestamps are valid
//                        and their sum is plausible against that fenced time (at least a quarter
//                        of it: lavapipe's go wrong after draws, rendering-notes §4.2), else
//                        fenced_cpu with the reason in `note`.
enum class PassClock { fenced_cpu, timestamps_if_valid };

// Milliseconds of each pass of one frame, keyed by the pass names of `bench frame`.
struct PassTimings {
  std::array<double, std::size_t(FramePass::count)> milliseconds{};  // indexed by FramePass
  // Fenced CPU timings only: the process's CPU time (user + system, every thread: lavapipe's
  // workers included) spent on each pass's submit, less sensitive to other processes' load
  // than the wall time; 0 with timestamps.
  std::array<double, std::size_t(FramePass::count)> cpu_milliseconds{};
  double cpu_prepare_ms = 0.0;
  std::size_t proxies = 0;
  bool timestamps = false;      // milliseconds come from GPU timestamps (else fenced CPU timings)
  double frame_fenced_ms = 0.0; // timestamps_if_valid: the one fenced submit of the whole frame
  std::string note;             // why fenced CPU timings were used, if timestamps were asked for
};

// What to render: a scene time and optionally a camera, or a world state evaluated by the caller.
struct FrameRequest {
  double time_s = 0.0;                       // scene time, seconds
  std::optional<scene::CameraState> camera;  // another camera than the scene's
  const world::WorldState* state = nullptr;  // when set, rendered as it is (time_s and camera unused)
  int frame = -1;                            // the scene frame this is (bookkeeping), -1: none
  std::uint32_t debug_view = 0;              // gpu_layout::kDebugView*: an input shown instead (viewer)
  FrameOutput output = FrameOutput::readback();
  // GPU timestamps after skinning and after each pass of this very frame, read when it finishes
  // (FinishedFrame::passes) with no wait or submit of its own: a live HUD's pass times. Unlike
  // time_passes nothing checks them against a fenced time; a sum longer than the frame's submit-to-
  // finish wall time is refused (passes->timestamps false, with a note), as is a device whose
  // timestamps are unusable.
  bool pass_timestamps = false;
};

struct FrameTicket {
  std::uint64_t id = 0;
};

struct FinishedFrame {
  int frame = -1;
  double time_s = 0.0;
  std::vector<render::Sphere> spheres;  // the proxies this frame streamed, world space
  std::vector<std::uint8_t> ldr;        // RGBA8 sRGB, width × height (readback outputs)
  image::ImageF hdr;                    // linear radiance (readback outputs with hdr)
  FrameStatistics statistics;
  std::optional<PassTimings> passes;    // FrameRequest::pass_timestamps
};

struct SkinGroup;  // scene_renderer_parts.h

class SceneRenderer {
 public:
  // Loads the scene's world (options.assets_dir, rigs fitted or cached) and renders it with the
  // scene's render settings at its output size.
  static Result<std::unique_ptr<SceneRenderer>> create(Context& context, const scene::Scene& scene,
                                                       const SceneRendererOptions& options);
  // Renders a world loaded by the caller (shared with other renderers, the path tracer, the
  // regression tracks) with these settings; the world must outlive the renderer.
  static Result<std::unique_ptr<SceneRenderer>> create(Context& context, std::shared_ptr<const world::World> world,
                                                       const settings::RenderSettings& settings, std::uint32_t width,
                                                       std::uint32_t height, std::uint32_t frames_in_flight = 2,
                                                       const prt::StaticFieldOptions& static_transfer = {});
  ~SceneRenderer();

  // Changes settings and output size in place (waits for frames in flight first). With
  // render.quality a target, the settings rendered are quality::ChooseSettingsJob's choice for the
  // last shot (the scene camera at the scene's first frame until requalify names another); the
  // requested order, k, upsampling and shadow_eta are replaced by the choice.
  Status apply_settings(const settings::RenderSettings& settings, std::uint32_t width, std::uint32_t height);

  // render.quality (quality/choose.h): the choice for `requested` at scene time `time_s` seen by
  // `camera` (the scene's when empty) on `height` pixels (× the supersampling factor). Manual:
  // `requested` unchanged, nothing evaluated. Does not change the renderer.
  Result<quality::QualityChoice> choose_quality(const settings::RenderSettings& requested, double time_s,
                                                const std::optional<scene::CameraState>& camera,
                                                std::uint32_t height) const;
  // Renders `choice.settings` from now on and remembers the choice and its shot (time, camera) for
  // later apply_settings calls. When its settings equal the current ones nothing is rebuilt (and
  // frames may be in flight); otherwise as apply_settings.
  Status apply_choice(const quality::QualityChoice& choice, double time_s, const std::optional<scene::CameraState>& camera,
                      std::uint32_t width, std::uint32_t height);
  // The choice the current settings came from (automatic false when render.quality is manual).
  const quality::QualityChoice& quality() const { return quality_; }

  // Prepares a frame and submits it without waiting for the GPU. Ring slots are used round-robin;
  // the next slot must be free: finish the oldest begun frame first when all are in flight.
  Result<FrameTicket> begin(const FrameRequest& request);
  // Waits for a begun frame and returns it.
  Result<FinishedFrame> finish(FrameTicket ticket);
  Result<FinishedFrame> render(const FrameRequest& request);

  // Scene frames (time frame / fps, the scene camera, readback with HDR).
  Status begin_frame(int frame);
  Result<FinishedFrame> finish_frame(int frame);  // the oldest begun frame with that number
  Result<FinishedFrame> render(int frame);
  // Prepares frame `frame` and times each of its passes (PassClock). Needs every begun frame
  // finished. The frame's pixels are not copied out; its composite writes what
  // run::time_pipelined_frames' frames keep (no irradiance AOV; the HDR when `hdr`).
  Result<PassTimings> time_passes(int frame, PassClock clock = PassClock::fenced_cpu, bool hdr = true);

  // The skinned world-space positions of the last finished frame, per instance and primitive in
  // the order of the instance's mesh nodes (what the G-buffer drew; for tests against the CPU
  // skinning of the same world state). Needs every begun frame finished.
  Result<std::vector<std::vector<std::vector<glm::vec3>>>> read_skinned_positions() const;

  const scene::Scene& scene() const { return world_->scene(); }
  const world::World& world() const { return *world_; }
  const SoftGiFrame& frame() const { return *frame_; }
  const FrameConfig& config() const { return frame_->config(); }
  std::size_t proxy_count() const { return world_->proxy_count(); }
  // render.proxy_lod auto: the levels and each instance's last choice (null before its first frame).
  const world::ProxyLod* proxy_lod() const { return proxy_lod_.get(); }
  std::size_t frames_in_flight() const;
  const StaticTransferReport& static_transfer() const { return static_report_; }
  // The PRT field in use (null when none) and its records for the current lighting (twin tests).
  const prt::StaticTransferField* static_field() const { return static_field_.get(); }
  std::span<const float> static_records() const { return static_records_; }
  // How many models' VSGL sender exposures (ref/sender_exposure.h) this renderer has computed.
  // Each model's is computed once, on first need (created with, or changed in place to,
  // render.indirect_method vsgl), shared by its instances and kept for the renderer's life.
  std::size_t sender_exposure_computations() const { return sender_exposure_computations_; }
  const prt::VisibilityGrid* static_visibility() const { return static_visibility_.get(); }

 private:
  struct ModelTextures;
  struct Instance;
  struct SlotState;
  explicit SceneRenderer(Context& context);
  Status upload_instances();
  // FrameRequest::pass_timestamps (scene_pass_timestamps.cpp): the slot's queries for the frame
  // about to be recorded (null when the device's timestamps are unusable, with the slot's note),
  // and the finished frame's pass times.
  const TimestampQueries* arm_timestamps(SlotState& slot);
  PassTimings read_timestamps(SlotState& slot);
  // Computes (once per model) and binds every instance's sender exposures (scene_meshes.cpp).
  Status ensure_sender_exposure();
  Status upload_static_meshes();  // ground (a quad, or the vertex method's grid) and static meshes
  Result<FrameConfig> make_config(const settings::RenderSettings& settings, std::uint32_t width,
                                  std::uint32_t height) const;
  Result<render::FrameTables> make_tables(const settings::RenderSettings& settings) const;
  // apply_settings with settings already chosen (no render.quality resolution).
  Status apply_resolved(const settings::RenderSettings& settings, std::uint32_t width, std::uint32_t height);
  // CPU half of a frame into ring slot `slot`: world state, skin palettes, constants, proxies.
  Result<std::vector<DrawItem>> prepare(const FrameRequest& request, std::uint32_t slot);
  void record_skinning(VkCommandBuffer commands, std::uint32_t slot) const;
  Status wait_all();
  // Loads (or drops) the PRT for settings.static_transfer and bakes its records for `tables`
  // (scene_static_transfer.cpp); the frame must be built for `settings`.
  Status update_static_transfer(const settings::RenderSettings& settings, const render::FrameTables& tables);

  Context& context_;
  std::shared_ptr<const world::World> world_;
  std::vector<std::unique_ptr<ModelTextures>> model_textures_;  // one per world model
  std::vector<std::unique_ptr<Instance>> instances_;
  std::vector<SkinGroup> skin_groups_;  // per model mesh node: its instances skinned together
  // Per model: its sender exposure buffers, one per primitive in anim::pose_meshes order.
  std::map<const world::Model*, std::vector<std::shared_ptr<const Buffer>>> sender_exposure_;
  std::size_t sender_exposure_computations_ = 0;
  std::vector<StaticMesh> static_meshes_;
  std::vector<std::unique_ptr<MaterialTextures>> static_textures_;  // the textures static_meshes_ bind
  settings::ShadingMethod static_meshes_method_ = settings::ShadingMethod::image_space;
  std::unique_ptr<SoftGiFrame> frame_;
  std::unique_ptr<SkinPass> skin_pass_;
  world::WorldState state_;  // scratch: the state evaluated for the frame being prepared
  prt::StaticFieldOptions static_options_;
  std::shared_ptr<const prt::StaticTransferField> static_field_;  // loaded once per SH order
  std::shared_ptr<const prt::VisibilityGrid> static_visibility_;   // with it
  std::vector<float> static_records_;
  StaticTransferReport static_report_;
  quality::QualityChoice quality_;             // render.quality: the current settings' choice
  double shot_time_s_ = 0.0;                    // and the shot it was made for
  std::optional<scene::CameraState> shot_camera_;
  std::unique_ptr<world::ProxyLod> proxy_lod_;  // render.proxy_lod auto: built on first use
  std::vector<render::Sphere> lod_spheres_;     // scratch: the spheres it streams this frame

  struct SlotState {
    Context::InFlight in_flight;
    bool busy = false;
    std::uint64_t ticket = 0;
    int frame = -1;
    double time_s = 0.0;
    FrameOutput output;
    std::vector<render::Sphere> spheres;
    FrameStatistics statistics;
    // FrameRequest::pass_timestamps: the slot's queries (made on first use), how many this frame
    // wrote (0: not timed), for which passes, and when it was submitted.
    std::optional<TimestampQueries> timestamps;
    std::uint32_t timestamps_written = 0;
    std::span<const FramePass> timed_passes;
    std::string timestamps_note;  // why a frame asked to be timed was not
    std::chrono::steady_clock::time_point submitted;
  };
  std::vector<SlotState> slots_;
  std::uint32_t next_slot_ = 0;
  std::uint64_t next_ticket_ = 1;
};

}  // namespace proxygi::gpu
