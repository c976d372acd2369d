#include "ref/guided_filter.h"

#include <array>
#include <cmath>
#include <string>

namespace proxygi::ref {
namespace {

constexpr int kMaxGuide = 8;

Plane product(const Plane& a, const Plane& b) {
  Plane out(a.width, a.height);
  for (std::size_t i = 0; i < out.values.size(); ++i) out.values[i] = a.values[i] * b.values[i];
  return out;
}

// Solves (A) x = rhs in place for a symmetric positive definite d x d matrix (Cholesky).
void solve_spd(std::array<double, kMaxGuide * kMaxGuide>& a, int d, std::array<double, kMaxGuide>& x) {
  for (int j = 0; j < d; ++j) {
    double diagonal = a[std::size_t(j * d + j)];
    for (int k = 0; k < j; ++k) diagonal -= a[std::size_t(j * d + k)] * a[std::size_t(j * d + k)];
    diagonal = std::sqrt(std::max(diagonal, 1e-12));
    a[std::size_t(j * d + j)] = diagonal;
    for (int i = j + 1; i < d; ++i) {
      double v = a[std::size_t(i * d + j)];
      for (int k = 0; k < j; ++k) v -= a[std::size_t(i * d + k)] * a[std::size_t(j * d + k)];
      a[std::size_t(i * d + j)] = v / diagonal;
    }
  }
  for (int i = 0; i < d; ++i) {  // L y = rhs
    for (int k = 0; k < i; ++k) x[std::size_t(i)] -= a[std::size_t(i * d + k)] * x[std::size_t(k)];
    x[std::size_t(i)] /= a[std::size_t(i * d + i)];
  }
  for (int i = d - 1; i >= 0; --i) {  // L^T x = y
    for (int k = i + 1; k < d; ++k) x[std::size_t(i)] -= a[std::size_t(k * d + i)] * x[std::size_t(k)];
    x[std::size_t(i)] /= a[std::size_t(i * d + i)];
  }
}

}  // namespace

Result<image::ImageF> guided_filter(const image::ImageF& input, std::span<const Plane> guide,
                                    std::span<const float> epsilon, int radius) {
  const int d = int(guide.size());
  if (d < 1 || d > kMaxGuide) return make_error("guided filter: need 1 to 8 guide planes, got " + std::to_string(d));
  if (epsilon.size() != guide.size()) return make_error("guided filter: one epsilon per guide plane");
  if (radius < 1) return make_error("guided filter: radius must be at least 1");
  if (input.width <= 0 || input.height <= 0) return make_error("guided filter: empty input");
  for (int k = 0; k < d; ++k) {
    if (guide[std::size_t(k)].width != input.width || guide[std::size_t(k)].height != input.height)
      return make_error("guided filter: guide plane " + std::to_string(k) + " is " +
                        std::to_string(guide[std::size_t(k)].width) + "x" + std::to_string(guide[std::size_t(k)].height) +
                        ", input is " + std::to_string(input.width) + "x" + std::to_string(input.height));
    if (!(epsilon[std::size_t(k)] > 0.0f)) return make_error("guided filter: epsilon must be positive");
  }
  const int w = input.width, h = input.height;
  const std::size_t n = std::size_t(w) * std::size_t(h);

  std::vector<Plane> mean_i, corr_ii;  // corr_ii: upper triangle, (k, l) with k <= l
  for (int k = 0; k < d; ++k) mean_i.push_back(box_mean(guide[std::size_t(k)], radius));
  for (int k = 0; k < d; ++k)
    for (int l = k; l < d; ++l) corr_ii.push_back(box_mean(product(guide[std::size_t(k)], guide[std::size_t(l)]), radius));

  image::ImageF output(w, h);
  for (std::size_t i = 0; i < n; ++i) output.pixels[i].a = input.pixels[i].a;
  for (int c = 0; c < 3; ++c) {
    const Plane p = channel_plane(input, c);
    const Plane mean_p = box_mean(p, radius);
    std::vector<Plane> mean_ip;
    for (int k = 0; k < d; ++k) mean_ip.push_back(box_mean(product(guide[std::size_t(k)], p), radius));

    std::vector<Plane> a(std::size_t(d), Plane(w, h));
    Plane b(w, h);
    for (std::size_t i = 0; i < n; ++i) {
      std::array<double, kMaxGuide * kMaxGuide> sigma{};
      std::array<double, kMaxGuide> x{};
      std::size_t pair = 0;
      for (int k = 0; k < d; ++k)
        for (int l = k; l < d; ++l, ++pair) {
          const double cov = double(corr_ii[pair].values[i]) - double(mean_i[std::size_t(k)].values[i]) * mean_i[std::size_t(l)].values[i];
          sigma[std::size_t(k * d + l)] = sigma[std::size_t(l * d + k)] = cov;
        }
      for (int k = 0; k < d; ++k) {
        sigma[std::size_t(k * d + k)] += epsilon[std::size_t(k)];
        x[std::size_t(k)] = double(mean_ip[std::size_t(k)].values[i]) - double(mean_i[std::size_t(k)].values[i]) * mean_p.values[i];
      }
      solve_spd(sigma, d, x);
      double offset = mean_p.values[i];
      for (int k = 0; k < d; ++k) {
        a[std::size_t(k)].values[i] = float(x[std::size_t(k)]);
        offset -= x[std::size_t(k)] * mean_i[std::size_t(k)].values[i];
      }
      b.values[i] = float(offset);
    }
    // q = mean(a) . I + mean(b): every window covering the pixel contributes its linear model.
    Plane q = box_mean(b, radius);
    for (int k = 0; k < d; ++k) {
      const Plane mean_a = box_mean(a[std::size_t(k)], radius);
      for (std::size_t i = 0; i < n; ++i) q.values[i] += mean_a.values[i] * guide[std::size_t(k)].values[i];
    }
    for (std::size_t i = 0; i < n; ++i) output.pixels[i][c] = q.values[i];
  }
  return output;
}

Result<image::ImageF> guided_filter_indirect(const image::ImageF& noisy_indirect, const GuideFeatures& features,
                                             const GuidedFilterOptions& options) {
  std::vector<Plane> guide;
  std::vector<float> epsilon;
  auto check_size = [&](const image::ImageF& feature, const char* name) -> Status {
    if (feature.width != noisy_indirect.width || feature.height != noisy_indirect.height)
      return make_error(std::string("guided filter: ") + name + " is " + std::to_string(feature.width) + "x" +
                        std::to_string(feature.height) + ", indirect image is " + std::to_string(noisy_indirect.width) +
                        "x" + std::to_string(noisy_indirect.height));
    return {};
  };
  if (features.normal != nullptr) {
    if (Status ok = check_size(*features.normal, "normal image"); !ok) return ok.error();
    for (int c = 0; c < 3; ++c) {
      Plane plane = channel_plane(*features.normal, c);
      for (float& v : plane.values) v = 0.5f * (v + 1.0f);
      guide.push_back(std::move(plane));
      epsilon.push_back(options.epsilon_normal);
    }
  }
  if (features.depth != nullptr) {
    if (Status ok = check_size(*features.depth, "depth image"); !ok) return ok.error();
    if (!(features.depth_scale > 0.0f)) return make_error("guided filter: depth_scale must be positive");
    Plane plane = channel_plane(*features.depth, 0);
    for (float& v : plane.values) v /= features.depth_scale;
    guide.push_back(std::move(plane));
    epsilon.push_back(options.epsilon_depth);
  }
  if (features.albedo != nullptr) {
    if (Status ok = check_size(*features.albedo, "albedo image"); !ok) return ok.error();
    for (int c = 0; c < 3; ++c) {
      guide.push_back(channel_plane(*features.albedo, c));
      epsilon.push_back(options.epsilon_albedo);
    }
  }
  if (guide.empty()) return make_error("guided filter: no feature image given (normal, depth or albedo)");
  return guided_filter(noisy_indirect, guide, epsilon, options.radius);
}

}  // namespace proxygi::ref
