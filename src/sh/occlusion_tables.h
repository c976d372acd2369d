#pragma once
// Per-sphere zonal vectors and the 1-D tables the GPU samples (conventions in sh/basis.h, paper
// eq. 3-4, notes sections 3-4).
//
// A sphere proxy of radius r whose center lies along +z at distance d, seen from the receiver,
// covers the cap of half-angle alpha with s = sin(alpha) = min(r / d, 1).
//   proxy visibility V(s): 1 on the cap (the proxy is seen), 0 elsewhere; zonal coefficients
//     c_0 = sqrt(pi)(1 - cos a), c_l = 2 pi sqrt((2l+1)/(4pi)) (P_{l-1}(cos a) - P_{l+1}(cos a))/(2l+1)
//   occlusion O(s) = 1 - V(s): the environment seen past the proxy (paper's O_i); O_0 = sqrt(4pi) - c_0
//   log occlusion O_log(s) = log*(O(s)) (sh/exponential.h, eps = 0.02 lambda_max).
// All zonal vectors hold the plain m = 0 coefficients z_l (NOT pre-scaled by sqrt(4pi/(2l+1)));
// turn them to the sphere's direction with rotate_zonal (sh/rotation.h).
//
// GPU table layout (ZonalTable): `rows` rows over s in [0, 1], row i <-> s_i = i / (rows - 1),
// each row `order` floats z_0..z_{order-1}; values[i * order + l]. Sample with linear filtering
// at texel coordinate s * (rows - 1) (i.e. u = (s (rows-1) + 0.5) / rows for a texture).
#include <span>
#include <vector>

#include "sh/exponential.h"

namespace proxygi::sh {

std::vector<double> proxy_visibility_zonal(int order, double s);
std::vector<double> occlusion_zonal(int order, double s);
// log*(O(s)) for orders 3..6 (ZH in, ZH out).
std::vector<double> log_occlusion_zonal(int order, double s, double epsilon_ratio = 0.02);

struct ZonalTable {
  int order = 0;
  int rows = 0;
  std::vector<float> values;  // rows * order, row-major
  std::span<const float> row(int index) const { return {values.data() + std::size_t(index) * std::size_t(order), std::size_t(order)}; }
  // Linear interpolation at s (clamped to [0, 1]); out holds order values.
  void lookup(float s, std::span<float> out) const;
};

// rows >= 2. Orders 1..8 for the visibility table, 3..6 for the log-occlusion table.
ZonalTable make_proxy_visibility_table(int order, int rows = 256);
ZonalTable make_log_occlusion_table(int order, int rows = 256);

// Smooth clamp to the sphere of influence (paper 4.1). With influence factor eta the smallest
// supported proxy has s = 1/eta: the weight is 0 for s <= 1/eta and rises with a smoothstep to 1
// over `fade_rows` table rows (row spacing 1/(rows-1)), so the accumulated contribution goes to 0
// continuously at the splat boundary. 1/eta must be < 1.
float influence_fade_weight(float s, float eta, int rows, int fade_rows = 4);
// Multiplies every row of the table by influence_fade_weight(s_i, eta, rows, fade_rows).
void apply_influence_fade(ZonalTable& table, float eta, int fade_rows = 4);

// OL (a, b) fitted on the single-sphere family (the published implementations' choice):
// a = DC of exp*(fhat) / sqrt(4pi) (DC exact), b = <exp*(fhat), fhat> / <fhat, fhat> (least
// squares), indexed by |fhat| along the increasing branch of |fhat(s)|; rows over
// [0, max_norm] (max_norm <= 0: the end of that branch, about 5.1 at order 4). Orders 3..6.
OptimalLinearTable make_optimal_linear_table(int order, int rows = 256, float max_norm = 0.0f);

}  // namespace proxygi::sh
