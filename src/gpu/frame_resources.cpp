// SoftGiFrame's resources: the targets sized by the frame configuration, the ring slots, the
// uploaded tables, and static meshes.
#include <array>
#include <cstring>
#include <string_view>
#include <type_traits>

#include "gpu/context.h"
#include "gpu/soft_gi_frame.h"
#include "gpu/transfer.h"
#include "shaders/shared/layouts.h"

namespace proxygi::gpu {
namespace {

constexpr VkBufferUsageFlags kStorage =
    VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT;

template <class T>
std::span<const std::uint8_t> bytes_of(std::span<const T> values) {
  return {reinterpret_cast<const std::uint8_t*>(values.data()), values.size_bytes()};
}

std::vector<glm::vec4> to_vec4(std::span<const glm::vec3> values, float w) {
  std::vector<glm::vec4> out;
  out.reserve(values.size());
  for (const auto& value : values) out.emplace_back(value, w);
  return out;
}

// Every target buffer of `targets`: its name, its size for `config` (0: not used by it) and
// whether upsample_composite.comp reads it as texels (Buffer::add_texel_view says why: a Receiver
// is two RGBA32F texels, position_depth and normal). The one list of those: only they get
// uniform texel usage and a view. `TargetsT`: SoftGiFrame::Targets, const or not.
template <class TargetsT>
auto target_rows(TargetsT& targets, const FrameConfig& config, std::uint32_t tiles) {
  using BufferT = std::conditional_t<std::is_const_v<TargetsT>, const Buffer, Buffer>;
  struct Row {
    std::string_view name;
    BufferT* buffer;
    VkDeviceSize bytes;
    bool texels;
  };
  const VkDeviceSize receivers = config.receiver_count();
  const VkDeviceSize pixels = VkDeviceSize(config.width) * config.height;
  const VkDeviceSize samples = VkDeviceSize(config.shading_width()) * config.shading_height();
  const bool supersampled = config.supersampling() > 1;
  const VkDeviceSize coefficients = VkDeviceSize(config.render.sh_order) * VkDeviceSize(config.render.sh_order);
  return std::array{
      Row{"receivers", &targets.receivers, receivers * sizeof(gpu_layout::Receiver), true},
      Row{"log_occlusion", &targets.log_occlusion, receivers * coefficients * sizeof(float), false},
      Row{"direct", &targets.direct, receivers * sizeof(glm::vec4), false},
      Row{"indirect", &targets.indirect, receivers * sizeof(glm::vec4), false},
      Row{"shaded", &targets.shaded, receivers * sizeof(glm::vec4), true},
      Row{"irradiance", &targets.irradiance, samples * sizeof(glm::vec4), false},
      Row{"hdr", &targets.hdr, pixels * sizeof(glm::vec4), false},
      Row{"ldr", &targets.ldr, pixels * sizeof(std::uint32_t), false},
      Row{"sample_hdr", &targets.sample_hdr, supersampled ? samples * sizeof(glm::vec4) : 0, false},
      Row{"sample_ldr", &targets.sample_ldr, supersampled ? samples * sizeof(std::uint32_t) : 0, false},
      Row{"tile_counts", &targets.tile_counts, VkDeviceSize(tiles) * sizeof(std::uint32_t), false},
      Row{"vsgl_partials", &targets.vsgl_partials, VsglLightsPass::partials_bytes(), false},
      Row{"vsgl_lights", &targets.vsgl_lights, VsglLightsPass::lights_bytes(), false},
  };
}

}  // namespace

Result<StaticMesh> upload_static_mesh(Context& context, std::span<const glm::vec3> positions,
                                      std::span<const glm::vec3> normals, std::span<const std::uint32_t> indices,
                                      const glm::vec4& base_color, std::span<const glm::vec2> uvs,
                                      const BaseColorTexture& texture) {
  if (positions.empty() || indices.empty() || normals.size() != positions.size())
    return make_error("static mesh: needs positions, one normal per position and indices");
  if (!uvs.empty() && uvs.size() != positions.size()) return make_error("static mesh: uv count differs from positions");
  StaticMesh mesh;
  if (!uvs.empty()) {
    auto uploaded = create_buffer_with_data(context, bytes_of(uvs), kStorage);
    if (!uploaded) return uploaded.error();
    mesh.uvs = std::move(*uploaded);
  }
  const auto positions4 = to_vec4(positions, 1.0f);
  const auto normals4 = to_vec4(normals, 0.0f);
  auto p = create_buffer_with_data(context, bytes_of(std::span<const glm::vec4>(positions4)), kStorage);
  auto n = create_buffer_with_data(context, bytes_of(std::span<const glm::vec4>(normals4)), kStorage);
  // Storage too: the VSGL lights pass reads a sender's triangles (a test's static mesh can be one).
  auto i = create_buffer_with_data(context, bytes_of(indices),
                                   VK_BUFFER_USAGE_INDEX_BUFFER_BIT | VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
  if (!p) return p.error();
  if (!n) return n.error();
  if (!i) return i.error();
  mesh.positions = std::move(*p);
  mesh.normals = std::move(*n);
  mesh.indices = std::move(*i);
  mesh.index_count = static_cast<std::uint32_t>(indices.size());
  mesh.base_color = base_color;
  mesh.texture = texture;
  return mesh;
}

Status SoftGiFrame::build_targets() {
  const FrameConfig& config = config_;
  Targets targets;
  const VkImageUsageFlags target_usage =
      VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
  for (Image* image : {&targets.position_depth, &targets.normal, &targets.albedo}) {
    auto made = Image::create(context_, config.shading_width(), config.shading_height(), kGbufferFormat, target_usage);
    if (!made) return made.error();
    *image = std::move(*made);
  }
  auto depth = Image::create(context_, config.shading_width(), config.shading_height(), kDepthFormat,
                             VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT);
  if (!depth) return depth.error();
  targets.depth = std::move(*depth);
  for (Image* image : {&targets.rsm_position, &targets.rsm_normal, &targets.rsm_flux}) {
    auto made = Image::create(context_, gpu_layout::kRsmSize, gpu_layout::kRsmSize, kGbufferFormat, target_usage);
    if (!made) return made.error();
    *image = std::move(*made);
  }
  auto rsm_depth = Image::create(context_, gpu_layout::kRsmSize, gpu_layout::kRsmSize, kDepthFormat,
                                 VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT);
  if (!rsm_depth) return rsm_depth.error();
  targets.rsm_depth = std::move(*rsm_depth);

  for (const auto& target : target_rows(targets, config, tiles_x() * tiles_y())) {
    if (target.bytes == 0) continue;  // not used by this configuration
    const VkBufferUsageFlags usage = kStorage | (target.texels ? VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT : 0);
    auto made = Buffer::create(context_, target.bytes, usage, MemoryKind::device_local);
    if (!made) return made.error();
    *target.buffer = std::move(*made);
    if (target.texels)
      if (Status s = target.buffer->add_texel_view(context_, VK_FORMAT_R32G32B32A32_SFLOAT); !s) return s;
  }
  targets_ = std::move(targets);
  output_staging_ = Image();
  return {};
}

std::vector<SoftGiFrame::TargetBufferInfo> SoftGiFrame::target_buffers() const {
  std::vector<TargetBufferInfo> out;
  for (const auto& row : target_rows(targets_, config_, tiles_x() * tiles_y()))
    out.push_back({row.name, row.buffer, row.texels});
  return out;
}

Status SoftGiFrame::build_slots() {
  const VkDeviceSize pixels = VkDeviceSize(config_.width) * config_.height;
  std::vector<Slot> slots;
  for (std::uint32_t i = 0; i < std::max(config_.frames_in_flight, 1u); ++i) {
    Slot slot;
    auto constants = Buffer::create(context_, sizeof(gpu_layout::FrameConstants), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT,
                                    MemoryKind::host_visible);
    auto proxies = Buffer::create(context_, sizeof(gpu_layout::ProxySphere) * gpu_layout::kMaxProxies,
                                  VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, MemoryKind::host_visible);
    if (!constants) return constants.error();
    if (!proxies) return proxies.error();
    slot.constants = std::move(*constants);
    slot.proxies = std::move(*proxies);
    auto ldr = Buffer::create(context_, pixels * sizeof(std::uint32_t), VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                              MemoryKind::host_visible);
    auto hdr =
        Buffer::create(context_, pixels * sizeof(glm::vec4), VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryKind::host_visible);
    if (!ldr) return ldr.error();
    if (!hdr) return hdr.error();
    slot.ldr_readback = std::move(*ldr);
    slot.hdr_readback = std::move(*hdr);
    slots.push_back(std::move(slot));
  }
  slots_ = std::move(slots);
  return {};
}

Status SoftGiFrame::upload_tables(const render::FrameTables& tables) {
  if (tables.settings.sh_order != config_.render.sh_order || tables.settings.shadow_eta != config_.render.shadow_eta ||
      tables.settings.indirect_eta != config_.render.indirect_eta ||
      tables.settings.sh_window != config_.render.sh_window ||
      tables.settings.ground_bounce != config_.render.ground_bounce ||
      tables.settings.mask_sender_light != config_.render.mask_sender_light)
    return make_error("frame: tables built for other table settings than the frame's");
  std::vector<glm::vec2> optimal_linear;
  for (int row = 0; row < tables.optimal_linear.rows(); ++row)
    optimal_linear.emplace_back(tables.optimal_linear.a[std::size_t(row)], tables.optimal_linear.b[std::size_t(row)]);
  std::vector<float> cubes;
  for (const auto& cube : tables.lighting_cube) cubes.insert(cubes.end(), cube.values.begin(), cube.values.end());
  // The sender light as texels (indirect.comp reads texels in SIMD; a storage-buffer read is a
  // loop over the lanes on lavapipe): per cube texel, coefficient i's (r, g, b, 0) at texel * 9 + i.
  std::vector<glm::vec4> sender_texels;
  const std::size_t sender_values = tables.sender_light_cube[0].values.size();
  sender_texels.reserve(sender_values);
  for (std::size_t v = 0; v < sender_values; ++v)
    sender_texels.emplace_back(tables.sender_light_cube[0].values[v], tables.sender_light_cube[1].values[v],
                               tables.sender_light_cube[2].values[v], 0.0f);
  Tables uploaded;
  struct TableUpload {
    Buffer* buffer;
    std::span<const std::uint8_t> bytes;
  };
  const TableUpload uploads[] = {
      {&uploaded.log_table, bytes_of(std::span<const float>(tables.log_occlusion.values))},
      {&uploaded.visibility_table, bytes_of(std::span<const float>(tables.proxy_visibility.values))},
      {&uploaded.exact_indirect, bytes_of(std::span<const float>(tables.exact_indirect.values))},
      {&uploaded.optimal_linear, bytes_of(std::span<const glm::vec2>(optimal_linear))},
      {&uploaded.lighting_cube, bytes_of(std::span<const float>(cubes))},
  };
  for (const auto& upload : uploads) {
    auto made = create_buffer_with_data(context_, upload.bytes, kStorage);
    if (!made) return made.error();
    *upload.buffer = std::move(*made);
  }
  auto sender = create_buffer_with_data(context_, bytes_of(std::span<const glm::vec4>(sender_texels)),
                                        VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT);
  if (!sender) return sender.error();
  if (Status s = sender->add_texel_view(context_, VK_FORMAT_R32G32B32A32_SFLOAT); !s) return s;
  uploaded.sender_light = std::move(*sender);
  uploaded.log_table_rows = float(tables.log_occlusion.rows);
  uploaded.visibility_rows = float(tables.proxy_visibility.rows);
  uploaded.optimal_linear_rows = float(tables.optimal_linear.rows());
  uploaded.optimal_linear_max = tables.optimal_linear.max_norm;
  uploaded.cube_size = float(tables.lighting_cube[0].face_size);
  uploaded.shadow_eta = tables.shadow_eta;
  uploaded.irradiance_order3 = tables.irradiance_order3;
  uploaded.vsgl_sender_order3 = tables.vsgl_sender_order3;
  uploaded.vsgl_sun = tables.vsgl_sun;
  uploaded.sun_direction = tables.sun_direction;
  uploaded.sun_irradiance = tables.sun_irradiance;
  tables_ = std::move(uploaded);
  return {};
}

}  // namespace proxygi::gpu
