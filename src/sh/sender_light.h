#pragma once
// The light a proxy reflects toward a receiver (docs/sender-light.md derives this).
//
// The paper's proxies (Sloan et al. 2007, eq. 13–17) reflect the whole unshadowed environment:
// their radiance comes from L̃ = L * clamped cosine, the same for every receiver. But the part of
// a proxy that a receiver p (unit normal N) sees lies above p's tangent plane, and light reaching
// it from below that plane must cross the surface p lies on: exactly so for the ground, and
// approximately for a body part, whose tangent plane stands for the body under p. So the sender
// light of p is the lighting above p's plane,
//   L_N(s) = L(s) [s · N > 0],    L̃_N = A_l (L_N)_lm   (order 3, the indirect pass's order),
// with A_l = π, 2π/3, π/4 the clamped cosine's convolution factors (sh/convolution.h). Nothing is
// added below the plane: the light the receiver's own surface would reflect there is a second
// bounce. For a receiver on the ground (N = +Y) L_N is the lighting above the horizon.
// Exact for band-limited L: (L_N)_i = ∫_{s·N>0} L(s) y_i(s) ds integrates a polynomial of degree
// ≤ (order − 1) + (out_order − 1) over the hemisphere about N, which the Gauss–Legendre × uniform φ
// rule of sh/ground_bounce.h, turned onto N, does exactly.
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "sh/environment.h"

namespace proxygi::sh {

// The order-`out_order` projection of L(s) [s · N > 0] for the order-`order` lighting L (one
// channel; lighting.size() ≥ order²; N unit). Returns out_order² values.
std::vector<double> project_above_plane(int order, std::span<const double> lighting, const glm::dvec3& normal,
                                        int out_order);

// L̃_N of one channel per receiver normal N, order 3 (9 values per texel), over the cube-map
// layout of sh/environment.h (texel centres as N; render::lookup_lighting_cube reads it).
LightingCubeMap make_sender_light_cube(int order, std::span<const double> lighting, int face_size);

}  // namespace proxygi::sh
