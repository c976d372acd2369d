#pragma once
// Importance sampling of a distant environment from a tabulated equirectangular image
// (scene/environment.h mapping: u, v in [0, 1], v = 0 the zenith, texel (i, j) covering
// [i/W, (i+1)/W] x [j/H, (j+1)/H]).
//
// Each texel is chosen with probability proportional to weight(i, j) * sin(theta_center) (its
// share of the power; weight = luminance, floored at a small fraction of the mean so no direction
// with light is impossible), then a point uniform in the texel's (u, v) rectangle. As a density
// over directions: pdf(d) = p_texel * W * H / (2 pi^2 sin theta). The sampled radiance is always
// evaluated from the true environment, so the table only shapes variance, never the mean.
#include <vector>

#include <glm/glm.hpp>

namespace proxygi::ref {

class EquirectSampler {
 public:
  EquirectSampler() = default;
  // weights: width * height non-negative values, row-major, top row first. `to_world` rotates
  // table directions (the table's frame) into world space.
  EquirectSampler(int width, int height, const std::vector<float>& weights, const glm::mat3& to_world = glm::mat3(1.0f));

  bool empty() const { return width_ == 0; }
  // A world direction and its pdf (per steradian) from two uniform numbers.
  glm::vec3 sample(const glm::vec2& u, float& pdf) const;
  // The pdf with which sample() produces world direction `direction`.
  float pdf(const glm::vec3& direction) const;

 private:
  int width_ = 0, height_ = 0;
  std::vector<float> row_cdf_;     // height + 1 values, 0 .. 1
  std::vector<float> column_cdf_;  // per row, width + 1 values, 0 .. 1
  std::vector<float> texel_probability_;
  glm::mat3 to_world_{1.0f};
  glm::mat3 to_table_{1.0f};
};

}  // namespace proxygi::ref
