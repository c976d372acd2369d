#include "sh/product.h"

#include <vector>

#include "base/check.h"
#include "sh/basis.h"

namespace proxygi::sh {
namespace {

void check_order(int order) { PROXYGI_CHECK(has_product(order), "SH products exist for orders 3..6"); }

// Calls visit(i, j, k, value) for every ordered non-zero Gamma_ijk.
template <class Visit>
void for_each_ordered_entry(int order, Visit&& visit) {
  for (const TripleProductEntry& entry : triple_product_entries(order)) {
    const int i = entry.i, j = entry.j, k = entry.k;
    const double v = entry.value;
    // The distinct permutations of (i, j, k).
    visit(i, j, k, v);
    if (i == j && j == k) continue;
    if (i == j) { visit(i, k, j, v); visit(k, i, j, v); continue; }
    if (j == k) { visit(j, i, k, v); visit(j, k, i, v); continue; }
    visit(i, k, j, v);
    visit(j, i, k, v);
    visit(j, k, i, v);
    visit(k, i, j, v);
    visit(k, j, i, v);
  }
}

}  // namespace

std::span<const TripleProductEntry> triple_product_entries(int order) {
  check_order(order);
  switch (order) {
    case 3: return generated::kTripleProductEntries3;
    case 4: return generated::kTripleProductEntries4;
    case 5: return generated::kTripleProductEntries5;
    default: return generated::kTripleProductEntries6;
  }
}

int ordered_triple_product_count(int order) {
  int count = 0;
  for_each_ordered_entry(order, [&count](int, int, int, double) { ++count; });
  return count;
}

void product(int order, std::span<const float> a, std::span<const float> b, std::span<float> out) {
  check_order(order);
  const std::size_t count = std::size_t(order * order);
  PROXYGI_CHECK(a.size() >= count && b.size() >= count && out.size() >= count, "span too small");
  switch (order) {
    case 3: product<3>(a.data(), b.data(), out.data()); break;
    case 4: product<4>(a.data(), b.data(), out.data()); break;
    case 5: product<5>(a.data(), b.data(), out.data()); break;
    default: product<6>(a.data(), b.data(), out.data()); break;
  }
}

void square(int order, std::span<const float> a, std::span<float> out) {
  check_order(order);
  const std::size_t count = std::size_t(order * order);
  PROXYGI_CHECK(a.size() >= count && out.size() >= count, "span too small");
  switch (order) {
    case 3: square<3>(a.data(), out.data()); break;
    case 4: square<4>(a.data(), out.data()); break;
    case 5: square<5>(a.data(), out.data()); break;
    default: square<6>(a.data(), out.data()); break;
  }
}

void product(int order, std::span<const double> a, std::span<const double> b, std::span<double> out) {
  check_order(order);
  const std::size_t count = std::size_t(order * order);
  PROXYGI_CHECK(a.size() >= count && b.size() >= count && out.size() >= count, "span too small");
  std::vector<double> result(count, 0.0);
  for_each_ordered_entry(order, [&](int i, int j, int k, double v) { result[std::size_t(i)] += v * a[std::size_t(j)] * b[std::size_t(k)]; });
  std::copy(result.begin(), result.end(), out.begin());
}

Eigen::MatrixXd product_matrix(int order, std::span<const double> f) {
  check_order(order);
  const int count = order * order;
  PROXYGI_CHECK(f.size() >= std::size_t(count), "span too small");
  Eigen::MatrixXd matrix = Eigen::MatrixXd::Zero(count, count);
  for_each_ordered_entry(order, [&](int i, int j, int k, double v) { matrix(i, j) += v * f[std::size_t(k)]; });
  return matrix;
}

}  // namespace proxygi::sh
