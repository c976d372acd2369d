#include "gpu/soft_gi_frame.h"

#include <cstring>
#include <limits>

#include "gpu/context.h"
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

Result<Buffer> storage(Context& context, VkDeviceSize bytes) {
  return Buffer::create(context, bytes, kStorage, MemoryKind::device_local);
}

std::vector<glm::vec4> to_vec4(std::span<const glm::vec3> values, float w) {
  std::vector<glm::vec4> out;
  out.reserve(values.size());
  for (const auto& value : values) out.emplace_back(value, w);
  return out;
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
  auto i = create_buffer_with_data(context, bytes_of(indices), VK_BUFFER_USAGE_INDEX_BUFFER_BIT);
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

Result<std::unique_ptr<SoftGiFrame>> SoftGiFrame::create(Context& context, const FrameSettings& settings,
                                                         const render::FrameTables& tables,
                                                         const image::ImageF& environment) {
  if (settings.width < 1 || settings.height < 1) return make_error("frame: empty output size");
  if (settings.receiver_scale != 1 && settings.receiver_scale != 2 && settings.receiver_scale != 4 &&
      settings.receiver_scale != 8)
    return make_error("frame: receiver scale " + std::to_string(settings.receiver_scale) + " is not 1, 2, 4 or 8");
  if (environment.width < 1 || environment.height < 1) return make_error("frame: empty environment image");
  std::unique_ptr<SoftGiFrame> frame(new SoftGiFrame(context));
  frame->settings_ = settings;
  frame->order_ = tables.settings.order;
  auto pipelines = FramePipelines::create(context, frame->order_, settings.indirect_operator, settings.method);
  if (!pipelines) return pipelines.error();
  frame->pipelines_ = std::move(*pipelines);
  if (settings.splat == SplatMethod::raster && settings.method == ShadingMethod::image_space) {
    auto splat = ShadowSplatPass::create(context, frame->order_, settings.width, settings.height,
                                         settings.receiver_scale);
    if (!splat) return splat.error();
    frame->shadow_splat_ = std::move(*splat);
  }

  const VkImageUsageFlags target_usage =
      VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
  for (Image* image : {&frame->position_depth_, &frame->normal_, &frame->albedo_}) {
    auto made = Image::create(context, settings.width, settings.height, kGbufferFormat, target_usage);
    if (!made) return made.error();
    *image = std::move(*made);
  }
  auto depth = Image::create(context, settings.width, settings.height, kDepthFormat,
                             VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT);
  if (!depth) return depth.error();
  frame->depth_ = std::move(*depth);

  const VkDeviceSize receivers = VkDeviceSize(settings.receiver_width()) * settings.receiver_height();
  const VkDeviceSize pixels = VkDeviceSize(settings.width) * settings.height;
  const VkDeviceSize coefficients = VkDeviceSize(frame->order_) * VkDeviceSize(frame->order_);
  struct Target {
    Buffer* buffer;
    VkDeviceSize bytes;
  };
  const Target targets[] = {
      {&frame->receivers_, receivers * sizeof(gpu_layout::Receiver)},
      {&frame->log_occlusion_, receivers * coefficients * sizeof(float)},
      {&frame->direct_, receivers * sizeof(glm::vec4)},
      {&frame->indirect_, receivers * sizeof(glm::vec4)},
      {&frame->shaded_, receivers * sizeof(glm::vec4)},
      {&frame->irradiance_, pixels * sizeof(glm::vec4)},
      {&frame->hdr_, pixels * sizeof(glm::vec4)},
      {&frame->ldr_, pixels * sizeof(std::uint32_t)},
  };
  for (const auto& target : targets) {
    auto made = storage(context, target.bytes);
    if (!made) return made.error();
    *target.buffer = std::move(*made);
  }

  // Tables.
  std::vector<glm::vec2> optimal_linear;
  for (int row = 0; row < tables.optimal_linear.rows(); ++row)
    optimal_linear.emplace_back(tables.optimal_linear.a[std::size_t(row)], tables.optimal_linear.b[std::size_t(row)]);
  std::vector<float> cubes;
  for (const auto& cube : tables.lighting_cube) cubes.insert(cubes.end(), cube.values.begin(), cube.values.end());
  struct TableUpload {
    Buffer* buffer;
    std::span<const std::uint8_t> bytes;
  };
  const TableUpload uploads[] = {
      {&frame->log_table_, bytes_of(std::span<const float>(tables.log_occlusion.values))},
      {&frame->visibility_table_, bytes_of(std::span<const float>(tables.proxy_visibility.values))},
      {&frame->exact_indirect_table_, bytes_of(std::span<const float>(tables.exact_indirect.values))},
      {&frame->optimal_linear_, bytes_of(std::span<const glm::vec2>(optimal_linear))},
      {&frame->lighting_cube_, bytes_of(std::span<const float>(cubes))},
      {&frame->environment_, bytes_of(std::span<const glm::vec4>(environment.pixels))},
  };
  for (const auto& upload : uploads) {
    auto made = create_buffer_with_data(context, upload.bytes, kStorage);
    if (!made) return made.error();
    *upload.buffer = std::move(*made);
  }
  frame->environment_width_ = std::uint32_t(environment.width);
  frame->environment_height_ = std::uint32_t(environment.height);
  frame->log_table_rows_ = float(tables.log_occlusion.rows);
  frame->visibility_rows_ = float(tables.proxy_visibility.rows);
  frame->optimal_linear_rows_ = float(tables.optimal_linear.rows());
  frame->optimal_linear_max_ = tables.optimal_linear.max_norm;
  frame->cube_size_ = float(tables.lighting_cube[0].face_size);
  frame->eta_shadow_ = tables.settings.eta_shadow;
  frame->eta_indirect_ = tables.settings.eta_indirect;
  frame->irradiance_order3_ = tables.irradiance_order3;

  for (std::uint32_t i = 0; i < std::max(settings.frames_in_flight, 1u); ++i) {
    Slot slot;
    auto constants = Buffer::create(context, sizeof(gpu_layout::FrameConstants), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT,
                                    MemoryKind::host_visible);
    auto proxies = Buffer::create(context, sizeof(gpu_layout::ProxySphere) * gpu_layout::kMaxProxies,
                                  VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, MemoryKind::host_visible);
    if (!constants) return constants.error();
    if (!proxies) return proxies.error();
    slot.constants = std::move(*constants);
    slot.proxies = std::move(*proxies);
    auto ldr = Buffer::create(context, pixels * sizeof(std::uint32_t), VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                              MemoryKind::host_visible);
    auto hdr =
        Buffer::create(context, pixels * sizeof(glm::vec4), VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryKind::host_visible);
    if (!ldr) return ldr.error();
    if (!hdr) return hdr.error();
    slot.ldr_readback = std::move(*ldr);
    slot.hdr_readback = std::move(*hdr);
    frame->slots_.push_back(std::move(slot));
  }
  return frame;
}

Status SoftGiFrame::write_slot(std::uint32_t slot, const FrameView& view, std::span<const render::Sphere> spheres) {
  if (slot >= slots_.size()) return make_error("frame: slot " + std::to_string(slot) + " out of range");
  if (spheres.size() > gpu_layout::kMaxProxies)
    return make_error("frame: " + std::to_string(spheres.size()) + " proxies, at most " +
                      std::to_string(gpu_layout::kMaxProxies) + " per frame");
  gpu_layout::FrameConstants constants{};
  constants.view_projection = view.projection * view.view;
  constants.inverse_view_projection = glm::inverse(constants.view_projection);
  constants.eye_position = glm::vec4(view.eye, 1.0f);
  constants.eye_forward = glm::vec4(glm::normalize(view.forward), 0.0f);
  constants.sizes =
      glm::uvec4(settings_.width, settings_.height, settings_.receiver_width(), settings_.receiver_height());
  const std::uint32_t composite = settings_.method == ShadingMethod::vertex ? gpu_layout::kCompositeDisplayIrradiance
                                                                             : std::uint32_t(settings_.upsample);
  constants.counts =
      glm::uvec4(std::uint32_t(spheres.size()), settings_.receiver_scale, std::uint32_t(order_), composite);
  const float tau = settings_.optimal_linear_only ? std::numeric_limits<float>::max() : settings_.hybrid_tau;
  constants.shadow = glm::vec4(eta_shadow_, eta_indirect_, tau, log_table_rows_);
  constants.tables = glm::vec4(optimal_linear_max_, optimal_linear_rows_, visibility_rows_, cube_size_);
  constants.output_params = glm::vec4(settings_.exposure, float(int(settings_.tonemap)),
                                      settings_.bilateral_depth_epsilon, settings_.indirect ? 1.0f : 0.0f);
  for (int channel = 0; channel < 3; ++channel)
    for (int i = 0; i < 9; ++i)
      constants.irradiance_sh[channel * 9 + i] =
          glm::vec4(irradiance_order3_[std::size_t(channel)][std::size_t(i)], 0, 0, 0);
  std::memcpy(slots_[slot].constants.mapped(), &constants, sizeof(constants));

  slots_[slot].proxy_count = std::uint32_t(spheres.size());
  auto* proxies = static_cast<gpu_layout::ProxySphere*>(slots_[slot].proxies.mapped());
  for (std::size_t i = 0; i < spheres.size(); ++i) {
    proxies[i].center_radius = glm::vec4(spheres[i].center, spheres[i].radius);
    proxies[i].albedo = glm::vec4(spheres[i].albedo, 1.0f);
  }
  return {};
}

void SoftGiFrame::record_pass(VkCommandBuffer commands, std::uint32_t slot, FramePass pass,
                              std::span<const DrawItem> draws) const {
  const Slot& current = slots_[slot];
  const std::uint32_t width = settings_.width, height = settings_.height;
  const std::uint32_t receiver_width = settings_.receiver_width(), receiver_height = settings_.receiver_height();
  auto dispatch_2d = [&](std::uint32_t w, std::uint32_t h) {
    vkCmdDispatch(commands, group_count(w, gpu_layout::kFrameLocalSize), group_count(h, gpu_layout::kFrameLocalSize),
                  1);
  };

  switch (pass) {
    case FramePass::gbuffer:
      record_gbuffer(commands, current, draws);
      break;
    case FramePass::receivers: {
      if (settings_.method == ShadingMethod::vertex) {
        record_vertex_receivers(commands, draws);
        break;
      }
      context_.begin_label(commands, frame_pass_name(FramePass::receivers));
      pipelines_.receivers.bind(commands);
      DescriptorPush()
          .uniform_buffer(0, current.constants)
          .storage_image(1, position_depth_.view())
          .storage_image(2, normal_.view())
          .storage_buffer(3, receivers_)
          .push(context_, commands, pipelines_.receivers);
      dispatch_2d(receiver_width, receiver_height);
      memory_barrier(commands);
      context_.end_label(commands);
      break;
    }
    case FramePass::shadow: {
      if (settings_.method == ShadingMethod::ambient_occlusion) {
        record_ambient_occlusion(commands, current);
        break;
      }
      context_.begin_label(commands, frame_pass_name(FramePass::shadow));
      if (shadow_splat_) {
        shadow_splat_->record(commands, {&current.constants, &receivers_, &current.proxies, current.proxy_count,
                                         &log_table_, &log_occlusion_});
        context_.end_label(commands);
        break;
      }
      pipelines_.shadow.bind(commands);
      DescriptorPush()
          .uniform_buffer(0, current.constants)
          .storage_buffer(1, receivers_)
          .uniform_buffer(2, current.proxies)
          .storage_buffer(3, log_table_)
          .storage_buffer(4, log_occlusion_)
          .push(context_, commands, pipelines_.shadow);
      dispatch_2d(receiver_width, receiver_height);
      memory_barrier(commands);
      context_.end_label(commands);
      break;
    }
    case FramePass::exponentiate: {
      context_.begin_label(commands, frame_pass_name(FramePass::exponentiate));
      pipelines_.exponentiate.bind(commands);
      DescriptorPush()
          .uniform_buffer(0, current.constants)
          .storage_buffer(1, receivers_)
          .storage_buffer(2, log_occlusion_)
          .storage_buffer(3, optimal_linear_)
          .storage_buffer(4, lighting_cube_)
          .storage_buffer(5, direct_)
          .push(context_, commands, pipelines_.exponentiate);
      dispatch_2d(receiver_width, receiver_height);
      memory_barrier(commands);
      context_.end_label(commands);
      break;
    }
    case FramePass::indirect: {
      context_.begin_label(commands, frame_pass_name(FramePass::indirect));
      pipelines_.indirect.bind(commands);
      DescriptorPush()
          .uniform_buffer(0, current.constants)
          .storage_buffer(1, receivers_)
          .uniform_buffer(2, current.proxies)
          .storage_buffer(3, visibility_table_)
          .storage_buffer(4, direct_)
          .storage_buffer(5, indirect_)
          .storage_buffer(6, shaded_)
          .storage_buffer(7, exact_indirect_table_)  // read by the exact variant only
          .push(context_, commands, pipelines_.indirect);
      dispatch_2d(receiver_width, receiver_height);
      memory_barrier(commands);
      context_.end_label(commands);
      break;
    }
    case FramePass::upsample_composite: {
      context_.begin_label(commands, frame_pass_name(FramePass::upsample_composite));
      pipelines_.upsample_composite.bind(commands);
      DescriptorPush()
          .uniform_buffer(0, current.constants)
          .storage_image(1, position_depth_.view())
          .storage_image(2, normal_.view())
          .storage_buffer(3, receivers_)
          .storage_buffer(4, shaded_)
          .storage_buffer(5, irradiance_)
          .storage_image(6, albedo_.view())
          .storage_buffer(7, environment_)
          .storage_buffer(8, hdr_)
          .storage_buffer(9, ldr_)
          .push(context_, commands, pipelines_.upsample_composite);
      const gpu_layout::CompositePush composite{environment_width_, environment_height_, 0, 0};
      pipelines_.upsample_composite.push_constants(commands, &composite, sizeof(composite));
      dispatch_2d(width, height);
      memory_barrier(commands);
      context_.end_label(commands);
      break;
    }
    case FramePass::skin:
    case FramePass::count:
      break;
  }
}

void SoftGiFrame::record(VkCommandBuffer commands, std::uint32_t slot, std::span<const DrawItem> draws) const {
  memory_barrier(commands);  // the previous frame on the queue may still read these targets
  for (FramePass pass : frame_pass_order(settings_.method)) record_pass(commands, slot, pass, draws);
  const Slot& current = slots_[slot];
  const VkBufferCopy ldr_copy{0, 0, ldr_.size()}, hdr_copy{0, 0, hdr_.size()};
  vkCmdCopyBuffer(commands, ldr_.handle(), current.ldr_readback.handle(), 1, &ldr_copy);
  vkCmdCopyBuffer(commands, hdr_.handle(), current.hdr_readback.handle(), 1, &hdr_copy);
  VkMemoryBarrier2 to_host{VK_STRUCTURE_TYPE_MEMORY_BARRIER_2};
  to_host.srcStageMask = VK_PIPELINE_STAGE_2_COPY_BIT;
  to_host.srcAccessMask = VK_ACCESS_2_TRANSFER_WRITE_BIT;
  to_host.dstStageMask = VK_PIPELINE_STAGE_2_HOST_BIT;
  to_host.dstAccessMask = VK_ACCESS_2_HOST_READ_BIT;
  VkDependencyInfo dependency{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
  dependency.memoryBarrierCount = 1;
  dependency.pMemoryBarriers = &to_host;
  vkCmdPipelineBarrier2(commands, &dependency);
}

std::span<const std::uint8_t> SoftGiFrame::slot_ldr(std::uint32_t slot) const {
  const Buffer& buffer = slots_[slot].ldr_readback;
  return {static_cast<const std::uint8_t*>(buffer.mapped()), std::size_t(buffer.size())};
}

image::ImageF SoftGiFrame::slot_hdr(std::uint32_t slot) const {
  image::ImageF out{int(settings_.width), int(settings_.height)};
  std::memcpy(out.pixels.data(), slots_[slot].hdr_readback.mapped(), out.pixels.size() * sizeof(glm::vec4));
  return out;
}

Result<image::ImageF> SoftGiFrame::read_vec4_buffer(const Buffer& buffer, std::uint32_t width,
                                                    std::uint32_t height) const {
  auto bytes = readback(context_, buffer);
  if (!bytes) return bytes.error();
  image::ImageF out{int(width), int(height)};
  std::memcpy(out.pixels.data(), bytes->data(), std::min(bytes->size(), out.pixels.size() * sizeof(glm::vec4)));
  return out;
}

Result<std::vector<std::uint8_t>> SoftGiFrame::read_ldr() const { return readback(context_, ldr_); }
Result<image::ImageF> SoftGiFrame::read_hdr() const {
  return read_vec4_buffer(hdr_, settings_.width, settings_.height);
}
Result<image::ImageF> SoftGiFrame::read_irradiance() const {
  return read_vec4_buffer(irradiance_, settings_.width, settings_.height);
}
Result<image::ImageF> SoftGiFrame::read_direct() const {
  return read_vec4_buffer(direct_, settings_.receiver_width(), settings_.receiver_height());
}
Result<image::ImageF> SoftGiFrame::read_indirect() const {
  return read_vec4_buffer(indirect_, settings_.receiver_width(), settings_.receiver_height());
}

Result<image::ImageF> SoftGiFrame::read_receiver_field(bool normals) const {
  auto bytes = readback(context_, receivers_);
  if (!bytes) return bytes.error();
  image::ImageF out{int(settings_.receiver_width()), int(settings_.receiver_height())};
  const auto* receivers = reinterpret_cast<const gpu_layout::Receiver*>(bytes->data());
  for (std::size_t i = 0; i < out.pixels.size(); ++i)
    out.pixels[i] = normals ? receivers[i].normal : receivers[i].position_depth;
  return out;
}
Result<image::ImageF> SoftGiFrame::read_receiver_positions() const { return read_receiver_field(false); }
Result<image::ImageF> SoftGiFrame::read_receiver_normals() const { return read_receiver_field(true); }

Result<image::ImageF> SoftGiFrame::read_shaded() const {
  return read_vec4_buffer(shaded_, settings_.receiver_width(), settings_.receiver_height());
}

Result<image::ImageF> SoftGiFrame::read_gbuffer_image(const Image& image) const {
  auto bytes = readback(context_, image, VK_IMAGE_LAYOUT_GENERAL);  // record() leaves them GENERAL
  if (!bytes) return bytes.error();
  image::ImageF out{int(settings_.width), int(settings_.height)};
  std::memcpy(out.pixels.data(), bytes->data(), std::min(bytes->size(), out.pixels.size() * sizeof(glm::vec4)));
  return out;
}
Result<image::ImageF> SoftGiFrame::read_gbuffer_positions() const { return read_gbuffer_image(position_depth_); }
Result<image::ImageF> SoftGiFrame::read_gbuffer_normals() const { return read_gbuffer_image(normal_); }
Result<image::ImageF> SoftGiFrame::read_gbuffer_albedo() const { return read_gbuffer_image(albedo_); }

Result<std::vector<float>> SoftGiFrame::read_log_occlusion() const {
  auto bytes = readback(context_, log_occlusion_);
  if (!bytes) return bytes.error();
  std::vector<float> values(bytes->size() / sizeof(float));
  std::memcpy(values.data(), bytes->data(), values.size() * sizeof(float));
  return values;
}

}  // namespace proxygi::gpu
