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

Plane display_channel(const image::ImageF& image, int channel, float exposure) {
  Plane plane(image.width, image.height);
  for (std::size_t i = 0; i < plane.values.size(); ++i) {
    const float v = exposure * image.pixels[i][channel];
    plane.values[i] = image::linear_to_srgb(v > 0.0f ? std::min(v, 1.0f) : 0.0f);  // NaN -> 0
  }
  return plane;
}

Plane product(const Plane& a, const Plane& b) {
  Plane out(a.width, a.height);
  for (std::size_t i = 0; i < out.values.size(); ++i) out.values[i] = a.values[i] * b.values[i];
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
    const Plane x = display_channel(test, c, options.exposure);
    const Plane y = display_channel(reference, c, options.exposure);
    // Replicated borders never reach the pixels kept below (their windows are inside the image).
    const Plane mu_x = convolve_separable(x, window, window);
    const Plane mu_y = convolve_separable(y, window, window);
    const Plane xx = convolve_separable(product(x, x), window, window);
    const Plane yy = convolve_separable(product(y, y), window, window);
    const Plane xy = convolve_separable(product(x, y), window, window);
    for (std::size_t i = 0; i < map.values.size(); ++i) {
      const double mx = mu_x.values[i], my = mu_y.values[i];
      const double var_x = xx.values[i] - mx * mx, var_y = yy.values[i] - my * my;
      const double cov = xy.values[i] - mx * my;
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
