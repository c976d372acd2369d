#pragma once
// Bone groups (render.vsgl_grouping bone_groups): a character's vertices grouped by their
// dominant joint into K groups of joints that are connected in the skeleton, so each of the K
// VSGL lights of a character (render.vsgl_lights) summarises one limb-like part of it instead
// of an arbitrary index range of its triangles.
//
//   const BoneGroups groups = character_bone_groups(character, 4);
//   std::vector<int> vertex_group = primitive_vertex_groups(character, node, primitive, groups);
//   GroupedTriangles grouped = group_triangles(primitive.indices, vertex_group, 4);
//   // grouped.indices: the triangles of group k at [grouped.first[k], grouped.first[k + 1])
//
// Everything is deterministic (ties go to the smaller index); nothing depends on the pose.
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "anim/character.h"

namespace proxygi::anim {

// Splits a node forest into `groups` (≥ 1) connected groups of similar vertex count.
// parents[i]: the parent of node i (< parents.size()) or −1; vertex_counts[i]: the vertices whose
// dominant node is i. Greedy: K − 1 times, the subtree (less what is already cut from it) whose
// count is nearest the remaining count / groups left is cut off as one group; what is left is the
// last. A cut group is a subtree minus the subtrees cut from it; the rest hangs together through
// a virtual root above the forest's roots. Groups are numbered by their smallest node. A group
// can be empty when fewer than K subtrees hold vertices. Returns the group of each node.
// Precondition: the parents form a forest (no cycle), sizes equal.
std::vector<int> split_joint_tree(std::span<const int> parents, std::span<const std::size_t> vertex_counts, int groups);

struct BoneGroups {
  int groups = 1;
  std::vector<int> node_group;  // per Character::nodes entry, in [0, groups)
};
// The node of a vertex: its largest skin weight's joint (the skin's node; ties: the first
// influence), or `node` itself for a rigid primitive (no skin or no influences).
int dominant_node(const Character& character, int node, const Primitive& primitive, std::size_t vertex);
// split_joint_tree over the character's nodes with each mesh node's vertices counted at their
// dominant node (every primitive of every node that has a mesh).
BoneGroups character_bone_groups(const Character& character, int groups);
// The group of each vertex of `primitive` (on node `node`).
std::vector<int> primitive_vertex_groups(const Character& character, int node, const Primitive& primitive,
                                         const BoneGroups& groups);

// A triangle list ordered by group: the triangles of group k, in their original order, at
// triangles [first[k], first[k + 1]) of `indices` (first has groups + 1 entries).
struct GroupedTriangles {
  std::vector<std::uint32_t> indices;
  std::vector<std::uint32_t> first;
};
// A triangle belongs to the group of two or three of its vertices, else to its first vertex's.
// Preconditions: indices.size() % 3 == 0, every index < vertex_group.size(), groups in range.
GroupedTriangles group_triangles(std::span<const std::uint32_t> indices, std::span<const int> vertex_group,
                                 int groups);

}  // namespace proxygi::anim
