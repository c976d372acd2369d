#pragma once
// Synthetic characters for proxy tests: closed, outward-oriented meshes with known geometry.
#include <cmath>
#include <numbers>
#include <string>

#include <glm/gtc/matrix_transform.hpp>

#include "anim/character.h"

namespace proxygi::proxies::testing {

// Axis-aligned box primitive (12 triangles, outward-facing, counter-clockwise seen from outside).
inline anim::Primitive box_primitive(const glm::vec3& lo, const glm::vec3& hi) {
  anim::Primitive prim;
  for (int i = 0; i < 8; ++i)
    prim.positions.push_back(glm::vec3(i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z));
  const std::uint32_t faces[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
  for (const auto& f : faces) prim.indices.insert(prim.indices.end(), {f[0], f[1], f[2], f[0], f[2], f[3]});
  prim.normals.assign(prim.positions.size(), glm::vec3(0.0f, 1.0f, 0.0f));
  return prim;
}

// A character with one unskinned box mesh on node 0 ("box"), placed by `translation`.
inline anim::Character box_character(const glm::vec3& lo, const glm::vec3& hi,
                                     const glm::vec3& translation = glm::vec3(0.0f)) {
  anim::Character ch;
  ch.source = "box";
  anim::Node node;
  node.name = "box";
  node.mesh = 0;
  node.rest.translation = translation;
  ch.nodes.push_back(node);
  ch.roots = {0};
  ch.evaluation_order = {0};
  anim::Mesh mesh;
  mesh.name = "box";
  mesh.primitives.push_back(box_primitive(lo, hi));
  ch.meshes.push_back(mesh);
  return ch;
}

// Closed cylinder along +X from 0 to length, radius r, `rings` rings of `around` vertices plus
// two cap centers. Skinned to joints 0 ("upper", at x = 0) and 1 ("lower", at x = length / 2),
// weights blended linearly over the middle fifth; joint 2 ("tip", at x = length) gets no weight.
inline anim::Character arm_character(float length = 1.0f, float r = 0.08f, int rings = 41, int around = 24) {
  anim::Character ch;
  ch.source = "arm";
  auto add_node = [&](const std::string& name, int parent, glm::vec3 t) {
    anim::Node n;
    n.name = name;
    n.parent = parent;
    n.rest.translation = t;
    ch.nodes.push_back(n);
    if (parent >= 0) ch.nodes[std::size_t(parent)].children.push_back(int(ch.nodes.size()) - 1);
  };
  add_node("skin_mesh", -1, glm::vec3(0.0f));
  add_node("upper", -1, glm::vec3(0.0f));
  add_node("lower", 1, glm::vec3(length / 2, 0, 0));
  add_node("tip", 2, glm::vec3(length / 2, 0, 0));
  ch.nodes[0].mesh = 0;
  ch.nodes[0].skin = 0;
  ch.roots = {0, 1};
  ch.evaluation_order = {0, 1, 2, 3};
  anim::Skin skin;
  skin.joints = {1, 2, 3};
  skin.inverse_bind_matrices = {glm::mat4(1.0f), glm::translate(glm::mat4(1.0f), glm::vec3(-length / 2, 0, 0)),
                                glm::translate(glm::mat4(1.0f), glm::vec3(-length, 0, 0))};
  ch.skins.push_back(skin);

  anim::Primitive prim;
  prim.influences_per_vertex = 4;
  auto add_vertex = [&](glm::vec3 p) {
    prim.positions.push_back(p);
    prim.normals.push_back(glm::vec3(0, 1, 0));
    const float t = std::clamp((p.x - 0.4f * length) / (0.2f * length), 0.0f, 1.0f);
    prim.joints.insert(prim.joints.end(), {0, 1, 2, 0});
    prim.weights.insert(prim.weights.end(), {1.0f - t, t, 0.0f, 0.0f});
  };
  for (int i = 0; i < rings; ++i)
    for (int j = 0; j < around; ++j) {
      const float a = 2.0f * std::numbers::pi_v<float> * float(j) / float(around);
      add_vertex(glm::vec3(length * float(i) / float(rings - 1), r * std::cos(a), r * std::sin(a)));
    }
  const std::uint32_t start_cap = std::uint32_t(prim.positions.size());
  add_vertex(glm::vec3(0.0f));
  add_vertex(glm::vec3(length, 0, 0));
  auto v = [&](int i, int j) { return std::uint32_t(i * around + (j % around)); };
  for (int i = 0; i + 1 < rings; ++i)
    for (int j = 0; j < around; ++j)  // outward: (i,j) -> (i,j+1) -> (i+1,j+1) seen from outside
      prim.indices.insert(prim.indices.end(), {v(i, j), v(i, j + 1), v(i + 1, j + 1), v(i, j), v(i + 1, j + 1), v(i + 1, j)});
  for (int j = 0; j < around; ++j) {
    prim.indices.insert(prim.indices.end(), {start_cap, v(0, j + 1), v(0, j)});
    prim.indices.insert(prim.indices.end(), {start_cap + 1, v(rings - 1, j), v(rings - 1, j + 1)});
  }
  anim::Mesh mesh;
  mesh.name = "arm";
  mesh.primitives.push_back(prim);
  ch.meshes.push_back(mesh);
  return ch;
}

}  // namespace proxygi::proxies::testing
