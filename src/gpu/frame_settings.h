#pragma once
// Settings of one soft-GI frame on the GPU (scene files map onto these; src/scene validates).
#include <cstdint>

#include "render/shading.h"

namespace proxygi::gpu {

struct FrameSettings {
  std::uint32_t width = 512;          // display resolution, pixels
  std::uint32_t height = 512;
  std::uint32_t receiver_scale = 4;   // k: receivers at 1/k resolution (1, 2, 4, 8)
  float hybrid_tau = 0.25f;           // HYB threshold τ
  bool optimal_linear_only = false;   // OL instead of HYB: no squarings (HYB with τ = ∞)
  render::UpsampleMode upsample = render::UpsampleMode::bilateral;
  float bilateral_depth_epsilon = 0.05f;  // ε of eq. 11, meters of eye depth
  bool indirect = true;
  render::IndirectOperator indirect_operator = render::IndirectOperator::averaged;  // its own pipeline variant
  render::Tonemap tonemap = render::Tonemap::aces;
  float exposure = 1.0f;              // multiplier before the tonemap (2^EV)
  std::uint32_t frames_in_flight = 2; // ring-buffer slots for per-frame uploads

  std::uint32_t receiver_width() const { return (width + receiver_scale - 1) / receiver_scale; }
  std::uint32_t receiver_height() const { return (height + receiver_scale - 1) / receiver_scale; }
};

}  // namespace proxygi::gpu
