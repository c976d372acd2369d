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

namespace proxygi::anim {
namespace {

// Every group is connected: each of its nodes but one has its parent in the group (the rest
// group may hold several forest roots, joined through the virtual root).
void expect_connected(std::span<const int> parents, std::span<const int> group, int groups) {
  std::map<int, int> tops;  // group → nodes whose parent is elsewhere
  std::map<int, bool> holds_root;
  for (std::size_t i = 0; i < parents.size(); ++i) {
    ASSERT_GE(group[i], 0);
    ASSERT_LT(group[i], groups);
    if (parents[i] < 0) holds_root[group[i]] = true;
    if (parents[i] < 0 || group[std::size_t(parents[i])] != group[i]) ++tops[group[i]];
  }
  for (const auto& [g, count] : tops) {
    if (!holds_root[g]) {
      EXPECT_EQ(count, 1) << "group " << g << " is not one subtree";
    }
  }
}

TEST(BoneGroups, ChainSplitsIntoBalancedContiguousRuns) {
  // A chain of 8 joints, 10 vertices each: K = 4 gives runs of 2 joints, 20 vertices each.
  const std::vector<int> parents = {-1, 0, 1, 2, 3, 4, 5, 6};
  const std::vector<std::size_t> counts(8, 10);
  const std::vector<int> group = split_joint_tree(parents, counts, 4);
  EXPECT_EQ(group, (std::vector<int>{0, 0, 1, 1, 2, 2, 3, 3}));
  expect_connected(parents, group, 4);
}

TEST(BoneGroups, TwoLimbsBecomeTwoGroups) {
  // Root (no vertices) with two limbs of three joints: K = 2 separates the limbs.
  const std::vector<int> parents = {-1, 0, 1, 2, 0, 4, 5};
  const std::vector<std::size_t> counts = {0, 5, 5, 5, 5, 5, 5};
  const std::vector<int> group = split_joint_tree(parents, counts, 2);
  for (int i : {1, 2, 3}) EXPECT_EQ(group[std::size_t(i)], group[1]);
  for (int i : {4, 5, 6}) EXPECT_EQ(group[std::size_t(i)], group[4]);
  EXPECT_NE(group[1], group[4]);
  expect_connected(parents, group, 2);
}

TEST(BoneGroups, FewerWeightedSubtreesThanGroupsLeavesEmptyGroups) {
  const std::vector<int> parents = {-1, 0};
  const std::vector<std::size_t> counts = {0, 7};
  const std::vector<int> group = split_joint_tree(parents, counts, 4);
  EXPECT_LT(*std::max_element(group.begin(), group.end()), 4);
  expect_connected(parents, group, 4);
}

TEST(BoneGroups, SplitIsDeterministicWithChildrenListedBeforeParents) {
  // The same tree with children listed before their parents.
  const std::vector<int> parents = {2, 2, -1, 1, 1};
  const std::vector<std::size_t> counts = {3, 1, 2, 4, 4};
  const std::vector<int> first = split_joint_tree(parents, counts, 3);
  EXPECT_EQ(first, split_joint_tree(parents, counts, 3));
  expect_connected(parents, first, 3);
}

TEST(BoneGroups, MannequinGroupsCoverEveryVertexExactlyOnce) {
  const Character character = build_mannequin();
  std::vector<int> parents;
  for (const Node& node : character.nodes) parents.push_back(node.parent);
  for (int k : {1, 2, 4, 8}) {
    SCOPED_TRACE("K = " + std::to_string(k));
    const BoneGroups groups = character_bone_groups(character, k);
    ASSERT_EQ(groups.node_group.size(), character.nodes.size());
    expect_connected(parents, groups.node_group, k);
    std::vector<std::size_t> per_group(std::size_t(k), 0);
    std::size_t vertices = 0, triangles = 0, grouped_triangles = 0;
    for (std::size_t node = 0; node < character.nodes.size(); ++node) {
      if (character.nodes[node].mesh < 0) continue;
      for (const Primitive& primitive : character.meshes[std::size_t(character.nodes[node].mesh)].primitives) {
        const std::vector<int> vertex_group = primitive_vertex_groups(character, int(node), primitive, groups);
        ASSERT_EQ(vertex_group.size(), primitive.positions.size());
        for (int g : vertex_group) {
          ASSERT_GE(g, 0);
          ASSERT_LT(g, k);
          ++per_group[std::size_t(g)];
        }
        vertices += primitive.positions.size();
        const GroupedTriangles grouped = group_triangles(primitive.indices, vertex_group, k);
        ASSERT_EQ(grouped.first.size(), std::size_t(k) + 1);
        EXPECT_EQ(grouped.first.front(), 0u);
        EXPECT_EQ(std::size_t(grouped.first.back()) * 3, primitive.indices.size());
        EXPECT_TRUE(std::is_sorted(grouped.first.begin(), grouped.first.end()));
        // A permutation of the triangles.
        std::multiset<std::array<std::uint32_t, 3>> before, after;
        for (std::size_t t = 0; t < primitive.indices.size(); t += 3) {
          before.insert({primitive.indices[t], primitive.indices[t + 1], primitive.indices[t + 2]});
          after.insert({grouped.indices[t], grouped.indices[t + 1], grouped.indices[t + 2]});
        }
        EXPECT_EQ(before, after);
        triangles += primitive.indices.size() / 3;
        grouped_triangles += grouped.first.back();
      }
    }
    EXPECT_EQ(std::accumulate(per_group.begin(), per_group.end(), std::size_t(0)), vertices);
    EXPECT_EQ(grouped_triangles, triangles);
    // Similar sizes: no group of a K ≤ 4 split is empty on the mannequin's 20-odd joints.
    if (k <= 4) {
      for (std::size_t g = 0; g < per_group.size(); ++g) EXPECT_GT(per_group[g], 0u) << "group " << g;
    }
  }
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
