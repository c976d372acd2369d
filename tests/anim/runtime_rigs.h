#pragma once
// Small synthetic characters for the runtime tests, and a write → import round trip through the
// project's own glTF writer and importer.
#include <gtest/gtest.h>

#include "anim/character.h"
#include "anim/gltf_import.h"
#include "anim/gltf_writer.h"

namespace proxygi::anim::testing {

// Writes `character` as GLB bytes and imports them back; fails the test on any error.
inline Character round_trip(const Character& character) {
  Result<std::vector<std::uint8_t>> bytes = encode_glb(character);
  EXPECT_TRUE(bytes.ok()) << (bytes ? "" : bytes.message());
  if (!bytes) return {};
  Result<Character> imported = import_gltf_bytes(*bytes, "round_trip.glb", {});
  EXPECT_TRUE(imported.ok()) << (imported ? "" : imported.message());
  return imported ? std::move(*imported) : Character{};
}

// A chain of `count` nodes, node i the parent of node i+1, each translated by (0, 1, 0).
inline Character chain(int count) {
  Character character;
  character.source = "chain";
  for (int i = 0; i < count; ++i) {
    Node node;
    node.name = std::to_string(i);
    node.name.insert(0, 1, 'n');  // not "n" + to_string: GCC 12 -O3 reports a bogus -Wrestrict
    node.parent = i - 1;
    if (i + 1 < count) node.children.push_back(i + 1);
    node.rest.translation = glm::vec3(0.0f, i == 0 ? 0.0f : 1.0f, 0.0f);
    character.nodes.push_back(node);
    character.evaluation_order.push_back(i);
  }
  character.roots = {0};
  return character;
}

inline Channel make_channel(int node, ChannelPath path, Interpolation interpolation, std::vector<float> times,
                            std::vector<float> values) {
  Channel channel;
  channel.node = node;
  channel.path = path;
  channel.interpolation = interpolation;
  channel.components = path == ChannelPath::rotation ? 4 : 3;
  channel.times = std::move(times);
  channel.values = std::move(values);
  return channel;
}

// Adds a one-triangle mesh on a new root node; returns the node index.
inline int add_triangle_node(Character& character, std::vector<glm::vec3> positions) {
  Primitive primitive;
  primitive.positions = std::move(positions);
  primitive.normals.assign(primitive.positions.size(), glm::vec3(0.0f, 0.0f, 1.0f));
  for (std::uint32_t i = 0; i < primitive.positions.size(); ++i) primitive.indices.push_back(i);
  Mesh mesh;
  mesh.name = "triangle";
  mesh.primitives.push_back(std::move(primitive));
  character.meshes.push_back(std::move(mesh));
  Node node;
  node.name = "mesh_node";
  node.mesh = static_cast<int>(character.meshes.size()) - 1;
  character.nodes.push_back(node);
  const int index = static_cast<int>(character.nodes.size()) - 1;
  character.roots.push_back(index);
  character.evaluation_order.push_back(index);
  return index;
}

}  // namespace proxygi::anim::testing
