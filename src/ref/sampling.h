#pragma once
// Random numbers and direction sampling for the reference path tracer.
//
// Random numbers are counter-based: every value is a pure function of
// (seed, pixel index, sample index, dimension), so an image is bit-identical whatever the number
// of threads, the tile order, or how the samples were split over resumed runs. Two samplers:
// - Sampler::sobol (default): each pair of dimensions (2k, 2k+1) is the 2-D Sobol (0,2)-sequence
//   over the sample index, Owen-scrambled (nested uniform scrambling by Laine–Karras hashing)
//   with a key from (seed, pixel, pair), its index shuffled per pair by the same scrambling, so
//   pairs are decorrelated from each other and from other pixels: Burley 2020, "Practical
//   Hash-based Owen Scrambling" (JCGT 9(4)), the "Sobol-Burley" sampler of Blender Cycles. The
//   first 2^m samples of a pixel are stratified in every pair; the integrator draws its numbers
//   in pairs (pixel jitter, sun, environment, BSDF per bounce), so each estimator sees 2-D
//   stratified points.
// - Sampler::random: plain Monte Carlo, the sampler used until 2026-12: PCG's output permutation
//   (O'Neill 2014, "PCG-RXS-M-XS 32") applied to a mixed counter; a stream is seeded from
//   (seed, pixel, sample) by chained hashing and each call draws the next dimension.
// Floats are the top 24 bits / 2^24, in [0, 1).
//
// Directions are unit vectors in world space; pdfs are per unit solid angle (sr^-1).
#include <cstdint>

#include <glm/glm.hpp>

namespace proxygi::ref {

inline constexpr float kPi = 3.14159265358979323846f;

// 32-bit integer hash (PCG RXS-M-XS output function after one LCG step): a bijection with good
// avalanche, used to derive independent streams from counters.
std::uint32_t pcg_hash(std::uint32_t value);

enum class Sampler { sobol, random };
const char* sampler_name(Sampler sampler);  // "sobol", "random"

// One pixel sample's random numbers. Dimensions are consumed in a fixed order by the
// integrator, so the same (seed, pixel, sample) always sees the same numbers.
class SampleStream {
 public:
  SampleStream(std::uint32_t seed, std::uint32_t pixel, std::uint32_t sample, Sampler sampler = Sampler::sobol);
  float next_float();  // uniform in [0, 1); with sobol, one coordinate of the current pair
  glm::vec2 next_2d();  // with sobol: a whole pair (skipping a half-used one)

 private:
  Sampler sampler_;
  std::uint32_t key_;     // random: the stream key; sobol: the (seed, pixel) key
  std::uint32_t sample_;  // sobol: the sample index
  std::uint32_t dimension_ = 0;
};

// Owen-scrambled Sobol point `index` of the 2-D (0,2)-sequence for `key` (the sobol sampler's
// pair), components as 32-bit fixed point (value / 2^32 in [0, 1)).
glm::uvec2 sobol_owen_2d(std::uint32_t index, std::uint32_t key);

// Right-handed orthonormal frame (tangent, bitangent, normal) around a unit normal
// (Duff et al. 2017, "Building an orthonormal basis, revisited").
struct Frame {
  glm::vec3 tangent, bitangent, normal;
  explicit Frame(const glm::vec3& unit_normal);
  glm::vec3 to_world(const glm::vec3& local) const { return tangent * local.x + bitangent * local.y + normal * local.z; }
};

// Cosine-weighted direction about `normal` (Malley's method on a concentric disc).
// pdf = max(cos theta, 0) / pi.
glm::vec3 sample_cosine_hemisphere(const glm::vec3& normal, const glm::vec2& u);
inline float cosine_hemisphere_pdf(float cos_theta) { return cos_theta > 0.0f ? cos_theta / kPi : 0.0f; }

// Uniform direction in the cone {d : dot(d, axis) >= cos_max}; pdf = 1 / (2 pi (1 - cos_max)).
glm::vec3 sample_uniform_cone(const glm::vec3& axis, float cos_max, const glm::vec2& u);
float uniform_cone_pdf(float cos_max);

// Uniform direction on the unit sphere; pdf = 1 / (4 pi).
glm::vec3 sample_uniform_sphere(const glm::vec2& u);

// Veach's power heuristic (beta = 2) for one sample from each of two strategies.
inline float power_heuristic(float pdf_this, float pdf_other) {
  const float a = pdf_this * pdf_this, b = pdf_other * pdf_other;
  return a + b > 0.0f ? a / (a + b) : 0.0f;
}

}  // namespace proxygi::ref
