#include "ref/ssim.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

namespace proxygi::ref {
namespace {

constexpr int kRadius = 5;  // 11x11 window
constexpr double kSigma = 1.5;
constexpr double kC1 = 0.01 * 0.01;  // (K1 L)^2, L = 1
constexpr double kC2 = 0.03 * 0.03;  // (K2 L)^2

std::array<double, 2 * kRadius + 1> gaussian_window() {
  std::array<double, 2 * kRadius + 1> weights{};
  double sum = 0.0;
  for (int i = -kRadius; i <= kRadius; ++i) {
    weights[std::size_t(i + kRadius)] = std::exp(-double(i * i) / (2.0 * kSigma * kSigma));
    sum += weights[std::size_t(i + kRadius)];
  }
  for (double& w : weights) w /= sum;
  return weights;
}

std::vector<double> display_channel(const image::ImageF& image, int channel, float exposure) {
  std::vector<double> values(image.pixels.size());
  for (std::size_t i = 0; i < values.size(); ++i) {
    const float v = exposure * image.pixels[i][channel];
    values[i] = image::linear_to_srgb(v > 0.0f ? std::min(v, 1.0f) : 0.0f);  // NaN -> 0
  }
  return values;
}

std::vector<double> product(const std::vector<double>& a, const std::vector<double>& b) {
  std::vector<double> out(a.size());
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = a[i] * b[i];
  return out;
}

}  // namespace

Result<MetricResult> ssim(const image::ImageF& test, const image::ImageF& reference, const ReceiverMask* mask,
                          const SsimOptions& options) {
  if (Status ok = check_comparable(test, reference, mask); !ok) return ok.error();
  if (test.width < 2 * kRadius + 1 || test.height < 2 * kRadius + 1)
    return make_error("SSIM needs images of at least 11x11 pixels, got " + std::to_string(test.width) + "x" +
                      std::to_string(test.height));
  const auto window = gaussian_window();
  const int w = test.width, h = test.height;

  Plane map(w, h);
  for (int c = 0; c < 3; ++c) {
    const std::vector<double> x = display_channel(test, c, options.exposure);
    const std::vector<double> y = display_channel(reference, c, options.exposure);
    // Double precision: var = E[x^2] - E[x]^2 cancels, and float rounding of a small covariance
    // would move SSIM by ~1e-5. Replicated borders never reach the pixels kept below.
    auto blur = [&](const std::vector<double>& v) { return convolve_separable(v, w, h, window, window); };
    const std::vector<double> mu_x = blur(x), mu_y = blur(y);
    const std::vector<double> xx = blur(product(x, x)), yy = blur(product(y, y)), xy = blur(product(x, y));
    for (std::size_t i = 0; i < map.values.size(); ++i) {
      const double mx = mu_x[i], my = mu_y[i];
      const double var_x = xx[i] - mx * mx, var_y = yy[i] - my * my;
      const double cov = xy[i] - mx * my;
      const double s = ((2.0 * mx * my + kC1) * (2.0 * cov + kC2)) / ((mx * mx + my * my + kC1) * (var_x + var_y + kC2));
      map.values[i] += float(s / 3.0);
    }
  }
  std::vector<std::uint8_t> valid(map.values.size(), 0);
  for (int py = kRadius; py < h - kRadius; ++py)
    for (int px = kRadius; px < w - kRadius; ++px) valid[std::size_t(py) * std::size_t(w) + std::size_t(px)] = 1;
  MetricResult result = pool_mean(std::move(map), mask, &valid);
  if (result.pixels == 0) return make_error("SSIM: no receiver pixel lies 5 or more pixels inside the border");
  return result;
}

}  // namespace proxygi::ref
