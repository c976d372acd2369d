#include "anim/local_to_model.h"

#include <string>

namespace proxygi::anim {

Status LocalToModelJob::validate() const {
  if (character == nullptr) return make_error("local_to_model: character is required");
  const std::size_t count = character->nodes.size();
  if (locals.size() != count || world.size() != count || character->evaluation_order.size() != count) {
    return make_error(character->source + ": local_to_model: " + std::to_string(count) + " nodes but " +
                      std::to_string(locals.size()) + " locals, " + std::to_string(world.size()) + " world matrices, " +
                      std::to_string(character->evaluation_order.size()) + " entries in the evaluation order");
  }
  for (std::size_t i = 0; i < count; ++i) {
    const int node = character->evaluation_order[i];
    if (node < 0 || static_cast<std::size_t>(node) >= count) {
      return make_error(character->source + ": evaluation order entry " + std::to_string(i) + " is node " +
                        std::to_string(node) + ", out of range");
    }
    const int parent = character->nodes[i].parent;
    if (parent < -1 || parent >= static_cast<int>(count)) {
      return make_error(character->source + ": node " + std::to_string(i) + ": parent " + std::to_string(parent) +
                        " out of range");
    }
  }
  return {};
}

Status LocalToModelJob::run() const {
  if (Status status = validate(); !status) return status;
  for (const int index : character->evaluation_order) {
    const std::size_t i = static_cast<std::size_t>(index);
    const Node& node = character->nodes[i];
    const glm::mat4 local = node.matrix ? *node.matrix : to_matrix(locals[i]);
    const glm::mat4& parent = node.parent < 0 ? root_transform : world[static_cast<std::size_t>(node.parent)];
    world[i] = parent * local;
  }
  return {};
}

}  // namespace proxygi::anim
