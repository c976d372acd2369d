#pragma once
// What one GPU frame is built for: the render settings (settings/render_settings.h, the one
// definition of every setting) and the sizes they are applied at. Not a second settings type:
// FrameConfig only adds what the frame's buffers are sized by.
#include <algorithm>
#include <cstdint>

#include "settings/render_settings.h"

namespace proxygi::gpu {

// Vertex receivers are laid out in groups of kVertexReceiverGroup consecutive receivers (each
// draw's first vertex starts a group), as a receiver "image" kVertexReceiverWidth wide: an 8×8
// compute tile is one group of 64 consecutive vertices, so tiled culling bounds one mesh patch.
inline constexpr std::uint32_t kVertexReceiverWidth = 8;
inline constexpr std::uint32_t kVertexReceiverGroup = 64;
inline constexpr std::uint32_t round_up_to_receiver_group(std::uint32_t vertices) {
  return (vertices + kVertexReceiverGroup - 1) / kVertexReceiverGroup * kVertexReceiverGroup;
}

struct FrameConfig {
  settings::RenderSettings render;
  std::uint32_t width = 512;  // display resolution, pixels
  std::uint32_t height = 512;
  std::uint32_t frames_in_flight = 2;  // ring-buffer slots for per-frame uploads
  // Vertex method: receiver capacity, Σ round_up_to_receiver_group(vertex count) over the draws.
  std::uint32_t vertex_receivers = 0;

  // Supersampling (render.antialiasing): every pass shades shading_width × shading_height, f× the
  // display per axis, and the resolve pass box-filters that down to width × height. f = 1: equal.
  std::uint32_t supersampling() const { return std::uint32_t(settings::supersampling_factor(render.antialiasing)); }
  std::uint32_t shading_width() const { return width * supersampling(); }
  std::uint32_t shading_height() const { return height * supersampling(); }

  // The receiver "image": shading size / k, or for the vertex method kVertexReceiverWidth × rows.
  std::uint32_t receiver_width() const {
    const auto k = std::uint32_t(render.receiver_scale);
    return render.method == settings::ShadingMethod::vertex ? kVertexReceiverWidth : (shading_width() + k - 1) / k;
  }
  std::uint32_t receiver_height() const {
    if (render.method == settings::ShadingMethod::vertex)
      return std::max(round_up_to_receiver_group(vertex_receivers), kVertexReceiverGroup) / kVertexReceiverWidth;
    const auto k = std::uint32_t(render.receiver_scale);
    return (shading_height() + k - 1) / k;
  }
  std::uint64_t receiver_count() const { return std::uint64_t(receiver_width()) * receiver_height(); }
  bool operator==(const FrameConfig&) const = default;
};

}  // namespace proxygi::gpu
