// Environment projection (equirectangular images in memory and on disk, analytic sky) and LH(N).
#include <cmath>
#include <filesystem>
#include <fstream>
#include <vector>

#include <gtest/gtest.h>

#include "image/image.h"
#include "sh/basis.h"
#include "sh/convolution.h"
#include "sh/environment.h"
#include "sh/product.h"
#include "sh/quadrature.h"

namespace proxygi::sh {
namespace {

// A band-limited test radiance: 1 + 0.5 y + 0.3 x z (order 3), written into an equirect image.
double test_radiance(const glm::dvec3& d) { return 1.0 + 0.5 * d.y + 0.3 * d.x * d.z; }

image::ImageF equirect_of(int width, int height) {
  image::ImageF image(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const float value = float(test_radiance(equirect_direction((x + 0.5) / width, (y + 0.5) / height)));
      image.at(x, y) = glm::vec4(value, 2.0f * value, 0.5f * value, 1.0f);
    }
  return image;
}

std::vector<double> expected_projection(int order) {
  return project_function(order, make_sphere_quadrature(order + 2, 2 * order + 4), test_radiance);
}

TEST(ShEnvironment, EquirectConventionLooksAlongMinusZAtTheCentre) {
  EXPECT_NEAR(glm::distance(equirect_direction(0.5, 0.5), glm::dvec3(0, 0, -1)), 0.0, 1e-12);
  EXPECT_NEAR(glm::distance(equirect_direction(0.75, 0.5), glm::dvec3(1, 0, 0)), 0.0, 1e-12);
  EXPECT_NEAR(equirect_direction(0.3, 0.0).y, 1.0, 1e-12);
}

TEST(ShEnvironment, ProjectsAnInMemoryEquirectImage) {
  const RgbSh sh = project_equirect(4, equirect_of(256, 128));
  const std::vector<double> expected = expected_projection(4);
  for (int i = 0; i < 16; ++i) {
    EXPECT_NEAR(sh.channels[0][std::size_t(i)], expected[std::size_t(i)], 2e-3) << i;
    EXPECT_NEAR(sh.channels[1][std::size_t(i)], 2.0 * expected[std::size_t(i)], 4e-3) << i;
  }
}

TEST(ShEnvironment, ProjectsExrAndHdrFiles) {
  const std::filesystem::path folder = PROXYGI_TEST_OUTPUT_DIR;
  std::filesystem::create_directories(folder);
  const image::ImageF image = equirect_of(128, 64);
  const std::filesystem::path exr = folder / "sh_environment.exr";
  ASSERT_TRUE(image::write_exr(exr, image).ok());
  // A flat (uncompressed) Radiance RGBE file, written by hand.
  const std::filesystem::path hdr = folder / "sh_environment.hdr";
  {
    std::ofstream file(hdr, std::ios::binary);
    file << "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y " << image.height << " +X " << image.width << "\n";
    for (const glm::vec4& p : image.pixels) {
      const float largest = std::max({p.r, p.g, p.b});
      int exponent = 0;
      const float mantissa = std::frexp(largest, &exponent) * 256.0f / largest;
      const auto quantize = [&](float v) { return static_cast<unsigned char>(std::min(v * mantissa + 0.5f, 255.0f)); };
      const unsigned char rgbe[4] = {quantize(p.r), quantize(p.g), quantize(p.b), static_cast<unsigned char>(exponent + 128)};
      file.write(reinterpret_cast<const char*>(rgbe), 4);
    }
  }
  const std::vector<double> expected = expected_projection(3);
  for (const std::filesystem::path& path : {exr, hdr}) {
    const Result<RgbSh> sh = project_equirect_file(3, path);
    ASSERT_TRUE(sh.ok()) << sh.message();
    // RGBE keeps 8 mantissa bits: about 0.4 % per pixel.
    for (int i = 0; i < 9; ++i) EXPECT_NEAR(sh->channels[0][std::size_t(i)], expected[std::size_t(i)], 1e-2) << path << " " << i;
  }
  EXPECT_FALSE(project_equirect_file(3, folder / "missing.hdr").ok());
}

TEST(ShEnvironment, SkyProjectionMatchesBruteForceQuadrature) {
  AnalyticSky sky;
  sky.sun_radius_radians = 0.2;  // large enough for a brute-force grid to see it
  const RgbSh sh = project_sky(4, sky);
  const std::vector<double> brute = project_function(4, make_sphere_quadrature(800, 1600), [&](const glm::dvec3& d) { return sky.radiance(d).r; });
  for (int i = 0; i < 16; ++i) EXPECT_NEAR(sh.channels[0][std::size_t(i)], brute[std::size_t(i)], 0.02 * std::abs(brute[0])) << i;
}

TEST(ShEnvironment, SunDiscAddsToTheSkyUnderIt) {
  // scene/environment.h and the path tracer add the disc on top of the gradient; the projection
  // must too: with the sun minus without it is sun_radiance × the disc, whatever the sky under it.
  AnalyticSky sky;
  sky.sun_radius_radians = 0.3;
  sky.sun_radiance = glm::dvec3(2.0, 1.5, 1.0);  // comparable to the sky, so a replaced sky shows
  AnalyticSky dark = sky;
  dark.sun_radiance = glm::dvec3(0.0);
  const RgbSh with_sun = project_sky(4, sky), without_sun = project_sky(4, dark);
  const std::vector<double> disc = project_function(4, make_sphere_quadrature(800, 1600), [&](const glm::dvec3& d) {
    return glm::dot(d, sky.sun_direction) >= std::cos(sky.sun_radius_radians) ? 1.0 : 0.0;
  });
  const RgbSh sun = project_sun_disc(4, sky);
  for (int c = 0; c < 3; ++c)
    for (int i = 0; i < 16; ++i) {
      const std::size_t k = std::size_t(i);
      EXPECT_NEAR(with_sun.channels[std::size_t(c)][k] - without_sun.channels[std::size_t(c)][k],
                  sky.sun_radiance[c] * disc[k], 2e-3 * sky.sun_radiance[c]) << c << " " << i;
      EXPECT_NEAR(sun.channels[std::size_t(c)][k], with_sun.channels[std::size_t(c)][k] - without_sun.channels[std::size_t(c)][k], 1e-12);
    }
  EXPECT_EQ(sky.radiance(sky.sun_direction), sky.radiance_without_sun(sky.sun_direction) + sky.sun_radiance);
}

TEST(ShEnvironment, LightingTimesClampedCosineMatchesHighOrderProjection) {
  // L band-limited (order 3); LH(N) is the order-3 projection of L(s) max(N.s, 0). Reference:
  // integrate over the hemisphere about N = +z with a cap rule (exact for the polynomial).
  const int order = 3;
  const std::vector<double> lighting = expected_projection(order);
  const glm::dvec3 normal(0, 0, 1);
  const std::vector<double> lh = lighting_times_clamped_cosine(order, lighting, normal);
  const std::vector<double> reference = project_function(order, make_cap_quadrature(0.0, 12, 24),
                                                         [](const glm::dvec3& d) { return test_radiance(d) * d.z; });
  for (int i = 0; i < 9; ++i) EXPECT_NEAR(lh[std::size_t(i)], reference[std::size_t(i)], 1e-12) << i;
  // Irradiance: 1 . LH(N) = H(N) . L.
  const std::vector<double> h = clamped_cosine_about(order, normal);
  double irradiance = 0.0;
  for (int i = 0; i < 9; ++i) irradiance += h[std::size_t(i)] * lighting[std::size_t(i)];
  EXPECT_NEAR(lh[0] * kSqrtFourPi, irradiance, 1e-12);
}

TEST(ShEnvironment, CubeMapFollowsTheVulkanFaceConvention) {
  EXPECT_NEAR(glm::distance(cube_map_direction(0, 1, 1, 3), glm::dvec3(1, 0, 0)), 0.0, 1e-12);
  EXPECT_NEAR(glm::distance(cube_map_direction(3, 1, 1, 3), glm::dvec3(0, -1, 0)), 0.0, 1e-12);
  EXPECT_GT(cube_map_direction(4, 2, 1, 3).x, 0.0);  // +Z face: s grows with +x
  EXPECT_LT(cube_map_direction(4, 1, 2, 3).y, 0.0);  // t grows with -y
  const std::vector<double> lighting = expected_projection(4);
  const LightingCubeMap map = make_lighting_cube_map(4, lighting, 4);
  ASSERT_EQ(map.values.size(), 6u * 4u * 4u * 16u);
  const std::vector<double> texel = lighting_times_clamped_cosine(4, lighting, cube_map_direction(2, 3, 1, 4));
  const std::size_t offset = ((2 * 4 + 1) * 4 + 3) * 16;
  for (int i = 0; i < 16; ++i) EXPECT_NEAR(map.values[offset + std::size_t(i)], texel[std::size_t(i)], 1e-6);
}

}  // namespace
}  // namespace proxygi::sh
