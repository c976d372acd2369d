#pragma once
// Checks of anim/bone_groups.h shared by the mannequin test and the shared-assets test.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <map>
#include <numeric>
#include <set>
#include <span>
#include <string>

#include "anim/bone_groups.h"

namespace proxygi::anim::testing {

// Every group is connected: each of its nodes but one has its parent in the group (the rest
// group may hold several forest roots, joined through the virtual root).
inline void expect_connected(std::span<const int> parents, std::span<const int> group, int groups) {
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

// For K = 1, 2, 4, 8: every group connected, the K groups cover every vertex exactly once, each
// primitive's grouped triangles a permutation of its triangles; no group is empty when K ≤ 4 and
// at least K nodes are some vertex's dominant node.
inline void expect_groups_cover_every_vertex(const Character& character) {
  std::vector<int> parents;
  for (const Node& node : character.nodes) parents.push_back(node.parent);
  std::set<int> dominant;
  for (std::size_t node = 0; node < character.nodes.size(); ++node) {
    if (character.nodes[node].mesh < 0) continue;
    for (const Primitive& primitive : character.meshes[std::size_t(character.nodes[node].mesh)].primitives)
      for (std::size_t v = 0; v < primitive.positions.size(); ++v)
        dominant.insert(dominant_node(character, int(node), primitive, v));
  }
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
    if (k <= 4 && std::size_t(k) <= dominant.size()) {
      for (std::size_t g = 0; g < per_group.size(); ++g) EXPECT_GT(per_group[g], 0u) << "group " << g;
    }
  }
}

}  // namespace proxygi::anim::testing
