#include "anim/bone_groups.h"

#include <algorithm>
#include <cstdlib>
#include <limits>

#include "base/check.h"

namespace proxygi::anim {

std::vector<int> split_joint_tree(std::span<const int> parents, std::span<const std::size_t> vertex_counts, int groups) {
  PROXYGI_CHECK(parents.size() == vertex_counts.size(), "one vertex count per node");
  PROXYGI_CHECK(groups >= 1, "at least one group");
  const std::size_t n = parents.size();
  // Depths, then subtree counts accumulated deepest first (parents need not precede children).
  std::vector<std::size_t> depth(n, 0);
  for (std::size_t i = 0; i < n; ++i) {
    std::size_t d = 0;
    for (int p = parents[i]; p >= 0; p = parents[std::size_t(p)]) {
      PROXYGI_CHECK(std::size_t(p) < n && d <= n, "parents form a forest");
      ++d;
    }
    depth[i] = d;
  }
  std::vector<std::size_t> order(n);
  for (std::size_t i = 0; i < n; ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return depth[a] > depth[b]; });
  std::vector<std::size_t> subtree(vertex_counts.begin(), vertex_counts.end());  // less what is cut below
  std::size_t remaining = 0;
  for (std::size_t i : order) {
    remaining += vertex_counts[i];
    if (parents[i] >= 0) subtree[std::size_t(parents[i])] += subtree[i];
  }
  std::vector<bool> cut(n, false);
  for (int left = groups; left > 1 && remaining > 0; --left) {
    const double target = double(remaining) / double(left);
    std::size_t best = n;
    double best_gap = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < n; ++i) {
      if (cut[i] || subtree[i] == 0 || subtree[i] >= remaining) continue;  // the rest keeps a vertex
      const double gap = std::abs(double(subtree[i]) - target);
      if (gap < best_gap) best_gap = gap, best = i;
    }
    if (best == n) break;  // no subtree left to cut: the remaining groups stay empty
    cut[best] = true;
    const std::size_t count = subtree[best];
    for (int p = parents[best]; p >= 0; p = parents[std::size_t(p)]) subtree[std::size_t(p)] -= count;
    remaining -= count;
  }
  // Each node joins its nearest cut ancestor-or-self (n: the rest), then groups are renumbered by
  // their smallest node; unused numbers go last.
  std::vector<std::size_t> owner(n, n);
  for (std::size_t i = 0; i < n; ++i)
    for (int p = int(i); p >= 0; p = parents[std::size_t(p)])
      if (cut[std::size_t(p)]) {
        owner[i] = std::size_t(p);
        break;
      }
  std::vector<int> number(n + 1, -1);
  int next = 0;
  std::vector<int> group(n);
  for (std::size_t i = 0; i < n; ++i) {
    if (number[owner[i]] < 0) number[owner[i]] = next++;
    group[i] = number[owner[i]];
  }
  return group;
}

int dominant_node(const Character& character, int node, const Primitive& primitive, std::size_t vertex) {
  const int skin = character.nodes[std::size_t(node)].skin;
  const int influences = primitive.influences_per_vertex;
  if (skin < 0 || influences < 1) return node;
  std::size_t best = vertex * std::size_t(influences);
  for (std::size_t k = best + 1; k < (vertex + 1) * std::size_t(influences); ++k)
    if (primitive.weights[k] > primitive.weights[best]) best = k;
  return character.skins[std::size_t(skin)].joints[primitive.joints[best]];
}

BoneGroups character_bone_groups(const Character& character, int groups) {
  std::vector<int> parents;
  for (const Node& node : character.nodes) parents.push_back(node.parent);
  std::vector<std::size_t> counts(character.nodes.size(), 0);
  for (std::size_t node = 0; node < character.nodes.size(); ++node) {
    const int mesh = character.nodes[node].mesh;
    if (mesh < 0) continue;
    for (const Primitive& primitive : character.meshes[std::size_t(mesh)].primitives)
      for (std::size_t v = 0; v < primitive.positions.size(); ++v)
        ++counts[std::size_t(dominant_node(character, int(node), primitive, v))];
  }
  return {groups, split_joint_tree(parents, counts, groups)};
}

std::vector<int> primitive_vertex_groups(const Character& character, int node, const Primitive& primitive,
                                         const BoneGroups& groups) {
  std::vector<int> out(primitive.positions.size());
  for (std::size_t v = 0; v < out.size(); ++v)
    out[v] = groups.node_group[std::size_t(dominant_node(character, node, primitive, v))];
  return out;
}

GroupedTriangles group_triangles(std::span<const std::uint32_t> indices, std::span<const int> vertex_group,
                                 int groups) {
  PROXYGI_CHECK(indices.size() % 3 == 0 && groups >= 1, "whole triangles, at least one group");
  const std::size_t triangles = indices.size() / 3;
  std::vector<int> triangle_group(triangles);
  std::vector<std::uint32_t> count(std::size_t(groups), 0);
  for (std::size_t t = 0; t < triangles; ++t) {
    int g[3];
    for (int c = 0; c < 3; ++c) {
      PROXYGI_CHECK(indices[3 * t + std::size_t(c)] < vertex_group.size(), "index within the vertices");
      g[c] = vertex_group[indices[3 * t + std::size_t(c)]];
      PROXYGI_CHECK(g[c] >= 0 && g[c] < groups, "vertex group in range");
    }
    triangle_group[t] = (g[1] == g[2] && g[0] != g[1]) ? g[1] : g[0];  // majority, else the first
    ++count[std::size_t(triangle_group[t])];
  }
  GroupedTriangles out;
  out.first.assign(std::size_t(groups) + 1, 0);
  for (int k = 0; k < groups; ++k) out.first[std::size_t(k) + 1] = out.first[std::size_t(k)] + count[std::size_t(k)];
  out.indices.resize(indices.size());
  std::vector<std::uint32_t> cursor(out.first.begin(), out.first.end() - 1);
  for (std::size_t t = 0; t < triangles; ++t) {
    const std::uint32_t slot = cursor[std::size_t(triangle_group[t])]++;
    for (int c = 0; c < 3; ++c) out.indices[3 * std::size_t(slot) + std::size_t(c)] = indices[3 * t + std::size_t(c)];
  }
  return out;
}

}  // namespace proxygi::anim
