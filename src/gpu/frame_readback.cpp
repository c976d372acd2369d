// SoftGiFrame's readbacks of the last frame's targets (tests, AOVs): synchronous, after the
// frame's submission completed.
#include <cstring>

#include "gpu/soft_gi_frame.h"
#include "gpu/transfer.h"
#include "shaders/shared/layouts.h"

namespace proxygi::gpu {

Result<image::ImageF> SoftGiFrame::read_vec4_buffer(const Buffer& buffer, std::uint32_t width,
                                                    std::uint32_t height) const {
  auto bytes = readback(context_, buffer);
  if (!bytes) return bytes.error();
  image::ImageF out{int(width), int(height)};
  std::memcpy(out.pixels.data(), bytes->data(), std::min(bytes->size(), out.pixels.size() * sizeof(glm::vec4)));
  return out;
}

Result<std::vector<std::uint8_t>> SoftGiFrame::read_ldr() const { return readback(context_, targets_.ldr); }
Result<image::ImageF> SoftGiFrame::read_hdr() const {
  if (!hdr_written_)
    return make_error("read_hdr: the last frame was recorded without its HDR (FrameOutput::float_targets off, "
                      "no HDR readback)");
  return read_vec4_buffer(targets_.hdr, config_.width, config_.height);
}
Result<image::ImageF> SoftGiFrame::read_irradiance() const {
  if (!irradiance_written_)
    return make_error("read_irradiance: the last frame was recorded without the irradiance AOV "
                      "(FrameOutput::float_targets off)");
  return read_vec4_buffer(targets_.irradiance, config_.shading_width(), config_.shading_height());
}
Result<image::ImageF> SoftGiFrame::read_direct() const {
  return read_vec4_buffer(targets_.direct, config_.receiver_width(), config_.receiver_height());
}
Result<image::ImageF> SoftGiFrame::read_indirect() const {
  return read_vec4_buffer(targets_.indirect, config_.receiver_width(), config_.receiver_height());
}
Result<image::ImageF> SoftGiFrame::read_shaded() const {
  return read_vec4_buffer(targets_.shaded, config_.receiver_width(), config_.receiver_height());
}

std::uint32_t SoftGiFrame::tiles_x() const {
  return (config_.receiver_width() + gpu_layout::kFrameLocalSize - 1) / gpu_layout::kFrameLocalSize;
}
std::uint32_t SoftGiFrame::tiles_y() const {
  return (config_.receiver_height() + gpu_layout::kFrameLocalSize - 1) / gpu_layout::kFrameLocalSize;
}
Result<std::vector<std::uint32_t>> SoftGiFrame::read_tile_counts() const {
  auto bytes = readback(context_, targets_.tile_counts);
  if (!bytes) return bytes.error();
  std::vector<std::uint32_t> counts(std::size_t(tiles_x()) * tiles_y());
  std::memcpy(counts.data(), bytes->data(), std::min(bytes->size(), counts.size() * sizeof(std::uint32_t)));
  return counts;
}

Result<std::vector<gpu_layout::VsglLight>> SoftGiFrame::read_vsgl_lights() const {
  auto bytes = readback(context_, targets_.vsgl_lights);
  if (!bytes) return bytes.error();
  glm::uvec4 header;
  std::memcpy(&header, bytes->data(), sizeof(header));
  const std::size_t count = std::min<std::size_t>(header.x, gpu_layout::kVsglMaxLights);
  std::vector<gpu_layout::VsglLight> lights(count);
  std::memcpy(lights.data(), bytes->data() + sizeof(header), count * sizeof(gpu_layout::VsglLight));
  return lights;
}

Result<image::ImageF> SoftGiFrame::read_receiver_field(bool normals) const {
  auto bytes = readback(context_, targets_.receivers);
  if (!bytes) return bytes.error();
  image::ImageF out{int(config_.receiver_width()), int(config_.receiver_height())};
  const auto* receivers = reinterpret_cast<const gpu_layout::Receiver*>(bytes->data());
  for (std::size_t i = 0; i < out.pixels.size(); ++i)
    out.pixels[i] = normals ? receivers[i].normal : receivers[i].position_depth;
  return out;
}
Result<image::ImageF> SoftGiFrame::read_receiver_positions() const { return read_receiver_field(false); }
Result<image::ImageF> SoftGiFrame::read_receiver_normals() const { return read_receiver_field(true); }

Result<image::ImageF> SoftGiFrame::read_gbuffer_image(const Image& image) const {
  auto bytes = readback(context_, image, VK_IMAGE_LAYOUT_GENERAL);  // record() leaves them GENERAL
  if (!bytes) return bytes.error();
  image::ImageF out{int(config_.shading_width()), int(config_.shading_height())};
  std::memcpy(out.pixels.data(), bytes->data(), std::min(bytes->size(), out.pixels.size() * sizeof(glm::vec4)));
  return out;
}
Result<image::ImageF> SoftGiFrame::read_gbuffer_positions() const { return read_gbuffer_image(targets_.position_depth); }
Result<image::ImageF> SoftGiFrame::read_gbuffer_normals() const { return read_gbuffer_image(targets_.normal); }
Result<image::ImageF> SoftGiFrame::read_gbuffer_albedo() const { return read_gbuffer_image(targets_.albedo); }

Result<std::vector<float>> SoftGiFrame::read_log_occlusion() const {
  auto bytes = readback(context_, targets_.log_occlusion);
  if (!bytes) return bytes.error();
  std::vector<float> values(bytes->size() / sizeof(float));
  std::memcpy(values.data(), bytes->data(), values.size() * sizeof(float));
  return values;
}

}  // namespace proxygi::gpu
