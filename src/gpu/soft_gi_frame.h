#pragma once
// SoftGiFrame: the GPU half of one proxygi frame (DESIGN.md "One frame, as data", steps 2–9; step
// 1, skinning, is gpu::SkinPass, recorded by the caller first). It owns the frame's targets, the
// uploaded tables (render::FrameTables), the pass objects (frame_passes.h) and a ring of
// per-frame upload slots, so the CPU writes frame t+1's constants and proxies while the GPU still
// renders frame t. Settings change in place: apply() rebuilds only what the change needs.
//
//   auto frame = SoftGiFrame::create(context, config, tables, environment_image);
//   frame->write_slot(slot, view, spheres);          // host writes, no GPU wait
//   in_flight.submit([&](VkCommandBuffer c) { frame->record(c, slot, draws, FrameOutput::readback()); });
//   frame->slot_ldr(slot) / slot_hdr(slot) / read_direct() ...
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

#include "base/result.h"
#include "gpu/draw_item.h"
#include "gpu/frame_config.h"
#include "gpu/pass_timestamps.h"
#include "gpu/frame_output.h"
#include "gpu/frame_pass_set.h"
#include "gpu/resources.h"
#include "image/image.h"
#include "render/frame_tables.h"
#include "render/shading.h"
#include "scene/camera.h"

namespace proxygi::gpu_layout {
struct VsglLight;
}
namespace proxygi::prt {
struct StaticTransferField;
struct VisibilityGrid;
}

namespace proxygi::gpu {

class Context;

// Where the frame looks from. World space, meters; projection is Vulkan clip space (depth 0..1,
// framebuffer y down) as src/scene/camera.h builds it.
struct FrameView {
  glm::mat4 view{1.0f};
  glm::mat4 projection{1.0f};
  glm::vec3 eye{0.0f};
  glm::vec3 forward{0.0f, 0.0f, -1.0f};  // unit image-plane normal
  std::uint32_t debug_view = 0;           // gpu_layout::kDebugView* (the viewer's views); 0: final
};
// The view of a scene camera at aspect width / height (debug_view 0).
FrameView frame_view(const scene::CameraState& camera, float aspect);

class SoftGiFrame {
 public:
  // tables: built for config.render (render::make_frame_tables); environment: the
  // equirectangular radiance shown behind the scene (sh/environment.h layout).
  static Result<std::unique_ptr<SoftGiFrame>> create(Context& context, const FrameConfig& config,
                                                     const render::FrameTables& tables,
                                                     const image::ImageF& environment);

  // Changes the settings and sizes in place, rebuilding only what settings::classify_change (and
  // a size change) needs: pipelines, targets, tables (from `tables`, which must be built for
  // config.render when the table settings changed) or nothing but the constants written by the
  // next write_slot. No frame may be in flight. The result equals a frame created with `config`.
  Status apply(const FrameConfig& config, const render::FrameTables& tables);

  // Writes slot `slot`'s frame constants and proxies (host-visible, no GPU wait). The caller
  // must not reuse a slot whose previous frame is still executing. Errors when there are more
  // than kMaxProxies spheres.
  Status write_slot(std::uint32_t slot, const FrameView& view, std::span<const render::Sphere> spheres);

  // Makes what `output` needs (an RGBA8 staging image of the frame's encoding). Fails for an
  // image format it cannot write (see frame_output.h). Call before record() with that output.
  Status prepare_output(const FrameOutput& output);

  // Records steps 2–8 for the frame written in `slot`, drawing `draws` into the G-buffer, then
  // step 9 into `output` (the slot's readback buffers, or a caller's image). With `timestamps`,
  // a GPU timestamp after the i-th pass of frame_pass_order (index first_timestamp + i).
  void record(VkCommandBuffer commands, std::uint32_t slot, std::span<const DrawItem> draws,
              const FrameOutput& output, const TimestampQueries* timestamps = nullptr,
              std::uint32_t first_timestamp = 0) const;
  // Records one pass (gbuffer .. upsample_composite) with the barriers it needs against the
  // passes recorded before it in the same command buffer (`barriers`); the passes in
  // frame_pass_order equal record() without the output. The benchmark submits them one by one to
  // time each with the CPU clock (lavapipe's timestamps are unreliable, rendering-notes §4.2).
  // `output` decides which float targets upsample_composite writes (FrameOutput::float_targets).
  void record_pass(VkCommandBuffer commands, std::uint32_t slot, FramePass pass, std::span<const DrawItem> draws,
                   PassBarriers& barriers, const FrameOutput& output = FrameOutput::readback()) const;

  const FrameConfig& config() const { return config_; }
  float shadow_eta() const { return tables_.shadow_eta; }  // in use (resolved when the setting is auto)
  const settings::RenderSettings& settings() const { return config_.render; }
  std::uint32_t slot_count() const { return static_cast<std::uint32_t>(slots_.size()); }

  // The finished frame of `slot` (copied by a readback output; valid once that submission
  // completed, until the slot is recorded again): RGBA8 sRGB and linear radiance.
  std::span<const std::uint8_t> slot_ldr(std::uint32_t slot) const;
  image::ImageF slot_hdr(std::uint32_t slot) const;

  // Readback of the last recorded frame's intermediate results (after its submit completed).
  // "Shading res" is FrameConfig::shading_width/height (the display res unless antialiasing
  // supersamples); "receiver res" is the receiver image of FrameConfig::receiver_width/height: for the vertex
  // method, receiver i is vertex i of the draws in order (groups of 64 per draw, the rest empty),
  // and the G-buffer's normal target holds the interpolated vertex irradiance instead.
  Result<std::vector<std::uint8_t>> read_ldr() const;   // RGBA8 sRGB, width × height
  // read_hdr and read_irradiance fail when the last frame was recorded without them
  // (FrameOutput::float_targets false; the HDR is kept when read back).
  Result<image::ImageF> read_hdr() const;                // linear radiance, display res
  Result<image::ImageF> read_irradiance() const;         // shading res, upsampled E
  Result<image::ImageF> read_direct() const;             // receiver res: rgb E_direct, a (O_p)_0
  Result<image::ImageF> read_indirect() const;           // receiver res: rgb E_indirect, a ω_p
  Result<image::ImageF> read_receiver_positions() const; // receiver res: xyz p, a eye depth
  Result<image::ImageF> read_receiver_normals() const;
  Result<std::vector<float>> read_log_occlusion() const; // receiver res × n²
  Result<image::ImageF> read_shaded() const;             // receiver res: rgb E_dir + E_ind, a depth
  // Proxies kept by each 8×8-receiver tile's culling (gather or AO; row-major, tiles_x() a row).
  Result<std::vector<std::uint32_t>> read_tile_counts() const;
  std::uint32_t tiles_x() const;
  std::uint32_t tiles_y() const;
  // The VSGL lights of the last frame (indirect_method vsgl; gpu_layout::VsglLight each), count first.
  Result<std::vector<gpu_layout::VsglLight>> read_vsgl_lights() const;

  // The static receivers' PRT the static-transfer variants read (render.static_transfer ratio,
  // l1): `field` packed into the layouts.h buffers with `records` (prt::bake_static_records for
  // the frame's lighting, one prt::static_record_floats(order) each; order = the frame's SH order).
  // nullptr: no static receivers (an empty grid). `visibility` (prt/visibility_grid.h, the
  // frame's order; nullptr: none) shades the other receivers inside it. No frame may be in
  // flight. Until it is called the frame has none.
  Status set_static_transfer(const prt::StaticTransferField* field, std::span<const float> records,
                             const prt::VisibilityGrid* visibility);
  std::size_t static_transfer_bytes() const;  // GPU memory of those buffers
  // G-buffer (shading res): xyz world position, a eye depth (0 = background); xyz normal.
  Result<image::ImageF> read_gbuffer_positions() const;
  Result<image::ImageF> read_gbuffer_normals() const;
  Result<image::ImageF> read_gbuffer_albedo() const;

  // The target buffers by name ("receivers", "shaded", ...), empty ones (unused by this
  // configuration) included; `texels`: upsample_composite.comp reads it through a texel view, and
  // only those have VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT (frame_resources.cpp keeps the list).
  struct TargetBufferInfo {
    std::string_view name;
    const Buffer* buffer = nullptr;
    bool texels = false;
  };
  std::vector<TargetBufferInfo> target_buffers() const;

  // The frame's targets and tables (src/gpu/frame_resources.cpp).
  struct Targets {
    Image position_depth, normal, albedo, depth;
    Buffer receivers, log_occlusion, direct, indirect, shaded, irradiance, hdr, ldr;  // hdr, ldr: display size
    Buffer sample_hdr, sample_ldr;  // antialiasing ssaa*: the composite's samples (shading size), else empty
    Buffer tile_counts;  // uint per 8×8-receiver tile (tile_count()), the shadow pass's list lengths
    Buffer vsgl_partials, vsgl_lights;  // VsglLightsPass outputs (small: allocated for every method)
    Image rsm_position, rsm_normal, rsm_flux, rsm_depth;  // RsmPass outputs (kRsmSize², every method)
  };
  struct StaticTransfer {
    Buffer positions, triangles, grid, records, visibility;  // layouts.h kExponentiateBindStatic*
  };
  struct Tables {
    Buffer log_table, visibility_table, optimal_linear, lighting_cube, exact_indirect, sender_light;
    float log_table_rows = 0, visibility_rows = 0, optimal_linear_rows = 0, optimal_linear_max = 0, cube_size = 0;
    float shadow_eta = 0;  // render::FrameTables::shadow_eta (resolved when the setting is auto)
    std::array<std::array<float, 9>, 3> irradiance_order3{};
    std::array<std::array<float, 9>, 3> vsgl_sender_order3{};
    bool vsgl_sun = false;  // render::FrameTables::vsgl_sun
    glm::vec3 sun_direction{0.0f, 1.0f, 0.0f}, sun_irradiance{0.0f};
  };

 private:
  explicit SoftGiFrame(Context& context) : context_(context) {}
  Status build_targets();
  Status build_slots();
  Status upload_tables(const render::FrameTables& tables);
  Result<image::ImageF> read_vec4_buffer(const Buffer& buffer, std::uint32_t width, std::uint32_t height) const;
  Result<image::ImageF> read_gbuffer_image(const Image& image) const;
  Result<image::ImageF> read_receiver_field(bool normals) const;
  void record_output(VkCommandBuffer commands, std::uint32_t slot, const FrameOutput& output) const;

  struct Slot {
    Buffer constants;     // FrameConstants, host-visible uniform
    Buffer proxies;       // ProxySphere[kMaxProxies], host-visible uniform
    Buffer ldr_readback;  // host-visible copies of the slot's finished frame
    Buffer hdr_readback;
    std::uint32_t proxy_count = 0;  // instances of the raster splat
    bool rsm = false;               // the sun map is drawn (render.vsgl_sun on, senders' proxies bound it)
    bool debug_view = false;        // FrameView::debug_view is a view, not the final frame
  };

  Context& context_;
  FrameConfig config_;
  FramePassSet passes_;
  Targets targets_;
  Tables tables_;
  StaticTransfer static_;
  Buffer environment_;
  std::uint32_t environment_width_ = 0, environment_height_ = 0;
  std::vector<Slot> slots_;
  // Image outputs (prepare_output): the 8-bit frame is composited in the image's channel order,
  // so one raw copy lands it at the frame's size; other sizes go through `output_staging_` (the
  // image's format, the frame's size) and a linear blit.
  bool ldr_bgra_ = false;
  Image output_staging_;
  // What the last recorded upsample_composite wrote (read_hdr, read_irradiance check it).
  mutable bool hdr_written_ = true, irradiance_written_ = true;
};

}  // namespace proxygi::gpu
