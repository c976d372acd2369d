#include "sh/exponential.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Eigenvalues>

#include "base/check.h"
#include "sh/basis.h"
#include "sh/product.h"

namespace proxygi::sh {
namespace {

// q(x) = log(x) / (x - 1), continuous at x = 1.
double log_ratio(double x) {
  const double t = x - 1.0;
  if (std::abs(t) < 1e-5) return 1.0 - t / 2.0 + t * t / 3.0;
  return std::log(x) / t;
}

template <int Order>
float dc_factor_and_norm(const float* f, float& norm) {
  float sum = 0.0f;
  for (int i = 1; i < Order * Order; ++i) sum += f[i] * f[i];
  norm = std::sqrt(sum);
  return std::exp(float(kInvSqrtFourPi) * f[0]);
}

}  // namespace

std::vector<double> exp_exact(int order, std::span<const double> f) {
  const int count = order * order;
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver(product_matrix(order, f));
  const Eigen::MatrixXd& r = solver.eigenvectors();
  // R e^D R^T 1, and R^T 1 = sqrt(4 pi) * (first row of R).
  const Eigen::VectorXd projected = kSqrtFourPi * r.row(0).transpose();
  const Eigen::VectorXd result = r * (solver.eigenvalues().array().exp() * projected.array()).matrix();
  return std::vector<double>(result.data(), result.data() + count);
}

std::vector<double> log_exact(int order, std::span<const double> g, double epsilon_ratio) {
  const int count = order * order;
  PROXYGI_CHECK(g.size() >= std::size_t(count), "span too small");
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver(product_matrix(order, g));
  const double largest = solver.eigenvalues().maxCoeff();
  PROXYGI_CHECK(largest > 0.0, "SH log of a function without positive eigenvalues");
  const double epsilon = epsilon_ratio * largest;
  Eigen::VectorXd g_minus_one = Eigen::Map<const Eigen::VectorXd>(g.data(), count);
  g_minus_one(0) -= kSqrtFourPi;
  const Eigen::MatrixXd& r = solver.eigenvectors();
  Eigen::VectorXd weights = solver.eigenvalues().unaryExpr([epsilon](double x) { return log_ratio(std::max(x, epsilon)); });
  const Eigen::VectorXd result = r * (weights.array() * (r.transpose() * g_minus_one).array()).matrix();
  return std::vector<double>(result.data(), result.data() + count);
}

float hybrid_blend(float x, float tau) {
  const float t = std::clamp((x / tau - kHybridBlendStart) / (1.0f - kHybridBlendStart), 0.0f, 1.0f);
  return t * t * (3.0f - 2.0f * t);
}

glm::vec2 OptimalLinearTable::lookup(float norm) const {
  PROXYGI_CHECK(rows() >= 2, "empty OL table");
  const float position = std::clamp(norm / max_norm, 0.0f, 1.0f) * float(rows() - 1);
  const int row = std::min(int(position), rows() - 2);
  const float t = position - float(row);
  return {a[std::size_t(row)] + t * (a[std::size_t(row) + 1] - a[std::size_t(row)]),
          b[std::size_t(row)] + t * (b[std::size_t(row) + 1] - b[std::size_t(row)])};
}

template <int Order>
void exp_product_series(const float* f, int degree, float* out) {
  constexpr int kCount = Order * Order;
  float norm = 0.0f;
  const float dc = dc_factor_and_norm<Order>(f, norm);
  float fhat[kCount], term[kCount], next[kCount];
  fhat[0] = 0.0f;
  for (int i = 1; i < kCount; ++i) fhat[i] = f[i];
  // k = 0 and k = 1 terms: 1 + fhat.
  for (int i = 0; i < kCount; ++i) term[i] = fhat[i];
  for (int i = 0; i < kCount; ++i) out[i] = fhat[i];
  out[0] = float(kSqrtFourPi);
  for (int k = 2; k <= degree; ++k) {
    product<Order>(fhat, term, next);
    const float inverse_k = 1.0f / float(k);
    for (int i = 0; i < kCount; ++i) {
      term[i] = next[i] * inverse_k;
      out[i] += term[i];
    }
  }
  for (int i = 0; i < kCount; ++i) out[i] *= dc;
}

template <int Order>
void exp_optimal_linear(const float* f, const OptimalLinearTable& table, float* out) {
  float norm = 0.0f;
  const float dc = dc_factor_and_norm<Order>(f, norm);
  const glm::vec2 ab = table.lookup(norm);
  out[0] = dc * ab.x * float(kSqrtFourPi);
  for (int i = 1; i < Order * Order; ++i) out[i] = dc * ab.y * f[i];
}

template <int Order>
int exp_hybrid(const float* f, const OptimalLinearTable& table, float tau, float* out, int max_squarings) {
  constexpr int kCount = Order * Order;
  float norm = 0.0f;
  const float dc = dc_factor_and_norm<Order>(f, norm);
  int squarings = 0;
  float scale = 1.0f;
  while (norm * scale > tau && squarings < max_squarings) {
    scale *= 0.5f;
    ++squarings;
  }
  const glm::vec2 ab = table.lookup(norm * scale);
  float g[kCount], squared[kCount];
  g[0] = ab.x * float(kSqrtFourPi);
  for (int i = 1; i < kCount; ++i) g[i] = ab.y * scale * f[i];
  if (const float blend = hybrid_blend(norm * scale, tau); blend > 0.0f) {
    // Toward OL(fhat / 2^(s+1))^{*2}: at x = tau the s squarings below give HYB with s + 1.
    const glm::vec2 half_ab = table.lookup(0.5f * norm * scale);
    float h[kCount];
    h[0] = half_ab.x * float(kSqrtFourPi);
    for (int i = 1; i < kCount; ++i) h[i] = half_ab.y * 0.5f * scale * f[i];
    square<Order>(h, squared);
    for (int i = 0; i < kCount; ++i) g[i] += blend * (squared[i] - g[i]);
  }
  for (int k = 0; k < squarings; ++k) {
    square<Order>(g, squared);
    std::copy(squared, squared + kCount, g);
  }
  for (int i = 0; i < kCount; ++i) out[i] = dc * g[i];
  return squarings;
}

#define PROXYGI_SH_INSTANTIATE_EXP(ORDER)                                                                  \
  template void exp_product_series<ORDER>(const float*, int, float*);                                    \
  template void exp_optimal_linear<ORDER>(const float*, const OptimalLinearTable&, float*);             \
  template int exp_hybrid<ORDER>(const float*, const OptimalLinearTable&, float, float*, int);
PROXYGI_SH_INSTANTIATE_EXP(3)
PROXYGI_SH_INSTANTIATE_EXP(4)
PROXYGI_SH_INSTANTIATE_EXP(5)
PROXYGI_SH_INSTANTIATE_EXP(6)
#undef PROXYGI_SH_INSTANTIATE_EXP

namespace {
void check_spans(int order, std::span<const float> f, std::span<float> out) {
  PROXYGI_CHECK(has_product(order), "SH exponential exists for orders 3..6");
  PROXYGI_CHECK(f.size() >= std::size_t(order * order) && out.size() >= std::size_t(order * order), "span too small");
}
}  // namespace

void exp_product_series(int order, std::span<const float> f, int degree, std::span<float> out) {
  check_spans(order, f, out);
  switch (order) {
    case 3: exp_product_series<3>(f.data(), degree, out.data()); break;
    case 4: exp_product_series<4>(f.data(), degree, out.data()); break;
    case 5: exp_product_series<5>(f.data(), degree, out.data()); break;
    default: exp_product_series<6>(f.data(), degree, out.data()); break;
  }
}

void exp_optimal_linear(int order, std::span<const float> f, const OptimalLinearTable& table, std::span<float> out) {
  check_spans(order, f, out);
  PROXYGI_CHECK(table.order == order, "OL table built for another order");
  switch (order) {
    case 3: exp_optimal_linear<3>(f.data(), table, out.data()); break;
    case 4: exp_optimal_linear<4>(f.data(), table, out.data()); break;
    case 5: exp_optimal_linear<5>(f.data(), table, out.data()); break;
    default: exp_optimal_linear<6>(f.data(), table, out.data()); break;
  }
}

int exp_hybrid(int order, std::span<const float> f, const OptimalLinearTable& table, float tau, std::span<float> out,
               int max_squarings) {
  check_spans(order, f, out);
  PROXYGI_CHECK(table.order == order, "OL table built for another order");
  switch (order) {
    case 3: return exp_hybrid<3>(f.data(), table, tau, out.data(), max_squarings);
    case 4: return exp_hybrid<4>(f.data(), table, tau, out.data(), max_squarings);
    case 5: return exp_hybrid<5>(f.data(), table, tau, out.data(), max_squarings);
    default: return exp_hybrid<6>(f.data(), table, tau, out.data(), max_squarings);
  }
}

}  // namespace proxygi::sh
