// Bone groups (anim/bone_groups.h; render.vsgl_grouping bone_groups): the split of a joint tree
// into K connected groups of similar vertex count, and the triangles reordered by group. The K
// groups cover every vertex exactly once (synthetic trees and the procedural mannequin).
#include "anim/bone_groups.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <map>
#include <numeric>
#include <set>

#include "anim/mannequin.h"
#include "bone_groups_check.h"

namespace proxygi::anim {
namespace {

TEST(BoneGroups, ChainSplitsIntoBalancedContiguousRuns) {
  // A chain of 8 joints, 10 vertices each: K = 4 gives runs of 2 joints, 20 vertices each.
  const std::vector<int> parents = {-1, 0, 1, 2, 3, 4, 5, 6};
  const std::vector<std::size_t> counts(8, 10);
  const std::vector<int> group = split_joint_tree(parents, counts, 4);
  EXPECT_EQ(group, (std::vector<int>{0, 0, 1, 1, 2, 2, 3, 3}));
  testing::expect_connected(parents, group, 4);
}

TEST(BoneGroups, TwoLimbsBecomeTwoGroups) {
  // Root (no vertices) with two limbs of three joints: K = 2 separates the limbs.
  const std::vector<int> parents = {-1, 0, 1, 2, 0, 4, 5};
  const std::vector<std::size_t> counts = {0, 5, 5, 5, 5, 5, 5};
  const std::vector<int> group = split_joint_tree(parents, counts, 2);
  for (int i : {1, 2, 3}) EXPECT_EQ(group[std::size_t(i)], group[1]);
  for (int i : {4, 5, 6}) EXPECT_EQ(group[std::size_t(i)], group[4]);
  EXPECT_NE(group[1], group[4]);
  testing::expect_connected(parents, group, 2);
}

TEST(BoneGroups, FewerWeightedSubtreesThanGroupsLeavesEmptyGroups) {
  const std::vector<int> parents = {-1, 0};
  const std::vector<std::size_t> counts = {0, 7};
  const std::vector<int> group = split_joint_tree(parents, counts, 4);
  EXPECT_LT(*std::max_element(group.begin(), group.end()), 4);
  testing::expect_connected(parents, group, 4);
}

TEST(BoneGroups, SplitIsDeterministicWithChildrenListedBeforeParents) {
  // The same tree with children listed before their parents.
  const std::vector<int> parents = {2, 2, -1, 1, 1};
  const std::vector<std::size_t> counts = {3, 1, 2, 4, 4};
  const std::vector<int> first = split_joint_tree(parents, counts, 3);
  EXPECT_EQ(first, split_joint_tree(parents, counts, 3));
  testing::expect_connected(parents, first, 3);
}

TEST(BoneGroups, MannequinGroupsCoverEveryVertexExactlyOnce) {
  testing::expect_groups_cover_every_vertex(build_mannequin());
}

TEST(BoneGroups, TrianglesGoToTheirMajorityGroup) {
  const std::vector<int> vertex_group = {0, 1, 1, 2, 0};
  const std::vector<std::uint32_t> indices = {0, 1, 2, /*majority 1*/ 0, 3, 4, /*majority 0*/ 3, 1, 4 /*none: 2*/};
  const GroupedTriangles grouped = group_triangles(indices, vertex_group, 3);
  EXPECT_EQ(grouped.first, (std::vector<std::uint32_t>{0, 1, 2, 3}));
  EXPECT_EQ(grouped.indices, (std::vector<std::uint32_t>{0, 3, 4, 0, 1, 2, 3, 1, 4}));
}

}  // namespace
}  // namespace proxygi::anim
