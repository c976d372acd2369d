// The static meshes' visibility grid (prt/visibility_grid.h): analytic cases. A receiver at the
// foot of a tall wide wall sees half of its upper hemisphere's cosine-weighted sky (exactly half
// by the mirror symmetry of H(+Y) about the wall's plane, so the order-n projection changes
// nothing); far from a small box the grid is proj(1); points inside a mesh are marked and left
// out of the trilinear sum; sampling reproduces the points and is outside beyond them; the
// ground is no occluder; the cache reads back what it wrote and a bad file is recomputed.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "prt/transfer_cache.h"
#include "prt/visibility_grid.h"
#include "prt_scenes.h"
#include "sh/basis.h"
#include "sh/convolution.h"

namespace proxygi::prt {
namespace {

using test::quad;

// The closed box [lo, hi] as six outward-facing quads (no subdivision).
void add_box(StaticReceivers& r, glm::vec3 lo, glm::vec3 hi) {
  const glm::vec3 d = hi - lo, a = glm::vec3(0.5f);
  const float big = 1e3f;
  r.surfaces.push_back(quad("-x", lo, {0, 0, d.z}, {0, d.y, 0}, a, big));
  r.surfaces.push_back(quad("+x", {hi.x, lo.y, lo.z}, {0, d.y, 0}, {0, 0, d.z}, a, big));
  r.surfaces.push_back(quad("-y", lo, {d.x, 0, 0}, {0, 0, d.z}, a, big));
  r.surfaces.push_back(quad("+y", {lo.x, hi.y, lo.z}, {0, 0, d.z}, {d.x, 0, 0}, a, big));
  r.surfaces.push_back(quad("-z", lo, {0, d.y, 0}, {d.x, 0, 0}, a, big));
  r.surfaces.push_back(quad("+z", {lo.x, lo.y, hi.z}, {d.x, 0, 0}, {0, d.y, 0}, a, big));
}

// (V · H(+Y)) / (1 · H(+Y)): the share of an upward receiver's unshadowed irradiance under a
// uniform sky that V leaves.
double sky_share(int order, std::span<const float> v) {
  const std::vector<double> h = sh::clamped_cosine_about(order, glm::dvec3(0, 1, 0));
  double dot = 0.0;
  for (std::size_t i = 0; i < h.size(); ++i) dot += double(v[i]) * h[i];
  return dot / (sh::kSqrtFourPi * h[0]);
}

TEST(PrtVisibilityGrid, FootOfAWallSeesHalfTheSkyAndFarPointsSeeAll) {
  StaticReceivers r;
  add_box(r, {0.0f, 0.0f, -10.0f}, {0.6f, 10.0f, 10.0f});  // a wall 10 m high, 20 m wide, face x = 0
  r.surfaces.push_back(quad("ground", {-12, 0, -12}, {0, 0, 24}, {24, 0, 0}, glm::vec3(0.5f), 1e3f));
  const int order = 4;
  // Points at x = −0.55, −0.05, 0.45 (inside the wall), 0.95, 1.45; z = −10.55 + 0.5 k.
  const VisibilityGridSettings settings{.spacing_m = 0.5f, .margin_m = 0.55f, .directions = 2048};
  auto grid = compute_visibility_grid(r, order, settings, 2);
  ASSERT_TRUE(grid.ok()) << grid.message();
  EXPECT_NEAR(grid->origin.x, -0.55f, 1e-6f);
  EXPECT_EQ(grid->origin.y, 0.0f) << "the ground is no occluder: from y = 0";
  EXPECT_NEAR(grid->origin.z, -10.55f, 1e-5f);
  EXPECT_EQ(grid->size, glm::uvec3(5u, 23u, 44u));
  std::vector<float> v(16);
  // The grid point 5 cm in front of the wall's foot: the wall hides the +x half of the sphere but
  // for its edges 10 m away (a few % of the half's cosine weight).
  const float z = grid->origin.z + 21.0f * 0.5f;
  ASSERT_TRUE(sample_visibility(*grid, {-0.05f, 0.0f, z}, v));
  const double share = sky_share(order, v);
  std::printf("foot of the wall: sky share %.4f\n", share);
  EXPECT_GT(share, 0.5);
  EXPECT_LT(share, 0.53);
  // The point 0.35 m beyond the far face: the other half, a little more open (the edges nearer).
  ASSERT_TRUE(sample_visibility(*grid, {0.95f, 0.0f, z}, v));
  const double far_side = sky_share(order, v);
  EXPECT_GT(far_side, share);
  EXPECT_LT(far_side, 0.53);
  // The point at x = 0.45 is inside (its rays leave through the box's back faces): a receiver
  // 2 cm in front of the face takes only the points at x = −0.05, not the wall's inside.
  EXPECT_EQ(grid->values[((21 * 23 + 1) * 5 + 2) * 16], kInsidePoint) << "(0.45, 0.5, −0.05)";
  EXPECT_GT(grid->values[((21 * 23 + 1) * 5 + 1) * 16], 0.0f) << "(−0.05, 0.5, −0.05) is valid";
  std::vector<float> front(16);
  ASSERT_TRUE(sample_visibility(*grid, {-0.02f, 0.0f, z}, front));
  ASSERT_TRUE(sample_visibility(*grid, {-0.05f, 0.0f, z}, v));
  for (int i = 0; i < 16; ++i) EXPECT_NEAR(front[i], v[i], 1e-5f) << i;
  // Outside the grid: nothing.
  EXPECT_FALSE(sample_visibility(*grid, {-0.6f, 1.0f, 0.0f}, v));
  EXPECT_FALSE(sample_visibility(*grid, {0.0f, -0.01f, 0.0f}, v));

  // Far from a small box the grid is proj(1): a 0.2 m cube seen from 14 m hides 2e-5 of the sphere.
  StaticReceivers small;
  add_box(small, {-0.1f, 0.0f, -0.1f}, {0.1f, 0.2f, 0.1f});
  auto far = compute_visibility_grid(small, order, {.spacing_m = 2.0f, .margin_m = 10.05f, .directions = 1024}, 2);
  ASSERT_TRUE(far.ok()) << far.message();
  ASSERT_TRUE(sample_visibility(*far, far->origin, v));
  EXPECT_NEAR(v[0], sh::kSqrtFourPi, 1e-3);
  for (int i = 1; i < 16; ++i) EXPECT_NEAR(v[i], 0.0f, 1e-3f) << i;
  // The grid point 5 cm off its corner sees much of it.
  ASSERT_TRUE(sample_visibility(*far, {-0.15f, 0.0f, -0.15f}, v));
  EXPECT_LT(v[0], 0.99f * float(sh::kSqrtFourPi));
}

TEST(PrtVisibilityGrid, SamplingReproducesThePointsAndIsDeterministic) {
  StaticReceivers r;
  add_box(r, {0.0f, 0.0f, 0.0f}, {0.5f, 1.0f, 0.5f});
  VisibilityGridSettings settings{.spacing_m = 0.4f, .margin_m = 0.8f, .directions = 256};
  auto one = compute_visibility_grid(r, 3, settings, 1);
  auto two = compute_visibility_grid(r, 3, settings, 2);
  ASSERT_TRUE(one.ok() && two.ok());
  EXPECT_EQ(one->values, two->values) << "the thread count changes nothing";
  const glm::uvec3 q(1, 2, 0);
  const std::size_t index = (std::size_t(q.z) * one->size.y + q.y) * one->size.x + q.x;
  std::vector<float> v(9);
  ASSERT_TRUE(sample_visibility(*one, one->origin + one->spacing * glm::vec3(q), v));
  for (int i = 0; i < 9; ++i) EXPECT_NEAR(v[i], one->values[index * 9 + std::size_t(i)], 1e-5f);
  // Midway between two valid points: their mean.
  const std::size_t next = index + 1;
  ASSERT_TRUE(sample_visibility(*one, one->origin + one->spacing * (glm::vec3(q) + glm::vec3(0.5f, 0, 0)), v));
  for (int i = 0; i < 9; ++i)
    EXPECT_NEAR(v[i], 0.5f * (one->values[index * 9 + std::size_t(i)] + one->values[next * 9 + std::size_t(i)]), 1e-5f);

  EXPECT_FALSE(compute_visibility_grid(r, 3, {.spacing_m = 0.0f}, 1).ok());
  EXPECT_FALSE(compute_visibility_grid(r, 9, settings, 1).ok());
  auto empty = compute_visibility_grid(StaticReceivers{}, 3, settings, 1);
  ASSERT_TRUE(empty.ok());
  EXPECT_FALSE(sample_visibility(*empty, glm::vec3(0.0f), v));
}

TEST(PrtVisibilityGrid, CacheReadsBackWhatItWroteAndRecomputesABadFile) {
  StaticReceivers r;
  add_box(r, {0.0f, 0.0f, 0.0f}, {0.5f, 1.0f, 0.5f});
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "proxygi-visibility-grid-test";
  std::filesystem::remove_all(dir);
  const VisibilityGridSettings settings{.spacing_m = 0.4f, .margin_m = 0.4f, .directions = 64};
  auto first = load_or_compute_visibility_grid(r, 3, settings, dir, 1);
  ASSERT_TRUE(first.ok()) << first.message();
  EXPECT_FALSE(first->from_cache);
  auto second = load_or_compute_visibility_grid(r, 3, settings, dir, 1);
  ASSERT_TRUE(second.ok()) << second.message();
  EXPECT_TRUE(second->from_cache);
  EXPECT_EQ(second->grid.values, first->grid.values);
  EXPECT_EQ(second->grid.size, first->grid.size);
  EXPECT_EQ(second->grid.origin, first->grid.origin);
  // Another spacing is another key.
  EXPECT_NE(visibility_grid_key(r, 3, settings), visibility_grid_key(r, 3, {.spacing_m = 0.3f, .margin_m = 0.4f, .directions = 64}));
  {
    std::fstream f(second->file, std::ios::in | std::ios::out | std::ios::binary);
    f.seekp(40);
    f.put('\x5a');
  }
  auto third = load_or_compute_visibility_grid(r, 3, settings, dir, 1);
  ASSERT_TRUE(third.ok()) << third.message();
  EXPECT_FALSE(third->from_cache) << "a corrupt file is recomputed";
  EXPECT_EQ(third->grid.values, first->grid.values);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace proxygi::prt
