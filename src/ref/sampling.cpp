#include "ref/sampling.h"

#include <algorithm>
#include <cmath>

namespace proxygi::ref {

std::uint32_t pcg_hash(std::uint32_t value) {
  const std::uint32_t state = value * 747796405u + 2891336453u;
  const std::uint32_t word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
  return (word >> 22u) ^ word;
}

namespace {

float to_unit(std::uint32_t bits) { return static_cast<float>(bits >> 8) * (1.0f / 16777216.0f); }

std::uint32_t reverse_bits(std::uint32_t x) {
  x = ((x >> 1) & 0x55555555u) | ((x & 0x55555555u) << 1);
  x = ((x >> 2) & 0x33333333u) | ((x & 0x33333333u) << 2);
  x = ((x >> 4) & 0x0F0F0F0Fu) | ((x & 0x0F0F0F0Fu) << 4);
  x = ((x >> 8) & 0x00FF00FFu) | ((x & 0x00FF00FFu) << 8);
  return (x >> 16) | (x << 16);
}

// Burley 2020, listing 2 (the Laine–Karras-style hash with his improved constants): a
// permutation of reversed-bit integers in which each bit depends only on the bits below it, so
// in the normal bit order it is a nested uniform (Owen) scramble.
std::uint32_t laine_karras_permutation(std::uint32_t x, std::uint32_t seed) {
  x += seed;
  x ^= x * 0x6c50b47cu;
  x ^= x * 0xb82f1e52u;
  x ^= x * 0xc7afe638u;
  x ^= x * 0x8d22f6e6u;
  return x;
}

std::uint32_t nested_uniform_scramble(std::uint32_t x, std::uint32_t seed) {
  return reverse_bits(laine_karras_permutation(reverse_bits(x), seed));
}

// The first two Sobol dimensions: van der Corput (bit reversal) and the dimension of the
// primitive polynomial x + 1 (direction numbers v_i = v_{i-1} ^ (v_{i-1} >> 1), v_0 = 2^31).
std::uint32_t sobol_dimension_1(std::uint32_t index) {
  std::uint32_t result = 0, direction = 0x80000000u;
  for (; index != 0; index >>= 1, direction ^= direction >> 1)
    if (index & 1u) result ^= direction;
  return result;
}

std::uint32_t hash_combine(std::uint32_t seed, std::uint32_t value) {
  return seed ^ (pcg_hash(value) + 0x9E3779B9u + (seed << 6) + (seed >> 2));
}

}  // namespace

const char* sampler_name(Sampler sampler) { return sampler == Sampler::sobol ? "sobol" : "random"; }

glm::uvec2 sobol_owen_2d(std::uint32_t index, std::uint32_t key) {
  const std::uint32_t shuffled = nested_uniform_scramble(index, hash_combine(key, 0u));
  return {nested_uniform_scramble(reverse_bits(shuffled), hash_combine(key, 1u)),
          nested_uniform_scramble(sobol_dimension_1(shuffled), hash_combine(key, 2u))};
}

SampleStream::SampleStream(std::uint32_t seed, std::uint32_t pixel, std::uint32_t sample, Sampler sampler)
    : sampler_(sampler),
      // Chained hashing: each counter is folded in after the previous ones were scrambled, so
      // nearby (pixel, sample) pairs give unrelated keys. Sobol keys leave the sample out: the
      // sample index walks the sequence.
      key_(sampler == Sampler::random ? pcg_hash(pcg_hash(pcg_hash(seed) ^ pixel) ^ (sample * 0x9E3779B9u))
                                      : pcg_hash(pcg_hash(seed) ^ pixel)),
      sample_(sample) {}

float SampleStream::next_float() {
  if (sampler_ == Sampler::random) return to_unit(pcg_hash(key_ ^ pcg_hash(dimension_++)));
  const std::uint32_t dimension = dimension_++;
  const glm::uvec2 pair = sobol_owen_2d(sample_, hash_combine(key_, dimension >> 1));
  return to_unit(pair[dimension & 1u]);
}

glm::vec2 SampleStream::next_2d() {
  if (sampler_ == Sampler::random) {
    const float a = next_float();
    return {a, next_float()};
  }
  dimension_ += dimension_ & 1u;  // start a fresh pair
  const glm::uvec2 pair = sobol_owen_2d(sample_, hash_combine(key_, dimension_ >> 1));
  dimension_ += 2;
  return {to_unit(pair.x), to_unit(pair.y)};
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
