#pragma once
// SceneRenderer: a whole scene file rendered frame by frame on the GPU (DESIGN.md "One frame").
// Set-up (once): load every character (sharing models between instances), obtain each model's
// proxy rig (the cached *.proxies.json when its model hash matches, else fit and cache it),
// project the environment to SH, build the frame tables and the SoftGiFrame, upload bind-pose
// meshes and the ground. Per frame: CPU sampling, local-to-model, skin palettes and proxy
// tracking into the frame's ring slot; GPU skinning and the soft-GI passes.
//
// Frames in flight: begin_frame(f) prepares and submits frame f into ring slot f mod N without
// waiting for frame f−1; finish_frame(f) waits for it and returns its pixels. So a recorder can
// keep N frames on the GPU while it encodes finished ones.
#include <array>
#include <chrono>
#include <filesystem>
#include <memory>
#include <vector>

#include "base/result.h"
#include "gpu/context.h"
#include "gpu/material_textures.h"
#include "gpu/skin_pass.h"
#include "gpu/soft_gi_frame.h"
#include "proxies/tracking.h"
#include "scene/scene.h"

namespace proxygi::gpu {

struct SceneRendererOptions {
  std::filesystem::path assets_dir;  // where assets/mannequin.glb and its rig live
  bool write_rig_cache = true;       // write fitted rigs next to their models
};

struct FrameStatistics {
  std::size_t proxies = 0;           // proxies streamed this frame
  double cpu_prepare_ms = 0.0;       // sampling, skin palettes, tracking, uploads
};

// Milliseconds of each pass of one frame, each submitted and fenced on its own and timed with
// the CPU clock (lavapipe's GPU timestamps are unreliable, rendering-notes §4.2). Their sum
// exceeds a pipelined frame's time by the per-submit overhead.
struct PassTimings {
  std::array<double, std::size_t(FramePass::count)> milliseconds{};  // indexed by FramePass
  double cpu_prepare_ms = 0.0;
  std::size_t proxies = 0;
};

struct FinishedFrame {
  int frame = 0;
  std::vector<render::Sphere> spheres;  // the proxies this frame streamed, world space
  std::vector<std::uint8_t> ldr;     // RGBA8 sRGB, width × height
  image::ImageF hdr;                 // linear radiance
  FrameStatistics statistics;
};

class SceneRenderer {
 public:
  static Result<std::unique_ptr<SceneRenderer>> create(Context& context, const scene::Scene& scene,
                                                       const SceneRendererOptions& options);
  ~SceneRenderer();

  // Prepares frame `frame` (scene time frame / fps) and submits it without waiting for the GPU.
  // Ring slots are used round-robin whatever the frame numbers (shards, resumed gaps); the next
  // slot must be free: finish the oldest begun frame first when all are in flight.
  Status begin_frame(int frame);
  // Waits for frame `frame` (begun earlier) and returns its pixels.
  Result<FinishedFrame> finish_frame(int frame);
  // begin + finish.
  Result<FinishedFrame> render(int frame);
  // Prepares frame `frame` and runs its passes one submit each, timing every pass. Needs every
  // begun frame finished. The frame's pixels are not copied out.
  Result<PassTimings> time_passes(int frame);

  const scene::Scene& scene() const { return scene_; }
  const SoftGiFrame& frame() const { return *frame_; }
  std::size_t proxy_count() const;

 private:
  struct Model;
  struct Instance;
  explicit SceneRenderer(Context& context);
  // CPU half of a frame into ring slot `slot`: poses, skin palettes, tracking, constants.
  Result<std::vector<DrawItem>> prepare_frame(int frame, std::uint32_t slot);
  void record_skinning(VkCommandBuffer commands, std::uint32_t slot) const;  // out of line: Model and Instance are incomplete here

  Context& context_;
  scene::Scene scene_;
  std::vector<std::unique_ptr<Model>> models_;
  std::vector<std::unique_ptr<Instance>> instances_;
  std::vector<StaticMesh> static_meshes_;
  std::vector<std::unique_ptr<MaterialTextures>> static_textures_;  // the textures static_meshes_ bind
  std::unique_ptr<SoftGiFrame> frame_;
  std::unique_ptr<SkinPass> skin_pass_;
  std::vector<Context::InFlight> in_flight_;
  std::vector<int> slot_frame_;              // frame held by each slot, −1 when free
  std::vector<std::vector<render::Sphere>> slot_spheres_;  // proxies of the frame in each slot
  std::uint32_t next_slot_ = 0;
  std::vector<FrameStatistics> slot_statistics_;
  std::vector<render::Sphere> spheres_;      // scratch: this frame's proxies
};

}  // namespace proxygi::gpu
