#include "sh/basis.h"

#include <cmath>

#include "base/check.h"

namespace proxygi::sh {
namespace {

template <class Real>
void evaluate_basis_runtime(int order, const glm::vec<3, Real>& dir, std::span<Real> out) {
  PROXYGI_CHECK(order >= kMinOrder && order <= kMaxOrder, "SH order must be 1..8");
  PROXYGI_CHECK(out.size() >= std::size_t(coefficient_count(order)), "output span too small");
  switch (order) {
    case 1: evaluate_basis<1>(dir, out.data()); break;
    case 2: evaluate_basis<2>(dir, out.data()); break;
    case 3: evaluate_basis<3>(dir, out.data()); break;
    case 4: evaluate_basis<4>(dir, out.data()); break;
    case 5: evaluate_basis<5>(dir, out.data()); break;
    case 6: evaluate_basis<6>(dir, out.data()); break;
    case 7: evaluate_basis<7>(dir, out.data()); break;
    default: evaluate_basis<8>(dir, out.data()); break;
  }
}

double factorial(int k) { return std::tgamma(double(k) + 1.0); }

}  // namespace

int band_of_index(int index) { return int(std::floor(std::sqrt(double(index) + 0.5))); }

void evaluate_basis(int order, const glm::vec3& dir, std::span<float> out) { evaluate_basis_runtime(order, dir, out); }
void evaluate_basis(int order, const glm::dvec3& dir, std::span<double> out) { evaluate_basis_runtime(order, dir, out); }

double associated_legendre(int l, int m, double x) {
  PROXYGI_CHECK(m >= 0 && m <= l, "associated_legendre needs 0 <= m <= l");
  // P_m^m = (-1)^m (2m-1)!! (1-x^2)^(m/2): the (-1)^m is the Condon-Shortley phase.
  double pmm = 1.0;
  const double somx2 = std::sqrt(std::max(0.0, (1.0 - x) * (1.0 + x)));
  double odd_factorial = 1.0;
  for (int i = 1; i <= m; ++i) {
    pmm *= -odd_factorial * somx2;
    odd_factorial += 2.0;
  }
  if (l == m) return pmm;
  double pmmp1 = x * (2.0 * m + 1.0) * pmm;
  if (l == m + 1) return pmmp1;
  double pll = 0.0;
  for (int ll = m + 2; ll <= l; ++ll) {
    pll = ((2.0 * ll - 1.0) * x * pmmp1 - (ll + m - 1.0) * pmm) / (ll - m);
    pmm = pmmp1;
    pmmp1 = pll;
  }
  return pll;
}

double legendre(int l, double x) { return associated_legendre(l, 0, x); }

double basis_from_definition(int l, int m, double theta, double phi) {
  const int am = std::abs(m);
  const double k = std::sqrt((2.0 * l + 1.0) / (4.0 * kPi) * factorial(l - am) / factorial(l + am));
  const double p = associated_legendre(l, am, std::cos(theta));
  if (m > 0) return std::sqrt(2.0) * k * std::cos(m * phi) * p;
  if (m < 0) return std::sqrt(2.0) * k * std::sin(am * phi) * p;
  return k * p;
}

}  // namespace proxygi::sh
