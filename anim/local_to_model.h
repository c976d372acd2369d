#pragma once
// Local-to-model: world matrices of every node from a local pose.
//
//   world[n] = root_transform · world[parent] · local(n)   (root_transform only for roots)
//   local(n) = node.matrix if the node has one (fixed, never animated), else T · R · S.
//
// "World" is the character's glTF scene space (meters, +Y up) placed by root_transform.
// Matrices are GLM column-major (m[column][row]), the layout the GPU reads as std430 mat4.
// Nodes are evaluated in character.evaluation_order (parents before children).
//
//   LocalToModelJob job;
//   job.character = &character; job.locals = locals; job.world = world;
//   job.run();
#include <span>

#include "anim/character.h"
#include "base/result.h"

namespace proxygi::anim {

struct LocalToModelJob {
  // Inputs.
  const Character* character = nullptr;  // hierarchy, fixed matrices, evaluation order
  std::span<const Transform> locals;     // one per node, node-local (parent) space
  glm::mat4 root_transform{1.0f};        // world from character space

  // Output (caller-owned): one world matrix per node, column-major.
  std::span<glm::mat4> world;

  // Checks pointers, sizes (locals, world and evaluation_order all hold one entry per node) and
  // that every evaluation_order entry and parent index is in range. That the order lists each
  // node once with parents first is guaranteed by the importer and the mannequin builder.
  Status validate() const;
  Status run() const;
};

}  // namespace proxygi::anim
