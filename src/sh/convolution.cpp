#include "sh/convolution.h"

#include <cmath>

#include "base/check.h"
#include "sh/basis.h"
#include "sh/rotation.h"

namespace proxygi::sh {
namespace {

// integral_0^1 x P_l(x) dx.
double half_moment_of_legendre(int l) {
  if (l == 0) return 0.5;
  if (l == 1) return 1.0 / 3.0;
  if (l % 2 == 1) return 0.0;
  // (-1)^(l/2+1) (l-2)! / (2^l (l/2-1)! (l/2+1)!)
  const int half = l / 2;
  const double magnitude = std::tgamma(l - 1.0) / (std::pow(2.0, l) * std::tgamma(double(half)) * std::tgamma(half + 2.0));
  return (half % 2 == 0 ? -1.0 : 1.0) * magnitude;
}

template <class Real>
void convolve_zonal_impl(int order, std::span<const double> kernel, std::span<Real> sh) {
  PROXYGI_CHECK(kernel.size() >= std::size_t(order) && sh.size() >= std::size_t(order * order), "span too small");
  for (int l = 0; l < order; ++l)
    for (int i = l * l; i < (l + 1) * (l + 1); ++i) sh[std::size_t(i)] *= Real(zonal_rotation_scale(l) * kernel[std::size_t(l)]);
}

template <class Real>
void apply_window_impl(int order, std::span<Real> sh, double window_size) {
  PROXYGI_CHECK(sh.size() >= std::size_t(order * order), "span too small");
  const std::vector<double> window = ringing_window(order, window_size);
  for (int l = 0; l < order; ++l)
    for (int i = l * l; i < (l + 1) * (l + 1); ++i) sh[std::size_t(i)] *= Real(window[std::size_t(l)]);
}

}  // namespace

std::vector<double> clamped_cosine_zonal(int order) {
  std::vector<double> h(static_cast<std::size_t>(order));
  // h_l = 2 pi sqrt((2l+1)/(4pi)) integral_0^1 x P_l(x) dx.
  for (int l = 0; l < order; ++l) h[std::size_t(l)] = 2.0 * kPi * std::sqrt((2.0 * l + 1.0) / (4.0 * kPi)) * half_moment_of_legendre(l);
  return h;
}

void convolve_zonal(int order, std::span<const double> kernel, std::span<double> sh) { convolve_zonal_impl(order, kernel, sh); }
void convolve_zonal(int order, std::span<const double> kernel, std::span<float> sh) { convolve_zonal_impl(order, kernel, sh); }

std::vector<double> clamped_cosine_about(int order, const glm::dvec3& normal) {
  std::vector<double> result(static_cast<std::size_t>(order * order));
  rotate_zonal(order, clamped_cosine_zonal(order), normal, result);
  return result;
}

std::vector<double> ringing_window(int order, double window_size) {
  const double h = window_size > 0.0 ? window_size : 2.0 * order;
  std::vector<double> window(static_cast<std::size_t>(order));
  for (int l = 0; l < order; ++l) window[std::size_t(l)] = l >= h ? 0.0 : std::cos(kPi * l / (2.0 * h));
  return window;
}

void apply_ringing_window(int order, std::span<float> sh, double window_size) { apply_window_impl(order, sh, window_size); }
void apply_ringing_window(int order, std::span<double> sh, double window_size) { apply_window_impl(order, sh, window_size); }

}  // namespace proxygi::sh
