#include "render/exact_indirect.h"

#include <algorithm>
#include <cmath>
#include <span>

#include "base/check.h"
#include "sh/basis.h"

namespace proxygi::render {
namespace {

constexpr float kPi = 3.14159265358979f;
constexpr float kHalfSqrt2 = 0.70710678f;
// Band-2 basis constants (notes/sh-math.md §1): y_2,-2 = c1 xy, y_2,0 = c0 (3z² − 1), y_2,2 = c2 (x² − y²).
constexpr float kBand2Off = 1.092548430592079f;   // c1
constexpr float kBand2Zonal = 0.315391565252520f; // c0
constexpr float kBand2Sector = 0.546274215296040f; // c2

}  // namespace

std::array<glm::vec3, 3> rotation_to_z(const glm::vec3& direction) {
  const float sign = direction.z >= 0.0f ? 1.0f : -1.0f;
  const float a = -1.0f / (sign + direction.z);
  const float b = direction.x * direction.y * a;
  return {glm::vec3(1.0f + sign * direction.x * direction.x * a, sign * b, -sign * direction.x),
          glm::vec3(b, sign + direction.y * direction.y * a, -direction.y), direction};
}

std::array<float, 9> exact_indirect_weights(const sh::ExactIndirectTable& table, float s, const glm::vec3& direction,
                                            const glm::vec3& normal) {
  PROXYGI_CHECK(table.order == 3 && table.rows >= 2, "the exact indirect table must be order 3 with >= 2 rows");
  const std::array<glm::vec3, 3> rotation = rotation_to_z(direction);
  auto to_canonical = [&](const glm::vec3& v) {
    return glm::vec3(glm::dot(v, rotation[0]), glm::dot(v, rotation[1]), glm::dot(v, rotation[2]));
  };

  // H(R N): the clamped cosine h_l rotated to the canonical normal.
  float cosine_lobe[9];
  sh::evaluate_basis(3, to_canonical(normal), std::span<float>(cosine_lobe, 9));
  const float cosine[3] = {0.886226925f, 1.023326708f, 0.495415912f};
  for (int l = 0; l < 3; ++l)
    for (int m = -l; m <= l; ++m) cosine_lobe[l * (l + 1) + m] *= std::sqrt(4.0f * kPi / float(2 * l + 1)) * cosine[l];

  // w = M(s)ᵀ H(R N) over the non-zero entries, M interpolated between rows like ZONAL_LOOKUP.
  const float position = std::clamp(s, 0.0f, 1.0f) * float(table.rows - 1);
  const int row = std::min(int(position), table.rows - 2);
  const float t = position - float(row);
  const float* low = table.values.data() + std::size_t(row) * 81;
  const float* high = low + 81;
  float w[9] = {};
  for (const int entry : kExactIndirectEntries)
    w[entry % 9] += cosine_lobe[entry / 9] * (low[entry] + t * (high[entry] - low[entry]));

  std::array<float, 9> weights{};
  weights[0] = w[0];
  // Band 1: w_1 · y_1(v) = 0.4886 u · v with u = (−w_1,1, −w_1,−1, w_1,0); W(ω) = w(R ω) gives Rᵀ u.
  const glm::vec3 u(-w[3], -w[1], w[2]);
  const glm::vec3 world = u.x * rotation[0] + u.y * rotation[1] + u.z * rotation[2];
  weights[1] = -world.y;
  weights[2] = world.z;
  weights[3] = -world.x;
  // Band 2: b_k = w_2 · y_2(R ω_k), then the closed-form inverse of y_2m(ω_k).
  const glm::vec3 directions[5] = {{1.0f, 0.0f, 0.0f},
                                   {0.0f, 0.0f, 1.0f},
                                   {kHalfSqrt2, kHalfSqrt2, 0.0f},
                                   {kHalfSqrt2, 0.0f, kHalfSqrt2},
                                   {0.0f, kHalfSqrt2, kHalfSqrt2}};
  float b[5];
  for (int k = 0; k < 5; ++k) {
    float basis[9];
    sh::evaluate_basis(3, to_canonical(directions[k]), std::span<float>(basis, 9));
    b[k] = 0.0f;
    for (int i = 4; i < 9; ++i) b[k] += w[i] * basis[i];
  }
  weights[4] = (2.0f * b[2] + b[1]) / kBand2Off;
  weights[5] = (-b[0] - 2.0f * b[4]) / kBand2Off;
  weights[6] = b[1] / (2.0f * kBand2Zonal);
  weights[7] = (b[0] + b[1] - 2.0f * b[3]) / kBand2Off;
  weights[8] = (b[0] + 0.5f * b[1]) / kBand2Sector;
  return weights;
}

}  // namespace proxygi::render
