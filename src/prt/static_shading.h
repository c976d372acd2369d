#pragma once
// How a static receiver combines its precomputed transfer (prt/transfer.h) with the proxies'
// visibility O_p and bounce light I_p: the three levels of notes/prt-vsgl.md §2, CPU reference
// (the run-time GPU part is not written yet). All vectors are order-n SH (n² values, sh/basis.h);
// results are irradiance per channel (E; exit radiance = albedo/π · E), clamped at 0.
//   l0     E = O_p · (M_L H) + I_p · H                        today: no static self-shadowing
//   ratio  E = (T_DI · L) (O_p · M_L H) / (H · L) + I_p · H   static factor × proxy-shadowed light
//   l1     E = O_p · (M_L T) + I_p · T + κ_p (B · L),         T = T_DS, B = T_DI − T_DS,
//          κ_p = ((H − T) · O_p) / ((H − T) · 1) ∈ [0, 1]     (1 where nothing static blocks)
// M_L X is the order-n truncated product L ∗ X (sh/product.h), as the frame's LH(N).
#include <array>
#include <glm/glm.hpp>
#include <span>

#include "settings/render_settings.h"

namespace proxygi::prt {

// The levels are the frame's setting render.static_transfer (one definition, src/settings).
using StaticTransferLevel = settings::StaticTransfer;

struct StaticReceiverSh {
  std::span<const float> clamped_cosine;                 // H(N)
  std::span<const float> shadowed;                       // T_DS
  std::array<std::span<const float>, 3> interreflected;  // T_DI per channel
};

// lighting: per channel L; occlusion: O_p (all-ones visibility = (√4π, 0, …)); proxy_indirect:
// per channel I_p, or empty spans for none. order in 3..6.
glm::vec3 shade_static_receiver(int order, StaticTransferLevel level, const StaticReceiverSh& receiver,
                                const std::array<std::span<const float>, 3>& lighting, std::span<const float> occlusion,
                                const std::array<std::span<const float>, 3>& proxy_indirect = {});

// κ_p of the l1 level.
float unblocked_proxy_fraction(int order, std::span<const float> clamped_cosine, std::span<const float> shadowed,
                               std::span<const float> occlusion);
// The same κ_p from the blocked part D = H(N) − T_DS given directly (the frame's baked records).
float unblocked_fraction_of_blocked(int order, std::span<const float> blocked, std::span<const float> occlusion);

// Σ_{i<n} a_i b_i in float, in index order (the SH inner product both shading forms use).
float dot_coefficients(std::span<const float> a, std::span<const float> b, std::size_t n);

}  // namespace proxygi::prt
