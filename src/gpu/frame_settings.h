#pragma once
// Settings of one soft-GI frame on the GPU (scene files map onto these; src/scene validates).
#include <algorithm>
#include <cstdint>

#include "render/shading.h"

namespace proxygi::gpu {

// What the frame computes per receiver (scene render.method):
//   image_space        the paper's method: receivers at 1/k of the display, SHEXP shadows and
//                      indirect light, bilateral upsampling
//   vertex             the prior-work baseline: the receivers are the mesh vertices (skinned
//                      characters, the tessellated ground, static meshes), shaded by the same
//                      passes and interpolated across triangles by the rasterizer
//   ambient_occlusion  scalar AO from the same spheres at the image-space receivers:
//                      E = Π_i (1 − a_i) · E(N), no bounce light (render::ambient_occlusion)
enum class ShadingMethod { image_space, vertex, ambient_occlusion };

// Vertex receivers are laid out in groups of kVertexReceiverGroup consecutive receivers (each
// draw's first vertex starts a group), as a receiver "image" kVertexReceiverWidth wide: an 8×8
// compute tile is one group of 64 consecutive vertices, so tiled culling bounds one mesh patch.
inline constexpr std::uint32_t kVertexReceiverWidth = 8;
inline constexpr std::uint32_t kVertexReceiverGroup = 64;
inline constexpr std::uint32_t round_up_to_receiver_group(std::uint32_t vertices) {
  return (vertices + kVertexReceiverGroup - 1) / kVertexReceiverGroup * kVertexReceiverGroup;
}

// How frame step 4 accumulates the proxies' log-occlusion vectors (same result either way):
// the tiled compute gather (shadow_gather.comp) or the paper's raster splat (ShadowSplatPass).
// The raster splat needs receivers on the image grid: ShadingMethod::image_space only (the vertex
// method always gathers; ambient_occlusion has no log-occlusion step).
enum class SplatMethod { compute, raster };

struct FrameSettings {
  ShadingMethod method = ShadingMethod::image_space;
  // Vertex method: receiver capacity, Σ round_up_to_receiver_group(vertex count) over the draws.
  std::uint32_t vertex_receivers = 0;
  std::uint32_t width = 512;          // display resolution, pixels
  std::uint32_t height = 512;
  std::uint32_t receiver_scale = 4;   // k: receivers at 1/k resolution (1, 2, 4, 8)
  float hybrid_tau = 0.25f;           // HYB threshold τ
  bool optimal_linear_only = false;   // OL instead of HYB: no squarings (HYB with τ = ∞)
  render::UpsampleMode upsample = render::UpsampleMode::bilateral;
  float bilateral_depth_epsilon = 0.05f;  // ε of eq. 11, meters of eye depth
  SplatMethod splat = SplatMethod::compute;  // the faster on lavapipe (README, `proxygi bench frame`)
  bool indirect = true;
  render::IndirectOperator indirect_operator = render::IndirectOperator::averaged;  // its own pipeline variant
  render::Tonemap tonemap = render::Tonemap::aces;
  float exposure = 1.0f;              // multiplier before the tonemap (2^EV)
  std::uint32_t frames_in_flight = 2; // ring-buffer slots for per-frame uploads

  // The receiver "image": display / k, or for the vertex method kVertexReceiverWidth × rows.
  std::uint32_t receiver_width() const {
    return method == ShadingMethod::vertex ? kVertexReceiverWidth : (width + receiver_scale - 1) / receiver_scale;
  }
  std::uint32_t receiver_height() const {
    if (method == ShadingMethod::vertex)
      return std::max(round_up_to_receiver_group(vertex_receivers), kVertexReceiverGroup) / kVertexReceiverWidth;
    return (height + receiver_scale - 1) / receiver_scale;
  }
};

}  // namespace proxygi::gpu
