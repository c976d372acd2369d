// VSSA's teleport (proxies/teleport.h) on two synthetic parts in one mesh: a long bar (a limb
// stand-in, one bloated sphere) and a small cube (two spheres where one does): the teleport must
// move the cube's redundant sphere onto the bar, keeping the count and lowering the outside volume.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>

#include "proxies/box_lattice.h"
#include "proxies/mesh_index.h"
#include "proxies/point_sampling.h"
#include "proxies/sphere_set_fit.h"
#include "proxies/teleport.h"
#include "proxies/test_shapes.h"

namespace proxygi::proxies {
namespace {

const testing::AxisBox kBar{{-0.5f, -0.05f, -0.05f}, {0.5f, 0.05f, 0.05f}};
const testing::AxisBox kCube{{-0.05f, 0.45f, -0.05f}, {0.05f, 0.55f, 0.05f}};

struct TwoParts {
  TriangleSoup soup;
  WindingIndex winding;
  DistanceGrid grid;
  std::vector<glm::vec3> points;
  std::vector<std::uint32_t> bar, cube;
  std::vector<glm::vec3> ball = unit_ball_points(96);
  std::vector<glm::vec3> directions = fibonacci_directions(128);
  SphereObjective objective;

  TwoParts() {
    for (const testing::AxisBox& box : {kBar, kCube}) testing::add_to_soup(soup, testing::box_primitive(box.lo, box.hi));
    winding.build(soup, 16);
    grid = build_distance_grid(soup, winding, Box{kBar.lo, kCube.hi}, 0.01f, 0.6f);
    objective = {&grid, ball, directions, 0.02f, 0.05f};
    bar = testing::add_box_lattice(points, kBar);
    cube = testing::add_box_lattice(points, kCube);
  }
  // The bar with one sphere, the cube with two.
  std::vector<std::unique_ptr<BoneSphereSet>> start() const {
    std::vector<std::unique_ptr<BoneSphereSet>> sets;
    sets.push_back(std::make_unique<BoneSphereSet>(points, bar, objective));
    sets.push_back(std::make_unique<BoneSphereSet>(points, cube, objective));
    EXPECT_TRUE(sets[1]->split(0, 6));
    return sets;
  }
};

// Exact volume of the union of every set's spheres outside both boxes, m³ (5 mm lattice).
float union_outside_volume(const std::vector<std::unique_ptr<BoneSphereSet>>& sets) {
  std::vector<ClusterSphere> spheres;
  for (const auto& set : sets) spheres.insert(spheres.end(), set->spheres().begin(), set->spheres().end());
  const testing::AxisBox boxes[] = {kBar, kCube};
  return testing::union_outside_volume(spheres, boxes);
}

std::size_t sphere_count(const std::vector<std::unique_ptr<BoneSphereSet>>& sets) {
  std::size_t n = 0;
  for (const auto& set : sets) n += set->spheres().size();
  return n;
}

TEST(Teleport, MovesTheRedundantSphereToWhereTheSpheresBulgeMost) {
  const TwoParts parts;
  auto sets = parts.start();
  ASSERT_EQ(sets[0]->spheres().size(), 1u);
  ASSERT_EQ(sets[1]->spheres().size(), 2u);
  const float exact_before = union_outside_volume(sets);
  TeleportJob job;
  job.sets = sets;
  job.tolerance = 0.05f;
  job.rounds = 1;
  TeleportStats stats;
  job.stats = &stats;
  ASSERT_TRUE(job.run().ok());
  EXPECT_EQ(stats.moves, 1);
  // One sphere left the cube for the bar: same count, the bar now a chain of two.
  EXPECT_EQ(sets[0]->spheres().size(), 2u);
  EXPECT_EQ(sets[1]->spheres().size(), 1u);
  EXPECT_LT(stats.outside_after, stats.outside_before);
  const float exact_after = union_outside_volume(sets);
  EXPECT_LT(exact_after, 0.8f * exact_before) << exact_before << " -> " << exact_after;
}

TEST(Teleport, KeepsTheCountAndNeverRaisesTheOutsideVolume) {
  const TwoParts parts;
  for (int worsening : {0, 3}) {
    auto sets = parts.start();
    const std::size_t count = sphere_count(sets);
    TeleportJob job;
    job.sets = sets;
    job.tolerance = 0.05f;
    job.rounds = 8;
    job.candidates = 2;
    job.worsening = worsening;
    TeleportStats stats;
    job.stats = &stats;
    ASSERT_TRUE(job.run().ok());
    EXPECT_EQ(sphere_count(sets), count) << "worsening " << worsening;
    EXPECT_LE(stats.outside_after, stats.outside_before) << "worsening " << worsening;
    EXPECT_LE(stats.kept, stats.moves);
  }
}

// Allowing worsening moves continues from where the greedy teleport stops and keeps the best
// state seen, so it never ends above the greedy result.
TEST(Teleport, WorseningMovesEndNoWorseThanTheGreedyTeleport) {
  const TwoParts parts;
  auto greedy = parts.start();
  auto explore = parts.start();
  TeleportJob job;
  job.tolerance = 0.05f;
  job.rounds = 12;
  TeleportStats greedy_stats, explore_stats;
  job.sets = greedy;
  job.stats = &greedy_stats;
  ASSERT_TRUE(job.run().ok());
  job.sets = explore;
  job.worsening = 4;
  job.stats = &explore_stats;
  ASSERT_TRUE(job.run().ok());
  EXPECT_GE(explore_stats.moves, greedy_stats.moves);
  EXPECT_LE(explore_stats.outside_after, greedy_stats.outside_after + 1e-9f);
}

TEST(Teleport, RejectsNullSetsAndBadOptions) {
  std::vector<std::unique_ptr<BoneSphereSet>> sets(1);
  TeleportJob job;
  job.sets = sets;
  job.tolerance = 0.05f;
  EXPECT_FALSE(job.validate().ok());
  const TwoParts parts;
  auto good = parts.start();
  job.sets = good;
  EXPECT_TRUE(job.validate().ok());
  for (auto bad : {+[](TeleportJob& j) { j.tolerance = 0.0f; }, +[](TeleportJob& j) { j.rounds = -1; },
                   +[](TeleportJob& j) { j.candidates = 0; }, +[](TeleportJob& j) { j.worsening = -1; },
                   +[](TeleportJob& j) { j.lloyd_iterations = 0; }}) {
    TeleportJob copy = job;
    bad(copy);
    EXPECT_FALSE(copy.validate().ok());
    EXPECT_FALSE(copy.run().ok());
  }
}

}  // namespace
}  // namespace proxygi::proxies
