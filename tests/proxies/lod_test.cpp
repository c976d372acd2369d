// Levels of detail (proxies/lod.h): nested levels built bottom-up from a rig and their
// validation, the chooser (farther → fewer spheres, hysteresis, the fade over N frames), and the
// weighted spheres a cross-fade streams.
#include "proxies/lod.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>

namespace proxygi::proxies {
namespace {

// Four chains (two arms, two legs) of eight touching spheres each: 32 spheres.
struct ChainRig {
  std::vector<WorldSphere> spheres;
  std::vector<int> groups, nodes;
};
ChainRig four_chains() {
  ChainRig rig;
  const glm::vec3 directions[4] = {{1, 0, 0}, {-1, 0, 0}, {0.3f, -1, 0}, {-0.3f, -1, 0}};
  for (int chain = 0; chain < 4; ++chain)
    for (int i = 0; i < 8; ++i) {
      rig.spheres.push_back({glm::vec3(0, 1, 0) + 0.1f * float(i + 1) * directions[chain], 0.06f - 0.003f * float(i),
                             glm::vec3(0.2f * float(chain), 0.5f, 0.5f), 0.0f});
      rig.groups.push_back(10 + chain);
      rig.nodes.push_back(100 + 2 * chain + i / 4);
    }
  return rig;
}

LodLevels build(const ChainRig& rig, int min_spheres = 8) {
  LodLevels levels;
  BuildLodLevelsJob job{rig.spheres, rig.groups, rig.nodes, min_spheres, &levels};
  const Status built = job.run();
  EXPECT_TRUE(built.ok()) << built.message();
  return levels;
}

TEST(LodLevels, HalveDownToTheMinimumNestedAndCovering) {
  const ChainRig rig = four_chains();
  const LodLevels levels = build(rig);
  EXPECT_EQ(levels.counts(), (std::vector<int>{32, 16, 8}));
  const Status valid = validate_lod_levels(levels, rig.spheres);
  EXPECT_TRUE(valid.ok()) << valid.message();
  // Merges stay within a chain while a chain holds two spheres: with 8 per chain, 16 and 8 do.
  for (std::size_t k = 1; k < levels.levels.size(); ++k)
    for (const LodSphere& sphere : levels.levels[k].spheres) {
      std::set<int> chains;
      for (int m : sphere.members) chains.insert(rig.groups[std::size_t(m)]);
      EXPECT_EQ(chains.size(), 1u) << "level " << k;
      EXPECT_EQ(sphere.members.size(), std::size_t(1) << k) << "level " << k;
    }
  // Coverage holds in another pose too: every level sphere is evaluated from its children.
  std::vector<WorldSphere> moved = rig.spheres;
  for (std::size_t i = 0; i < moved.size(); ++i) moved[i].center += glm::vec3(0.0f, 0.02f * float(i % 5), 0.1f * float(i % 3));
  const Status still = validate_lod_levels(levels, moved);
  EXPECT_TRUE(still.ok()) << still.message();
}

TEST(LodLevels, SmallRigsAndOddCounts) {
  ChainRig rig = four_chains();
  rig.spheres.resize(7), rig.groups.resize(7), rig.nodes.resize(7);
  EXPECT_EQ(build(rig).counts(), (std::vector<int>{7}));  // no larger than the minimum: one level
  rig = four_chains();
  rig.spheres.resize(27), rig.groups.resize(27), rig.nodes.resize(27);
  const LodLevels levels = build(rig, 4);
  EXPECT_EQ(levels.counts(), (std::vector<int>{27, 14, 7, 4}));
  EXPECT_TRUE(validate_lod_levels(levels, rig.spheres).ok());
}

TEST(LodLevels, ValidateNamesTheBrokenInvariant) {
  const ChainRig rig = four_chains();
  const LodLevels good = build(rig);
  LodLevels broken = good;
  broken.levels[1].spheres[0].members.push_back(31);  // rig sphere 31 in two level-1 spheres
  Status s = validate_lod_levels(broken, rig.spheres);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find("level 1 sphere"), std::string::npos) << s.message();
  broken = good;
  broken.levels[2].spheres[1].children.push_back(broken.levels[2].spheres[0].children.front());  // not its child
  s = validate_lod_levels(broken, rig.spheres);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find("level 2 sphere 1"), std::string::npos) << s.message();
  broken = good;
  broken.levels[0].spheres[3].coarser = 99;
  EXPECT_FALSE(validate_lod_levels(broken, rig.spheres).ok());
  // Invalid inputs to the job.
  LodLevels out;
  std::vector<int> short_groups(rig.groups.begin(), rig.groups.end() - 1);
  EXPECT_FALSE((BuildLodLevelsJob{rig.spheres, short_groups, rig.nodes, 8, &out}.run().ok()));
  EXPECT_FALSE((BuildLodLevelsJob{rig.spheres, rig.groups, rig.nodes, 0, &out}.run().ok()));
  EXPECT_FALSE((BuildLodLevelsJob{rig.spheres, rig.groups, rig.nodes, 8, nullptr}.run().ok()));
  std::vector<WorldSphere> flat = rig.spheres;
  flat[5].radius = 0.0f;
  EXPECT_FALSE((BuildLodLevelsJob{flat, rig.groups, rig.nodes, 8, &out}.run().ok()));
}

TEST(LodChooser, AFartherCharacterGetsFewerSpheres) {
  const LodChooser chooser{{32, 16, 8}, 4.0f, 0.15f, 16};
  const float focal = 512.0f / (2.0f * std::tan(glm::radians(22.5f)));
  int previous = 1 << 30;
  for (float distance : {2.0f, 4.0f, 8.0f, 16.0f, 32.0f, 64.0f}) {
    const float radius = projected_radius_pixels(glm::vec3(0, 1, -distance), 0.9f, glm::vec3(0, 1, 0), focal);
    const int count = chooser.counts[std::size_t(chooser.level_for(radius))];
    EXPECT_LE(count, previous) << distance << " m";
    previous = count;
  }
  const auto count_at = [&](float d) {
    return chooser.counts[std::size_t(chooser.level_for(projected_radius_pixels(glm::vec3(0, 1, -d), 0.9f, glm::vec3(0, 1, 0), focal)))];
  };
  EXPECT_EQ(count_at(2.0f), 32);
  EXPECT_EQ(count_at(64.0f), 8);
  EXPECT_LT(count_at(64.0f), count_at(2.0f));
}

TEST(LodChooser, HysteresisHoldsTheLevelNearASwitchPoint) {
  const LodChooser chooser{{32, 16, 8}, 4.0f, 0.15f, 4};
  // Level 1 (16 spheres) is enough up to 64 px of radius.
  LodChoice choice{1, 1, 0};
  for (float radius : {60.0f, 66.0f, 70.0f, 62.0f, 73.0f})  // within 64 / (1 − 0.15) = 75.3 px: stays
    choice = chooser.step(choice, radius);
  EXPECT_EQ(choice, (LodChoice{1, 1, 0}));
  choice = chooser.step(choice, 76.0f);  // past it: fades to level 0
  EXPECT_EQ(choice, (LodChoice{1, 0, 1}));
  // The fade runs its 4 frames whatever the size does, t = 1/4, 2/4, 3/4, then settles.
  std::vector<float> fades = {chooser.fade(choice)};
  for (float radius : {10.0f, 10.0f, 10.0f}) {
    choice = chooser.step(choice, radius);
    fades.push_back(chooser.fade(choice));
  }
  EXPECT_EQ(fades, (std::vector<float>{0.25f, 0.5f, 0.75f, 1.0f}));
  EXPECT_EQ(choice, (LodChoice{0, 0, 0}));
  // Coarser needs the radius below 64 / (1 + 0.15) = 55.7 px.
  EXPECT_EQ(chooser.step(choice, 58.0f), choice);
  EXPECT_EQ(chooser.step(choice, 55.0f), (LodChoice{0, 1, 1}));
  // Far below both switch points the fade goes straight to the coarsest level.
  EXPECT_EQ(chooser.step(choice, 5.0f), (LodChoice{0, 2, 1}));
  // One fade frame is a hard switch.
  const LodChooser hard{{32, 16, 8}, 4.0f, 0.15f, 1};
  EXPECT_EQ(hard.step(choice, 5.0f), (LodChoice{2, 2, 0}));
}

TEST(LodSpheres, AFadeStreamsBothLevelsWithComplementaryWeights) {
  const ChainRig rig = four_chains();
  const LodLevels levels = build(rig);
  std::vector<std::vector<WorldSphere>> scratch;
  std::vector<WeightedSphere> out;
  append_lod_spheres(levels, {0, 0, 0}, 1.0f, rig.spheres, scratch, out);
  ASSERT_EQ(out.size(), 32u);
  for (std::size_t i = 0; i < out.size(); ++i) {
    EXPECT_EQ(out[i].weight, 1.0f);
    EXPECT_EQ(out[i].sphere.center, rig.spheres[i].center);
  }
  out.clear();
  append_lod_spheres(levels, {0, 1, 1}, 0.25f, rig.spheres, scratch, out);
  ASSERT_EQ(out.size(), 48u);
  for (std::size_t i = 0; i < out.size(); ++i) EXPECT_EQ(out[i].weight, i < 32 ? 0.75f : 0.25f) << i;
  // A sphere both levels share goes once with weight 1: a 3-sphere chain halves to 2 spheres,
  // one of them a rig sphere carried unchanged.
  ChainRig small;
  for (int i = 0; i < 3; ++i) {
    small.spheres.push_back({glm::vec3(0.1f * float(i), 0, 0), i == 2 ? 0.02f : 0.06f, glm::vec3(1), 0});
    small.groups.push_back(0), small.nodes.push_back(i);
  }
  const LodLevels two = build(small, 2);
  ASSERT_EQ(two.counts(), (std::vector<int>{3, 2}));
  out.clear();
  append_lod_spheres(two, {0, 1, 1}, 0.5f, small.spheres, scratch, out);
  ASSERT_EQ(out.size(), 4u);  // 3 at 0.5 or 1, the merged one at 0.5
  float total = 0.0f;
  int whole = 0;
  for (const auto& s : out) total += s.weight, whole += s.weight == 1.0f;
  EXPECT_EQ(whole, 1);
  EXPECT_FLOAT_EQ(total, 2.5f);
}

}  // namespace
}  // namespace proxygi::proxies
