#pragma once
// SH exponential and logarithm (SHEXP; conventions in sh/basis.h, notes sh-math.md section 3).
//
//   exp*(f) = sum_k f^{*k} / k!  (right-associated powers)  = expm(M_f) 1,
// with M_f the product matrix (sh/product.h) and 1 = (sqrt(4 pi), 0, ...) the constant function.
// DC isolation is exact: f = f0 e0 + fhat (fhat_0 = 0) gives
//   exp*(f) = exp(f0 / sqrt(4 pi)) exp*(fhat),   note: / sqrt(4 pi), i.e. exp(0.2820948 f0).
// Approximations of exp*(fhat), all followed by the DC factor:
//   PS  product series of degree p: sum_{k<=p} fhat^{*k}/k!   (p - 1 SH products)
//   OL  optimal linear: a(|fhat|) 1 + b(|fhat|) fhat, (a, b) from a 1-D table
//   HYB the smallest s with |fhat| / 2^s <= tau, OL(fhat / 2^s), then s squarings; continuous in
//       f: where x = |fhat| / 2^s nears tau (x > kHybridBlendStart tau), OL(fhat / 2^s) is blended
//       toward OL(fhat / 2^(s+1))^{*2} by smoothstep(kHybridBlendStart, 1, x / tau), so at x = tau
//       it is HYB with s + 1 squarings, what the next norm up uses (without the blend the count
//       switch stepped the shade by up to ~2/255 under a slow fade: notes F7, proxy LOD fades).
// log*(g) = R q(max(D, eps)) R^T (g - 1), M_g = R D R^T, q(x) = log(x)/(x-1), eps = 0.02 max(D).
// Orders 3..6 (the orders with products). Float paths are the run-time ones; double paths are
// the references.
#include <span>
#include <vector>

#include <glm/glm.hpp>

namespace proxygi::sh {

// Where HYB's blend toward the next squaring count starts, as a fraction of tau (the GPU's
// exponentiate.comp reads gpu_layout::kHybridBlendStart, asserted equal in exponentiate_pass.cpp).
// 0.75: 0.42 of an octave of |fhat|, so a quarter to a half of shadowed receivers pay one more
// SH square.
inline constexpr float kHybridBlendStart = 0.75f;
// The blend's weight at x = |fhat| / 2^s: 0 at or below kHybridBlendStart tau, 1 at tau.
float hybrid_blend(float x, float tau);

// Exact exp*(f) by eigendecomposition of the symmetric M_f (Eigen). Returns order*order values.
std::vector<double> exp_exact(int order, std::span<const double> f);
// SH log by eigendecomposition with the eigenvalue clamp eps = epsilon_ratio * max eigenvalue.
std::vector<double> log_exact(int order, std::span<const double> g, double epsilon_ratio = 0.02);

// The OL coefficients a, b tabulated over the norm |fhat| (L2 norm of the SH vector without its
// DC coefficient): row r <-> norm = r * max_norm / (rows - 1), linearly interpolated, clamped to
// the last row above max_norm. Built by make_optimal_linear_table (sh/occlusion_tables.h).
struct OptimalLinearTable {
  int order = 0;
  float max_norm = 0.0f;
  std::vector<float> a;  // rows values; a(0) = 1
  std::vector<float> b;  // rows values; b(0) = 1
  int rows() const { return int(a.size()); }
  glm::vec2 lookup(float norm) const;  // (a, b)
};

// Float run-time paths. f and out hold order*order values and may not alias.
void exp_product_series(int order, std::span<const float> f, int degree, std::span<float> out);
void exp_optimal_linear(int order, std::span<const float> f, const OptimalLinearTable& table, std::span<float> out);
// Returns the number of squarings used (s, the blend's extra square not counted). max_squarings
// bounds the loop for pathological inputs.
int exp_hybrid(int order, std::span<const float> f, const OptimalLinearTable& table, float tau,
               std::span<float> out, int max_squarings = 16);

// Fixed-order fast paths (Order 3..6), same contracts; defined in exponential.cpp for 3..6.
template <int Order>
void exp_product_series(const float* f, int degree, float* out);
template <int Order>
void exp_optimal_linear(const float* f, const OptimalLinearTable& table, float* out);
template <int Order>
int exp_hybrid(const float* f, const OptimalLinearTable& table, float tau, float* out, int max_squarings = 16);

}  // namespace proxygi::sh
