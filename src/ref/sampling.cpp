#include "ref/sampling.h"

#include <algorithm>
#include <cmath>

namespace proxygi::ref {

std::uint32_t pcg_hash(std::uint32_t value) {
  const std::uint32_t state = value * 747796405u + 2891336453u;
  const std::uint32_t word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
  return (word >> 22u) ^ word;
}

SampleStream::SampleStream(std::uint32_t seed, std::uint32_t pixel, std::uint32_t sample)
    // Chained hashing: each counter is folded in after the previous ones were scrambled, so
    // nearby (pixel, sample) pairs give unrelated keys.
    : key_(pcg_hash(pcg_hash(pcg_hash(seed) ^ pixel) ^ (sample * 0x9E3779B9u))) {}

float SampleStream::next_float() {
  const std::uint32_t bits = pcg_hash(key_ ^ pcg_hash(dimension_++));
  return static_cast<float>(bits >> 8) * (1.0f / 16777216.0f);
}

Frame::Frame(const glm::vec3& unit_normal) : normal(unit_normal) {
  const float sign = std::copysign(1.0f, unit_normal.z);
  const float a = -1.0f / (sign + unit_normal.z);
  const float b = unit_normal.x * unit_normal.y * a;
  tangent = glm::vec3(1.0f + sign * unit_normal.x * unit_normal.x * a, sign * b, -sign * unit_normal.x);
  bitangent = glm::vec3(b, sign + unit_normal.y * unit_normal.y * a, -unit_normal.y);
}

glm::vec3 sample_cosine_hemisphere(const glm::vec3& normal, const glm::vec2& u) {
  // Concentric map of the unit square onto the disc (Shirley-Chiu), then lift to the hemisphere.
  const glm::vec2 offset = 2.0f * u - glm::vec2(1.0f);
  glm::vec2 disc(0.0f);
  if (offset.x != 0.0f || offset.y != 0.0f) {
    float radius, theta;
    if (std::abs(offset.x) > std::abs(offset.y)) {
      radius = offset.x;
      theta = (kPi / 4.0f) * (offset.y / offset.x);
    } else {
      radius = offset.y;
      theta = kPi / 2.0f - (kPi / 4.0f) * (offset.x / offset.y);
    }
    disc = radius * glm::vec2(std::cos(theta), std::sin(theta));
  }
  const float z = std::sqrt(std::max(0.0f, 1.0f - glm::dot(disc, disc)));
  return glm::normalize(Frame(normal).to_world(glm::vec3(disc, z)));
}

glm::vec3 sample_uniform_cone(const glm::vec3& axis, float cos_max, const glm::vec2& u) {
  const float cos_theta = 1.0f - u.x * (1.0f - cos_max);
  const float sin_theta = std::sqrt(std::max(0.0f, 1.0f - cos_theta * cos_theta));
  const float phi = 2.0f * kPi * u.y;
  return glm::normalize(Frame(axis).to_world(glm::vec3(sin_theta * std::cos(phi), sin_theta * std::sin(phi), cos_theta)));
}

float uniform_cone_pdf(float cos_max) { return 1.0f / (2.0f * kPi * (1.0f - cos_max)); }

glm::vec3 sample_uniform_sphere(const glm::vec2& u) {
  const float z = 1.0f - 2.0f * u.x;
  const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
  const float phi = 2.0f * kPi * u.y;
  return {r * std::cos(phi), r * std::sin(phi), z};
}

}  // namespace proxygi::ref
