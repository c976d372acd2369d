#pragma once
// SoftGiFrame: the GPU half of one proxygi frame (DESIGN.md "One frame, as data", steps 2–8,
// with 7 and 8 fused into one pass;
// step 1, skinning, is gpu::SkinPass, run by the caller before record()). It owns the frame's
// targets, the uploaded tables (render::FrameTables) and a ring of per-frame upload slots, so
// the CPU can write frame t+1's constants and proxies while the GPU still renders frame t.
//
//   auto frame = SoftGiFrame::create(context, settings, tables, environment_image);
//   frame->write_slot(slot, view, spheres);          // host writes, no GPU wait
//   context.submit_and_wait([&](VkCommandBuffer c) { frame->record(c, slot, draws); });
//   frame->read_ldr() / read_hdr() / read_receivers() ...
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "base/result.h"
#include "gpu/frame_passes.h"
#include "gpu/frame_settings.h"
#include "gpu/material_textures.h"
#include "gpu/resources.h"
#include "gpu/shadow_splat_pass.h"
#include "image/image.h"
#include "render/frame_tables.h"
#include "render/shading.h"

namespace proxygi::gpu {

class Context;

// Where the frame looks from. World space, meters; projection is Vulkan clip space (depth 0..1,
// framebuffer y down) as src/scene/camera.h builds it.
struct FrameView {
  glm::mat4 view{1.0f};
  glm::mat4 projection{1.0f};
  glm::vec3 eye{0.0f};
  glm::vec3 forward{0.0f, 0.0f, -1.0f};  // unit image-plane normal
};

// One mesh draw of the G-buffer pass: world-space vec4 positions and normals, 32-bit indices;
// albedo = base_color × texture (gpu/material_textures.h) at the vertices' uvs.
struct DrawItem {
  const Buffer* positions = nullptr;
  const Buffer* normals = nullptr;
  const Buffer* indices = nullptr;
  std::uint32_t index_count = 0;
  glm::vec4 base_color{1.0f};   // linear albedo factor
  const Buffer* uvs = nullptr;  // vec2 TEXCOORD_0 per vertex; null: uv (0, 0)
  BaseColorTexture texture;     // null view: white
  std::uint32_t vertex_count() const { return positions ? std::uint32_t(positions->size() / sizeof(glm::vec4)) : 0; }
};

// The vertex method's receiver capacity for these draws: each draw's vertices start a new group
// (FrameSettings::vertex_receivers must be at least this).
std::uint32_t vertex_receiver_count(std::span<const DrawItem> draws);

// A static world-space mesh uploaded once (ground, static meshes).
struct StaticMesh {
  Buffer positions;  // vec4
  Buffer normals;    // vec4
  Buffer indices;    // uint32
  Buffer uvs;        // vec2; no handle when the mesh has none
  std::uint32_t index_count = 0;
  glm::vec4 base_color{1.0f};
  BaseColorTexture texture;
  DrawItem draw() const {
    return {&positions, &normals, &indices, index_count, base_color, uvs.handle() != VK_NULL_HANDLE ? &uvs : nullptr,
            texture};
  }
};
// uvs: empty or one per position. The texture's image and sampler must outlive the mesh's draws.
Result<StaticMesh> upload_static_mesh(Context& context, std::span<const glm::vec3> positions,
                                      std::span<const glm::vec3> normals, std::span<const std::uint32_t> indices,
                                      const glm::vec4& base_color, std::span<const glm::vec2> uvs = {},
                                      const BaseColorTexture& texture = {});

class SoftGiFrame {
 public:
  // environment: the equirectangular radiance shown behind the scene (sh/environment.h layout).
  static Result<std::unique_ptr<SoftGiFrame>> create(Context& context, const FrameSettings& settings,
                                                     const render::FrameTables& tables,
                                                     const image::ImageF& environment);

  // Writes slot `slot`'s frame constants and proxies (host-visible, no GPU wait). The caller
  // must not reuse a slot whose previous frame is still executing. Errors when there are more
  // than kMaxProxies spheres.
  Status write_slot(std::uint32_t slot, const FrameView& view, std::span<const render::Sphere> spheres);

  // Records steps 2–8 for the frame written in `slot`, drawing `draws` into the G-buffer, and
  // copies the results into the slot's readback buffers.
  void record(VkCommandBuffer commands, std::uint32_t slot, std::span<const DrawItem> draws) const;
  // Records one pass (gbuffer .. upsample_composite) followed by a memory barrier; the passes in order
  // equal record() without the readback copies. The benchmark submits them one by one to time
  // each with the CPU clock (lavapipe's timestamps are unreliable, rendering-notes §4.2).
  void record_pass(VkCommandBuffer commands, std::uint32_t slot, FramePass pass, std::span<const DrawItem> draws) const;

  const FrameSettings& settings() const { return settings_; }
  std::uint32_t slot_count() const { return static_cast<std::uint32_t>(slots_.size()); }

  // The finished frame of `slot` (copied at the end of record(); valid once that submission
  // completed, until the slot is recorded again): RGBA8 sRGB and linear radiance.
  std::span<const std::uint8_t> slot_ldr(std::uint32_t slot) const;
  image::ImageF slot_hdr(std::uint32_t slot) const;

  // Readback of the last recorded frame's intermediate results (after its submit completed).
  // "Receiver res" is the receiver image of FrameSettings::receiver_width/height: for the vertex
  // method, receiver i is vertex i of the draws in order (groups of 64 per draw, the rest empty),
  // and the G-buffer's normal target holds the interpolated vertex irradiance instead.
  Result<std::vector<std::uint8_t>> read_ldr() const;   // RGBA8 sRGB, width × height
  Result<image::ImageF> read_hdr() const;                // linear radiance
  Result<image::ImageF> read_irradiance() const;         // display res, upsampled E
  Result<image::ImageF> read_direct() const;             // receiver res: rgb E_direct, a (O_p)_0
  Result<image::ImageF> read_indirect() const;           // receiver res: rgb E_indirect, a ω_p
  Result<image::ImageF> read_receiver_positions() const; // receiver res: xyz p, a eye depth
  Result<image::ImageF> read_receiver_normals() const;
  Result<std::vector<float>> read_log_occlusion() const; // receiver res × n²
  Result<image::ImageF> read_shaded() const;             // receiver res: rgb E_dir + E_ind, a depth
  // G-buffer (display res): xyz world position, a eye depth (0 = background); xyz normal.
  Result<image::ImageF> read_gbuffer_positions() const;
  Result<image::ImageF> read_gbuffer_normals() const;
  Result<image::ImageF> read_gbuffer_albedo() const;

 private:
  SoftGiFrame(Context& context) : context_(context) {}
  Result<image::ImageF> read_vec4_buffer(const Buffer& buffer, std::uint32_t width, std::uint32_t height) const;
  Result<image::ImageF> read_gbuffer_image(const Image& image) const;
  Result<image::ImageF> read_receiver_field(bool normals) const;
  // The baselines' passes (src/gpu/baseline_passes.cpp).
  void record_vertex_receivers(VkCommandBuffer commands, std::span<const DrawItem> draws) const;

  struct Slot {
    Buffer constants;     // FrameConstants, host-visible uniform
    Buffer proxies;       // ProxySphere[kMaxProxies], host-visible uniform
    Buffer ldr_readback;  // host-visible copies of the slot's finished frame
    Buffer hdr_readback;
    std::uint32_t proxy_count = 0;  // instances of the raster splat
  };

  void record_ambient_occlusion(VkCommandBuffer commands, const Slot& slot) const;
  // The G-buffer pass (src/gpu/gbuffer_pass.cpp).
  void record_gbuffer(VkCommandBuffer commands, const Slot& slot, std::span<const DrawItem> draws) const;

  Context& context_;
  FrameSettings settings_;
  int order_ = 4;
  FramePipelines pipelines_;
  std::unique_ptr<ShadowSplatPass> shadow_splat_;  // only with SplatMethod::raster
  Image position_depth_, normal_, albedo_, depth_;
  Buffer receivers_, log_occlusion_, direct_, indirect_, shaded_, irradiance_, hdr_, ldr_;
  Buffer log_table_, visibility_table_, optimal_linear_, lighting_cube_, environment_;
  Buffer exact_indirect_table_;  // M(s) rows of render::FrameTables::exact_indirect
  std::uint32_t environment_width_ = 0, environment_height_ = 0;
  std::vector<Slot> slots_;
  float log_table_rows_ = 0, visibility_rows_ = 0, optimal_linear_rows_ = 0, optimal_linear_max_ = 0, cube_size_ = 0;
  float eta_shadow_ = 15.0f, eta_indirect_ = 10.0f;
  std::array<std::array<float, 9>, 3> irradiance_order3_{};
};

}  // namespace proxygi::gpu
