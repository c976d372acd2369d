#pragma once
// Projected SH products for orders 3..6 (conventions in sh/basis.h).
//   (f * g)_i = sum_jk Gamma_ijk f_j g_k,   Gamma_ijk = integral_S y_i y_j y_k,
// with every index truncated to < n*n, so the product is commutative but not associative.
// The product matrix (M_f)_ij = sum_k Gamma_ijk f_k is symmetric, f * g = M_f g, M_1 = I.
// Gamma is computed at build time by exact quadrature in src/sh/codegen/generate_sh.py, which
// also writes the unrolled float product/square code used here and sh_product.glsl
// (sh_product_<n>(a, b, out c), sh_square_<n>(a, out c)) for the shaders.
#include <span>

#include <Eigen/Core>

#include "sh/product_generated.h"

namespace proxygi::sh {

using generated::TripleProductEntry;
inline constexpr int kMinProductOrder = generated::kMinProductOrder;  // 3
inline constexpr int kMaxProductOrder = generated::kMaxProductOrder;  // 6

constexpr bool has_product(int order) { return order >= kMinProductOrder && order <= kMaxProductOrder; }

// Non-zero Gamma entries with i <= j <= k (each once; all permutations share the value).
std::span<const TripleProductEntry> triple_product_entries(int order);
// Number of non-zero ordered entries Gamma_ijk (353 at order 4).
int ordered_triple_product_count(int order);

// Fixed-order fast paths (unrolled, generated). out must not alias the inputs.
template <int Order>
inline void product(const float* a, const float* b, float* out) {
  static_assert(Order >= kMinProductOrder && Order <= kMaxProductOrder, "no product for this order");
  if constexpr (Order == 3) generated::product_3(a, b, out);
  if constexpr (Order == 4) generated::product_4(a, b, out);
  if constexpr (Order == 5) generated::product_5(a, b, out);
  if constexpr (Order == 6) generated::product_6(a, b, out);
}
template <int Order>
inline void square(const float* a, float* out) {
  static_assert(Order >= kMinProductOrder && Order <= kMaxProductOrder, "no product for this order");
  if constexpr (Order == 3) generated::square_3(a, out);
  if constexpr (Order == 4) generated::square_4(a, out);
  if constexpr (Order == 5) generated::square_5(a, out);
  if constexpr (Order == 6) generated::square_6(a, out);
}

// Runtime order (3..6). Spans hold >= order*order values; out must not alias a or b.
void product(int order, std::span<const float> a, std::span<const float> b, std::span<float> out);
void square(int order, std::span<const float> a, std::span<float> out);
// Double precision reference through the sparse table (aliasing allowed).
void product(int order, std::span<const double> a, std::span<const double> b, std::span<double> out);

// The product matrix M_f (order*order square, symmetric).
Eigen::MatrixXd product_matrix(int order, std::span<const double> f);

}  // namespace proxygi::sh
