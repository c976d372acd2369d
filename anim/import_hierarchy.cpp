// Nodes: indices, rest transforms, the parent forest (no cycles, one parent), scene roots and
// the parents-before-children evaluation order.
#include <cmath>

#include "anim/import_context.h"

namespace proxygi::anim::detail {
namespace {

std::string node_what(std::size_t index) { return "node " + std::to_string(index); }

bool all_finite(const std::vector<double>& values) {
  for (double v : values) {
    if (!std::isfinite(v)) return false;
  }
  return true;
}

Status check_index(int index, std::size_t size, const std::string& what, const std::string& kind,
                   const std::string& plural) {
  if (index < -1 || (index >= 0 && static_cast<std::size_t>(index) >= size)) {
    return error_at(what, kind + " " + std::to_string(index) + " out of range (" +
                              std::to_string(size) + " " + plural + ")");
  }
  return {};
}

Result<Node> convert_node(const tinygltf::Model& model, std::size_t index) {
  const tinygltf::Node& source = model.nodes[index];
  const std::string what = node_what(index);
  Node node;
  node.name = source.name;
  PROXYGI_IMPORT_TRY(check_index(source.mesh, model.meshes.size(), what, "mesh", "meshes"));
  PROXYGI_IMPORT_TRY(check_index(source.skin, model.skins.size(), what, "skin", "skins"));
  if (source.skin >= 0 && source.mesh < 0) {
    return error_at(what, "skin " + std::to_string(source.skin) + " set without a mesh");
  }
  node.mesh = source.mesh;
  node.skin = source.skin;
  if (!source.weights.empty() && source.mesh < 0) return error_at(what, "weights set without a mesh");
  for (double w : source.weights) {  // count checked against the mesh's targets in import_meshes
    if (!std::isfinite(w)) return error_at(what, "weights contain NaN or infinity");
    node.morph_weights.push_back(static_cast<float>(w));
  }

  const auto bad_size = [&](const char* field, std::size_t size, std::size_t expected) {
    return error_at(what, std::string(field) + " has " + std::to_string(size) +
                              " numbers, expected " + std::to_string(expected));
  };
  if (!source.translation.empty() && source.translation.size() != 3) {
    return bad_size("translation", source.translation.size(), 3);
  }
  if (!source.rotation.empty() && source.rotation.size() != 4) {
    return bad_size("rotation", source.rotation.size(), 4);
  }
  if (!source.scale.empty() && source.scale.size() != 3) {
    return bad_size("scale", source.scale.size(), 3);
  }
  if (!source.matrix.empty() && source.matrix.size() != 16) {
    return bad_size("matrix", source.matrix.size(), 16);
  }
  if (!all_finite(source.translation) || !all_finite(source.rotation) ||
      !all_finite(source.scale) || !all_finite(source.matrix)) {
    return error_at(what, "transform contains NaN or infinity");
  }
  if (!source.matrix.empty()) {
    if (!source.translation.empty() || !source.rotation.empty() || !source.scale.empty()) {
      return error_at(what, "has both matrix and translation/rotation/scale");
    }
    glm::mat4 matrix;
    for (int column = 0; column < 4; ++column) {
      for (int row = 0; row < 4; ++row) {
        matrix[column][row] = static_cast<float>(source.matrix[static_cast<std::size_t>(column * 4 + row)]);
      }
    }
    node.matrix = matrix;
  }
  if (!source.translation.empty()) {
    node.rest.translation = glm::vec3(static_cast<float>(source.translation[0]),
                                      static_cast<float>(source.translation[1]),
                                      static_cast<float>(source.translation[2]));
  }
  if (!source.rotation.empty()) {
    // glTF stores x, y, z, w; glm::quat's constructor takes w first.
    glm::quat q(static_cast<float>(source.rotation[3]), static_cast<float>(source.rotation[0]),
                static_cast<float>(source.rotation[1]), static_cast<float>(source.rotation[2]));
    const float length = glm::length(q);
    if (!(length > 1e-6f) || !std::isfinite(length)) {
      return error_at(what, "rotation quaternion has zero length");
    }
    node.rest.rotation = q / length;
  }
  if (!source.scale.empty()) {
    node.rest.scale = glm::vec3(static_cast<float>(source.scale[0]),
                                static_cast<float>(source.scale[1]),
                                static_cast<float>(source.scale[2]));
  }
  return node;
}

Status link_children(const tinygltf::Model& model, std::vector<Node>& nodes) {
  for (std::size_t index = 0; index < nodes.size(); ++index) {
    for (int child : model.nodes[index].children) {
      if (child < 0 || static_cast<std::size_t>(child) >= nodes.size()) {
        return error_at(node_what(index), "child " + std::to_string(child) + " out of range (" +
                                              std::to_string(nodes.size()) + " nodes)");
      }
      if (static_cast<std::size_t>(child) == index) {
        return error_at(node_what(index), "lists itself as a child");
      }
      Node& node = nodes[static_cast<std::size_t>(child)];
      if (node.parent >= 0) {
        return error_at(node_what(static_cast<std::size_t>(child)),
                        "has two parents (node " + std::to_string(node.parent) + " and node " +
                            std::to_string(index) + ")");
      }
      node.parent = static_cast<int>(index);
      nodes[index].children.push_back(child);
    }
  }
  return {};
}

// Breadth-first from every parentless node; a node never reached sits on a cycle.
Status order_nodes(Character& character) {
  auto& order = character.evaluation_order;
  order.clear();
  for (std::size_t i = 0; i < character.nodes.size(); ++i) {
    if (character.nodes[i].parent < 0) order.push_back(static_cast<int>(i));
  }
  for (std::size_t head = 0; head < order.size(); ++head) {
    for (int child : character.nodes[static_cast<std::size_t>(order[head])].children) {
      order.push_back(child);
    }
  }
  if (order.size() != character.nodes.size()) {
    std::vector<bool> reached(character.nodes.size(), false);
    for (int n : order) reached[static_cast<std::size_t>(n)] = true;
    for (std::size_t i = 0; i < reached.size(); ++i) {
      if (!reached[i]) return error_at(node_what(i), "is part of a cycle in the node hierarchy");
    }
  }
  return {};
}

Status find_roots(const tinygltf::Model& model, Character& character) {
  if (model.scenes.empty()) {
    for (std::size_t i = 0; i < character.nodes.size(); ++i) {
      if (character.nodes[i].parent < 0) character.roots.push_back(static_cast<int>(i));
    }
    return {};
  }
  int scene_index = model.defaultScene;
  if (scene_index < -1 || (scene_index >= 0 && static_cast<std::size_t>(scene_index) >= model.scenes.size())) {
    return make_error("scene " + std::to_string(scene_index) + " (default scene) out of range (" +
                      std::to_string(model.scenes.size()) + " scenes)");
  }
  if (scene_index < 0) scene_index = 0;
  const std::string what = "scene " + std::to_string(scene_index);
  std::vector<bool> seen(character.nodes.size(), false);
  for (int n : model.scenes[static_cast<std::size_t>(scene_index)].nodes) {
    if (n < 0 || static_cast<std::size_t>(n) >= character.nodes.size()) {
      return error_at(what, "node " + std::to_string(n) + " out of range (" +
                                std::to_string(character.nodes.size()) + " nodes)");
    }
    if (character.nodes[static_cast<std::size_t>(n)].parent >= 0) {
      return error_at(what, "node " + std::to_string(n) + " is not a root (its parent is node " +
                                std::to_string(character.nodes[static_cast<std::size_t>(n)].parent) + ")");
    }
    if (seen[static_cast<std::size_t>(n)]) {
      return error_at(what, "lists node " + std::to_string(n) + " twice");
    }
    seen[static_cast<std::size_t>(n)] = true;
    character.roots.push_back(n);
  }
  return {};
}

}  // namespace

Status import_hierarchy(ImportContext& ctx, Character& character) {
  const tinygltf::Model& model = ctx.model;
  character.nodes.clear();
  character.nodes.reserve(model.nodes.size());
  for (std::size_t i = 0; i < model.nodes.size(); ++i) {
    auto node = convert_node(model, i);
    if (!node) return node.error();
    character.nodes.push_back(std::move(*node));
  }
  PROXYGI_IMPORT_TRY(link_children(model, character.nodes));
  PROXYGI_IMPORT_TRY(order_nodes(character));
  return find_roots(model, character);
}

}  // namespace proxygi::anim::detail
