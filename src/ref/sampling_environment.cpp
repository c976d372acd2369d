#include "ref/sampling_environment.h"

#include <algorithm>
#include <cmath>

#include "ref/sampling.h"
#include "scene/environment.h"

namespace proxygi::ref {
namespace {

// Index k with cdf[k] <= u < cdf[k + 1], skipping zero-width bins.
int find_bin(const float* cdf, int count, float u) {
  const float* it = std::upper_bound(cdf, cdf + count + 1, u);
  return std::clamp(int(it - cdf) - 1, 0, count - 1);
}

}  // namespace

EquirectSampler::EquirectSampler(int width, int height, const std::vector<float>& weights, const glm::mat3& to_world)
    : width_(width), height_(height), to_world_(to_world), to_table_(glm::transpose(to_world)) {
  const std::size_t count = std::size_t(width) * std::size_t(height);
  double mean = 0.0;
  for (std::size_t i = 0; i < count; ++i) mean += std::max(weights[i], 0.0f);
  mean = count ? mean / double(count) : 0.0;
  const double floor = mean > 0.0 ? 1e-3 * mean : 1.0;

  std::vector<double> texel(count);
  std::vector<double> row_sum(std::size_t(height), 0.0);
  for (int y = 0; y < height; ++y) {
    const double sin_theta = std::sin(kPi * (y + 0.5) / height);
    for (int x = 0; x < width; ++x) {
      const std::size_t i = std::size_t(y) * std::size_t(width) + std::size_t(x);
      texel[i] = (std::max(double(weights[i]), 0.0) + floor) * sin_theta;
      row_sum[std::size_t(y)] += texel[i];
    }
  }
  double total = 0.0;
  for (double r : row_sum) total += r;

  row_cdf_.assign(std::size_t(height) + 1, 0.0f);
  column_cdf_.assign(std::size_t(height) * std::size_t(width + 1), 0.0f);
  texel_probability_.assign(count, 0.0f);
  double running = 0.0;
  for (int y = 0; y < height; ++y) {
    running += row_sum[std::size_t(y)];
    row_cdf_[std::size_t(y) + 1] = float(running / total);
    float* cdf = &column_cdf_[std::size_t(y) * std::size_t(width + 1)];
    double in_row = 0.0;
    for (int x = 0; x < width; ++x) {
      const std::size_t i = std::size_t(y) * std::size_t(width) + std::size_t(x);
      in_row += texel[i];
      cdf[x + 1] = float(in_row / row_sum[std::size_t(y)]);
      texel_probability_[i] = float(texel[i] / total);
    }
    cdf[width] = 1.0f;
  }
  row_cdf_[std::size_t(height)] = 1.0f;
}

glm::vec3 EquirectSampler::sample(const glm::vec2& u, float& pdf_out) const {
  const int y = find_bin(row_cdf_.data(), height_, u.x);
  const float* cdf = &column_cdf_[std::size_t(y) * std::size_t(width_ + 1)];
  // Reuse u.x's position inside the chosen row bin for the column: stays uniform, saves a number.
  const float row_width = row_cdf_[std::size_t(y) + 1] - row_cdf_[std::size_t(y)];
  const float u_column = row_width > 0.0f ? std::clamp((u.x - row_cdf_[std::size_t(y)]) / row_width, 0.0f, 0.99999994f) : 0.5f;
  const int x = find_bin(cdf, width_, u_column);
  const float column_width = cdf[x + 1] - cdf[x];
  const float tx = column_width > 0.0f ? std::clamp((u_column - cdf[x]) / column_width, 0.0f, 1.0f) : 0.5f;
  const glm::vec2 uv((float(x) + tx) / float(width_), (float(y) + u.y) / float(height_));
  const glm::vec3 direction = to_world_ * scene::equirect_direction(uv);
  pdf_out = pdf(direction);
  return direction;
}

float EquirectSampler::pdf(const glm::vec3& direction) const {
  if (empty()) return 0.0f;
  const glm::vec3 local = to_table_ * direction;
  const glm::vec2 uv = scene::equirect_uv(local);
  const int x = std::clamp(int(uv.x * float(width_)), 0, width_ - 1);
  const int y = std::clamp(int(uv.y * float(height_)), 0, height_ - 1);
  const float sin_theta = std::sqrt(std::max(0.0f, 1.0f - local.y * local.y));  // theta from +Y
  if (sin_theta <= 1e-7f) return 0.0f;
  return texel_probability_[std::size_t(y) * std::size_t(width_) + std::size_t(x)] * float(width_) * float(height_) /
         (2.0f * kPi * kPi * sin_theta);
}

}  // namespace proxygi::ref
