// The reference sampler: Owen-scrambled Sobol pairs are (0,2)-nets for every power-of-two prefix,
// deterministic, and give the same image means as plain Monte Carlo within noise, with less
// noise at equal samples per pixel.
#include <cmath>
#include <set>
#include <vector>

#include <gtest/gtest.h>

#include "ref/embree_scene.h"
#include "ref/path_tracer.h"
#include "ref/path_tracer_lighting.h"
#include "ref/reference_render.h"
#include "ref/sampling.h"
#include "ref/scene_geometry.h"
#include "small_scene.h"

namespace proxygi::ref {
namespace {

// Every elementary interval [a/2^i, (a+1)/2^i) × [b/2^j, (b+1)/2^j) with i + j = m holds exactly
// one of the first 2^m points (the (0,m,2)-net property Owen scrambling preserves).
TEST(SobolSampler, PowerOfTwoPrefixesAreZeroTwoNets) {
  for (std::uint32_t key : {0u, 1u, 12345u, 0xdeadbeefu})
    for (int m : {4, 7, 10}) {
      const std::uint32_t count = 1u << m;
      for (int i = 0; i <= m; ++i) {
        std::set<std::uint64_t> cells;
        for (std::uint32_t s = 0; s < count; ++s) {
          const glm::uvec2 p = sobol_owen_2d(s, key);
          const std::uint64_t x = i == 0 ? 0 : p.x >> (32 - i), y = m - i == 0 ? 0 : p.y >> (32 - (m - i));
          cells.insert((x << 32) | y);
        }
        EXPECT_EQ(cells.size(), count) << "key " << key << ", m " << m << ", " << i << " bits in x";
      }
    }
}

TEST(SobolSampler, StreamsAreDeterministicAndSeedDependent) {
  SampleStream a(3u, 17u, 5u), b(3u, 17u, 5u), c(4u, 17u, 5u), d(3u, 18u, 5u);
  const glm::vec2 pa = a.next_2d(), pb = b.next_2d(), pc = c.next_2d(), pd = d.next_2d();
  EXPECT_EQ(pa, pb);
  EXPECT_NE(pa, pc);
  EXPECT_NE(pa, pd);
  EXPECT_NE(a.next_2d(), pa);  // the next pair is another (decorrelated) 2-D sequence
  for (int i = 0; i < 64; ++i) {
    const float u = a.next_float();
    EXPECT_GE(u, 0.0f);
    EXPECT_LT(u, 1.0f);
  }
}

// Same scene, two samplers, two seeds each: the image means agree within noise (per pixel and
// over the image), and Sobol's variance of the mean, estimated from its two seeds, is lower.
TEST(SobolSampler, SameMeansAsRandomWithinNoiseAndLessNoise) {
  const EmbreeScene geometry = test_scenes::small_scene();
  const scene::Environment environment;  // analytic sky with a sun: both light strategies
  const EnvironmentLight light = EnvironmentLight::analytic_sky(environment);
  const PathTracer tracer(geometry, light, light, PathTracerSettings{LightTransport::one_bounce});
  const scene::CameraState camera = test_scenes::small_camera();
  RenderJob job;
  job.width = 24;
  job.height = 20;
  job.spp = 64;
  auto render = [&](Sampler sampler, std::uint32_t seed) {
    job.sampler = sampler;
    job.seed = seed;
    auto sums = render_samples(tracer, camera, job);
    EXPECT_TRUE(sums.ok());
    return to_images(*sums);
  };
  const ReferenceImages random_a = render(Sampler::random, 1), random_b = render(Sampler::random, 2);
  const ReferenceImages sobol_a = render(Sampler::sobol, 1), sobol_b = render(Sampler::sobol, 2);
  double random_sum = 0.0, sobol_sum = 0.0, random_var = 0.0, two_seed_random = 0.0, two_seed_sobol = 0.0;
  int outliers = 0, values = 0;
  for (std::size_t i = 0; i < random_a.radiance.pixels.size(); ++i)
    for (int c = 0; c < 3; ++c) {
      const double ra = random_a.radiance.pixels[i][c], rb = random_b.radiance.pixels[i][c];
      const double sa = sobol_a.radiance.pixels[i][c], sb = sobol_b.radiance.pixels[i][c];
      // Random's per-pixel variance of the mean is valid (independent samples); it bounds Sobol's.
      const double var = 0.5 * (random_a.variance.pixels[i][c] + random_b.variance.pixels[i][c]);
      random_sum += ra + rb;
      sobol_sum += sa + sb;
      random_var += var;
      two_seed_random += 0.5 * (ra - rb) * (ra - rb);
      two_seed_sobol += 0.5 * (sa - sb) * (sa - sb);
      // Means of two seeds each: variance of the difference <= var/2 + var/2.
      if (std::abs(0.5 * (sa + sb) - 0.5 * (ra + rb)) > 4.0 * std::sqrt(var) + 1e-6) ++outliers;
      ++values;
    }
  EXPECT_LE(outliers, values / 100 + 1) << "pixels whose means differ by more than 4 sigma";
  // Image means: the difference's standard error from the pixels' variances (pixels independent).
  const double n = values;
  const double sigma = std::sqrt(random_var) / n;  // of (sum over both seeds / 2n) difference, conservative
  EXPECT_NEAR(sobol_sum / (2.0 * n), random_sum / (2.0 * n), 4.0 * sigma);
  EXPECT_LT(two_seed_sobol, two_seed_random);
}

}  // namespace
}  // namespace proxygi::ref
