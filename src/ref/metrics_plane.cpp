#include "ref/metrics_plane.h"

#include <algorithm>

#include "base/check.h"

namespace proxygi::ref {

Plane channel_plane(const image::ImageF& image, int channel) {
  Plane plane(image.width, image.height);
  for (std::size_t i = 0; i < plane.values.size(); ++i) plane.values[i] = image.pixels[i][channel];
  return plane;
}

std::vector<double> convolve_separable(std::span<const double> in, int width, int height,
                                       std::span<const double> kernel_x, std::span<const double> kernel_y) {
  PROXYGI_CHECK(kernel_x.size() % 2 == 1 && kernel_y.size() % 2 == 1, "kernels have odd length");
  PROXYGI_CHECK(in.size() == std::size_t(width) * std::size_t(height), "grid size matches");
  const int rx = int(kernel_x.size() / 2), ry = int(kernel_y.size() / 2);
  const int w = width, h = height;
  auto index = [w](int x, int y) { return std::size_t(y) * std::size_t(w) + std::size_t(x); };
  std::vector<double> rows(in.size());
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      double sum = 0.0;
      for (int i = -rx; i <= rx; ++i) sum += kernel_x[std::size_t(i + rx)] * in[index(std::clamp(x + i, 0, w - 1), y)];
      rows[index(x, y)] = sum;
    }
  std::vector<double> out(in.size());
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      double sum = 0.0;
      for (int j = -ry; j <= ry; ++j) sum += kernel_y[std::size_t(j + ry)] * rows[index(x, std::clamp(y + j, 0, h - 1))];
      out[index(x, y)] = sum;
    }
  return out;
}

Plane convolve_separable(const Plane& in, std::span<const double> kernel_x, std::span<const double> kernel_y) {
  const std::vector<double> values(in.values.begin(), in.values.end());
  const std::vector<double> filtered = convolve_separable(values, in.width, in.height, kernel_x, kernel_y);
  Plane out(in.width, in.height);
  for (std::size_t i = 0; i < filtered.size(); ++i) out.values[i] = float(filtered[i]);
  return out;
}

Plane box_mean(const Plane& in, int radius) {
  const int w = in.width, h = in.height;
  // table(x, y) = sum of in over [0, x) x [0, y); (w+1) x (h+1).
  std::vector<double> table(std::size_t(w + 1) * std::size_t(h + 1), 0.0);
  auto t = [&](int x, int y) -> double& { return table[std::size_t(y) * std::size_t(w + 1) + std::size_t(x)]; };
  for (int y = 0; y < h; ++y) {
    double row = 0.0;
    for (int x = 0; x < w; ++x) {
      row += in.at(x, y);
      t(x + 1, y + 1) = t(x + 1, y) + row;
    }
  }
  Plane out(w, h);
  for (int y = 0; y < h; ++y) {
    const int y0 = std::max(0, y - radius), y1 = std::min(h, y + radius + 1);
    for (int x = 0; x < w; ++x) {
      const int x0 = std::max(0, x - radius), x1 = std::min(w, x + radius + 1);
      const double sum = t(x1, y1) - t(x0, y1) - t(x1, y0) + t(x0, y0);
      out.at(x, y) = float(sum / double((x1 - x0) * (y1 - y0)));
    }
  }
  return out;
}

}  // namespace proxygi::ref
