// Reference files: record round trip, resuming from written files, the guided-filtered variant.
#include <filesystem>

#include <gtest/gtest.h>

#include "ref/reference_render_io.h"

namespace proxygi::ref {
namespace {

std::filesystem::path output_dir() {
  const std::filesystem::path dir = std::filesystem::path(PROXYGI_TEST_OUTPUT_DIR) / "path_tracer_io";
  std::filesystem::create_directories(dir);
  return dir;
}

// A 12 x 10 image: left 8 columns covered (a wall facing +Z at depth 3), right 4 see the sky.
PixelFeatures wall_features() {
  PixelFeatures f;
  const int w = 12, h = 10;
  f.mask = image::ImageF(w, h, glm::vec4(0, 0, 0, 1));
  f.albedo = f.normal = f.depth = image::ImageF(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < 8; ++x) {
      f.mask.at(x, y) = glm::vec4(1.0f);
      f.albedo.at(x, y) = glm::vec4(0.5f, 0.5f, 0.5f, 1.0f);
      f.normal.at(x, y) = glm::vec4(0.0f, 0.0f, 1.0f, 1.0f);
      f.depth.at(x, y) = glm::vec4(3.0f, 3.0f, 3.0f, 1.0f);
    }
  return f;
}

SampleSums noisy_sums(const PixelFeatures& features, std::uint32_t samples) {
  SampleSums sums;
  sums.width = features.mask.width;
  sums.height = features.mask.height;
  sums.samples = samples;
  const std::size_t n = std::size_t(sums.width) * std::size_t(sums.height);
  sums.radiance.resize(n);
  sums.radiance_squared.resize(n);
  sums.indirect.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    if (features.mask.pixels[i].r == 0.0f) {  // sky: 2.0 exactly
      sums.radiance[i] = glm::dvec3(2.0 * samples);
      sums.radiance_squared[i] = glm::dvec3(4.0 * samples);
      sums.indirect[i] = glm::dvec3(0.0);
      continue;
    }
    // Direct 1.0, indirect 0.3 with deterministic +-0.2 "noise" alternating per pixel.
    const double indirect = 0.3 + ((i % 2 == 0) ? 0.2 : -0.2);
    sums.indirect[i] = glm::dvec3(indirect * samples);
    sums.radiance[i] = glm::dvec3((1.0 + indirect) * samples);
    sums.radiance_squared[i] = glm::dvec3((1.0 + indirect) * (1.0 + indirect) * samples + 0.01 * (samples - 1));
  }
  return sums;
}

TEST(PathTracerIo, WrittenFilesResumeAndDescribeThemselves) {
  const PixelFeatures features = wall_features();
  const SampleSums sums = noisy_sums(features, 8);
  const ReferenceImages images = to_images(sums);
  const ReferencePaths paths = reference_paths(output_dir() / "wall.exr");
  EXPECT_EQ(paths.depth.filename(), "wall.depth.exr");
  EXPECT_EQ(paths.record.filename(), "wall.json");
  ReferenceRecord record;
  record.scene = "default";
  record.frame = 3;
  record.width = 12;
  record.height = 10;
  record.transport = "one-bounce";
  record.lighting = "sh";
  record.sh_order = 4;
  record.seed = 5;
  record.samples = 8;
  record.rays = 12345;
  ASSERT_TRUE(write_reference(paths, images, features, record, nullptr).ok());

  auto back = read_record(paths.record);
  ASSERT_TRUE(back.ok()) << back.message();
  EXPECT_EQ(back->samples, 8u);
  EXPECT_EQ(back->rays, 12345u);
  EXPECT_EQ(record_mismatch(*back, record), "");
  ReferenceRecord other = record;
  other.seed = 6;
  EXPECT_NE(record_mismatch(*back, other).find("seed"), std::string::npos);

  auto resumed = read_previous_sums(paths, *back);
  ASSERT_TRUE(resumed.ok()) << resumed.message();
  ASSERT_EQ(resumed->samples, 8u);
  for (std::size_t i = 0; i < sums.radiance.size(); ++i) {
    EXPECT_NEAR(resumed->radiance[i].x, sums.radiance[i].x, 1e-5);
    EXPECT_NEAR(resumed->indirect[i].y, sums.indirect[i].y, 1e-5);
    EXPECT_NEAR(resumed->radiance_squared[i].z, sums.radiance_squared[i].z, 1e-4);
  }
}

TEST(PathTracerIo, GuidedFilterSmoothsIndirectKeepsDirectAndSky) {
  const PixelFeatures features = wall_features();
  const ReferenceImages images = to_images(noisy_sums(features, 4));
  GuidedFilterSettings settings;
  settings.radius = 4;
  auto filtered = guided_filter_reference(images, features, settings);
  ASSERT_TRUE(filtered.ok()) << filtered.message();
  for (int y = 2; y < 8; ++y)
    for (int x = 2; x < 6; ++x) {
      // The alternating +-0.2 averages out inside the wall: direct 1.0 + indirect ~0.3.
      EXPECT_NEAR(filtered->at(x, y).g, 1.3f, 0.05f) << x << "," << y;
    }
  for (int y = 0; y < 10; ++y)
    for (int x = 8; x < 12; ++x) EXPECT_EQ(filtered->at(x, y).r, 2.0f);  // the sky is untouched
  for (const glm::vec4& p : filtered->pixels) EXPECT_GE(p.b, 0.0f);
}

}  // namespace
}  // namespace proxygi::ref
