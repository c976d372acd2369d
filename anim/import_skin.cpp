// Skins: joint lists, inverse bind matrices (identity when absent), and the palette check that
// every JOINTS_n value of every mesh drawn with a skin is < that skin's joint count.
#include "anim/import_accessor.h"
#include "anim/import_context.h"

namespace proxygi::anim::detail {
namespace {

Result<Skin> convert_skin(ImportContext& ctx, std::size_t index) {
  const tinygltf::Skin& source = ctx.model.skins[index];
  const std::string what = "skin " + std::to_string(index);
  const std::size_t node_count = ctx.model.nodes.size();
  Skin skin;
  skin.name = source.name;
  if (source.joints.empty()) return error_at(what, "has no joints");
  if (source.joints.size() > ctx.limits.max_objects) {
    return error_at(what, std::to_string(source.joints.size()) + " joints exceed the limit of " +
                              std::to_string(ctx.limits.max_objects));
  }
  std::vector<bool> used(node_count, false);
  for (std::size_t j = 0; j < source.joints.size(); ++j) {
    const int node = source.joints[j];
    if (node < 0 || static_cast<std::size_t>(node) >= node_count) {
      return error_at(what, "joint " + std::to_string(j) + " is node " + std::to_string(node) +
                                ", out of range (" + std::to_string(node_count) + " nodes)");
    }
    if (used[static_cast<std::size_t>(node)]) {
      return error_at(what, "joint " + std::to_string(j) + " repeats node " + std::to_string(node));
    }
    used[static_cast<std::size_t>(node)] = true;
    skin.joints.push_back(node);
  }
  if (source.skeleton < -1 || (source.skeleton >= 0 && static_cast<std::size_t>(source.skeleton) >= node_count)) {
    return error_at(what, "skeleton node " + std::to_string(source.skeleton) + " out of range (" +
                              std::to_string(node_count) + " nodes)");
  }
  skin.skeleton = source.skeleton;
  if (source.inverseBindMatrices < 0) {
    skin.inverse_bind_matrices.assign(skin.joints.size(), glm::mat4(1.0f));
    return skin;
  }
  auto matrices = read_float_accessor(ctx, source.inverseBindMatrices, what + " inverseBindMatrices",
                                      {TINYGLTF_TYPE_MAT4}, {TINYGLTF_COMPONENT_TYPE_FLOAT});
  if (!matrices) return matrices.error();
  if (matrices->count < skin.joints.size()) {
    return error_at(what, "inverseBindMatrices has " + std::to_string(matrices->count) +
                              " matrices for " + std::to_string(skin.joints.size()) + " joints");
  }
  skin.inverse_bind_matrices.resize(skin.joints.size());
  for (std::size_t j = 0; j < skin.joints.size(); ++j) {
    glm::mat4& m = skin.inverse_bind_matrices[j];
    for (int column = 0; column < 4; ++column) {
      for (int row = 0; row < 4; ++row) {
        m[column][row] = matrices->values[16 * j + static_cast<std::size_t>(4 * column + row)];
      }
    }
  }
  return skin;
}

// Every primitive of a skinned node's mesh has influences, all < the skin's joint count.
Status check_palette(const Character& character, std::size_t node_index) {
  const Node& node = character.nodes[node_index];
  const Skin& skin = character.skins[static_cast<std::size_t>(node.skin)];
  const Mesh& mesh = character.meshes[static_cast<std::size_t>(node.mesh)];
  const std::string skin_what = "skin " + std::to_string(node.skin);
  for (std::size_t p = 0; p < mesh.primitives.size(); ++p) {
    const Primitive& primitive = mesh.primitives[p];
    const std::string where = "mesh " + std::to_string(node.mesh) + " primitive " + std::to_string(p);
    if (primitive.influences_per_vertex == 0) {
      return error_at("node " + std::to_string(node_index),
                      "uses " + skin_what + " but " + where + " has no JOINTS_0/WEIGHTS_0");
    }
    for (std::size_t i = 0; i < primitive.joints.size(); ++i) {
      if (primitive.joints[i] >= skin.joints.size()) {
        const auto per_vertex = static_cast<std::size_t>(primitive.influences_per_vertex);
        return error_at(skin_what, "joint index " + std::to_string(primitive.joints[i]) +
                                       " out of range (" + std::to_string(skin.joints.size()) +
                                       " joints) in " + where + " (vertex " +
                                       std::to_string(i / per_vertex) + ", used by node " +
                                       std::to_string(node_index) + ")");
      }
    }
  }
  return {};
}

}  // namespace

Status import_skins(ImportContext& ctx, Character& character) {
  character.skins.clear();
  for (std::size_t s = 0; s < ctx.model.skins.size(); ++s) {
    auto skin = convert_skin(ctx, s);
    if (!skin) return skin.error();
    character.skins.push_back(std::move(*skin));
  }
  for (std::size_t n = 0; n < character.nodes.size(); ++n) {
    if (character.nodes[n].skin >= 0) PROXYGI_IMPORT_TRY(check_palette(character, n));
  }
  return {};
}

}  // namespace proxygi::anim::detail
