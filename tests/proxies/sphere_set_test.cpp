// The per-bone sphere set on a synthetic bar (a limb stand-in): splitting into a chain, the
// combined-objective assignment and the teleport's removal, against exact box geometry.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "proxies/box_lattice.h"
#include "proxies/fit.h"
#include "proxies/mesh_index.h"
#include "proxies/point_sampling.h"
#include "proxies/quality.h"
#include "proxies/sphere_set_fit.h"
#include "proxies/test_shapes.h"

namespace proxygi::proxies {
namespace {

using testing::box_character;
using testing::box_primitive;

const glm::vec3 kLo(-0.5f, -0.05f, -0.05f), kHi(0.5f, 0.05f, 0.05f);

// The bar's fitting points: a lattice on its faces and inside it (spacing 0.02 m).
std::vector<glm::vec3> bar_points() {
  std::vector<glm::vec3> points;
  testing::add_box_lattice(points, {kLo, kHi});
  return points;
}

struct Bar {
  TriangleSoup soup;
  WindingIndex winding;
  DistanceGrid grid;
  std::vector<glm::vec3> points = bar_points();
  std::vector<glm::vec3> ball = unit_ball_points(96);
  std::vector<glm::vec3> directions = fibonacci_directions(128);
  SphereObjective objective;

  explicit Bar(float slack) {
    testing::add_to_soup(soup, box_primitive(kLo, kHi));
    winding.build(soup, 16);
    grid = build_distance_grid(soup, winding, Box{kLo, kHi}, 0.01f, 0.6f);
    objective = {&grid, ball, directions, slack, 0.05f};
  }
  std::vector<std::uint32_t> all() const {
    std::vector<std::uint32_t> m(points.size());
    for (std::uint32_t i = 0; i < m.size(); ++i) m[i] = i;
    return m;
  }
};

// Largest distance from a point to the union of the set's spheres (0 inside).
float worst_gap(const std::vector<glm::vec3>& points, const BoneSphereSet& set) {
  float worst = 0.0f;
  for (const glm::vec3& p : points) {
    float d = std::numeric_limits<float>::max();
    for (const ClusterSphere& s : set.spheres()) d = std::min(d, glm::length(p - s.center) - s.radius);
    worst = std::max(worst, d);
  }
  return worst;
}

// Exact volume of the union outside the bar, m³, on a 5 mm lattice.
float union_outside_volume(const BoneSphereSet& set) {
  const testing::AxisBox bar[] = {{kLo, kHi}};
  return testing::union_outside_volume(set.spheres(), bar);
}

TEST(SphereSet, ChainOfSmallerSpheresBeatsOneSphereOnOutsideVolumeAtEqualCoverage) {
  const Bar bar(0.02f);
  BoneSphereSet one(bar.points, bar.all(), bar.objective);
  BoneSphereSet chain = one;
  for (int i = 0; i < 5; ++i) ASSERT_TRUE(chain.split(chain.most_outside(), 6));
  ASSERT_EQ(chain.spheres().size(), 6u);
  // Both come within the slack of every point (coverage is the same).
  EXPECT_LE(worst_gap(bar.points, one), 0.02f + 1e-4f);
  EXPECT_LE(worst_gap(bar.points, chain), 0.02f + 1e-4f);
  // Every link is smaller than the bar's bounding sphere, and the chain is far tighter.
  const float bounding = glm::length(kHi - kLo) * 0.5f;
  for (const ClusterSphere& s : chain.spheres()) EXPECT_LT(s.radius, 0.5f * bounding);
  const float one_outside = union_outside_volume(one), chain_outside = union_outside_volume(chain);
  EXPECT_LT(chain_outside, 0.1f * one_outside) << one_outside << " vs " << chain_outside;
  // The fit's own estimate agrees on the order.
  EXPECT_LT(chain.outside_volume(), one.outside_volume());
}

TEST(SphereSet, SlackShrinksSpheresWithinTheirPoints) {
  const Bar tight(0.0f), slack(0.02f);
  const BoneSphereSet bounding(tight.points, tight.all(), tight.objective);
  const BoneSphereSet shrunk(slack.points, slack.all(), slack.objective);
  EXPECT_LE(worst_gap(tight.points, bounding), 1e-4f);  // no slack: every point inside
  EXPECT_LT(shrunk.spheres()[0].radius, bounding.spheres()[0].radius);
  EXPECT_LT(union_outside_volume(shrunk), union_outside_volume(bounding));
}

TEST(SphereSet, RemovalReclustersTheBoneAndKeepsEveryPointCovered) {
  const Bar bar(0.02f);
  BoneSphereSet set(bar.points, bar.all(), bar.objective);
  for (int i = 0; i < 3; ++i) ASSERT_TRUE(set.split(set.most_outside(), 6));
  ASSERT_EQ(set.spheres().size(), 4u);
  const float before = set.outside_volume();
  set.remove(1, 6);
  ASSERT_EQ(set.spheres().size(), 3u);
  std::size_t members = 0;
  for (const ClusterSphere& s : set.spheres()) members += s.members.size();
  EXPECT_EQ(members, bar.points.size());  // the dropped sphere's points joined the others
  EXPECT_LE(worst_gap(bar.points, set), 0.02f + 1e-4f);
  EXPECT_GT(set.outside_volume(), before);  // fewer, larger spheres on a bar bulge more
}

TEST(Fit, OutsideTargetKeepsAThinBarTightAtFullCoverage) {
  const anim::Character ch = box_character(kLo, kHi);
  FitResult fit;
  FitProxiesJob job;
  job.character = &ch;
  job.result = &fit;
  ASSERT_TRUE(job.run().ok());
  const FitQuality q = measure_fit_quality(ch, fit);
  EXPECT_GE(q.coverage, 0.999f);
  EXPECT_LE(q.outside_volume_ratio, 0.30f);
  // Without the target (protrusion alone) the bar keeps fewer, bloated spheres.
  FitResult loose;
  job.options.outside_target = 1.0f;
  job.result = &loose;
  ASSERT_TRUE(job.run().ok());
  const FitQuality lq = measure_fit_quality(ch, loose);
  EXPECT_GT(lq.outside_volume_ratio, q.outside_volume_ratio);
}

TEST(Fit, IsDeterministic) {
  const anim::Character ch = testing::arm_character();
  FitResult a, b;
  FitProxiesJob job;
  job.character = &ch;
  job.result = &a;
  ASSERT_TRUE(job.run().ok());
  job.result = &b;
  ASSERT_TRUE(job.run().ok());
  ASSERT_EQ(a.fitted.size(), b.fitted.size());
  for (std::size_t i = 0; i < a.fitted.size(); ++i) {
    EXPECT_EQ(a.fitted[i].center, b.fitted[i].center);
    EXPECT_EQ(a.fitted[i].radius, b.fitted[i].radius);
  }
}

}  // namespace
}  // namespace proxygi::proxies
