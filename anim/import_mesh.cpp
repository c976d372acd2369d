// Meshes: primitives converted to indexed triangle lists with positions, normals, UV0,
// skinning influences (all JOINTS_n/WEIGHTS_n sets, renormalized) and morph targets.
#include <algorithm>
#include <cmath>

#include "anim/import_accessor.h"
#include "anim/import_context.h"

namespace proxygi::anim::detail {
namespace {

constexpr int kFloat = TINYGLTF_COMPONENT_TYPE_FLOAT;
constexpr int kUByte = TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE;
constexpr int kUShort = TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
constexpr int kUInt = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;

std::vector<glm::vec3> to_vec3(const FloatAccessor& data) {
  std::vector<glm::vec3> out(data.count);
  for (std::size_t i = 0; i < data.count; ++i) {
    out[i] = glm::vec3(data.values[3 * i], data.values[3 * i + 1], data.values[3 * i + 2]);
  }
  return out;
}

Result<std::vector<glm::vec3>> read_vec3(ImportContext& ctx, int accessor, const std::string& what,
                                         std::size_t expected_count) {
  auto data = read_float_accessor(ctx, accessor, what, {TINYGLTF_TYPE_VEC3}, {kFloat});
  if (!data) return data.error();
  if (data->count != expected_count) {
    return error_at(what, "accessor " + std::to_string(accessor) + " has " +
                              std::to_string(data->count) + " elements, POSITION has " +
                              std::to_string(expected_count));
  }
  return to_vec3(*data);
}

// Triangle list from the primitive's mode; strips keep the winding of their first triangle.
Result<std::vector<std::uint32_t>> triangulate(std::vector<std::uint32_t> indices, int mode,
                                               const std::string& what) {
  switch (mode) {
    case TINYGLTF_MODE_TRIANGLES:
      if (indices.size() % 3 != 0) {
        return error_at(what, std::to_string(indices.size()) +
                                  " indices is not a multiple of 3 (TRIANGLES)");
      }
      return indices;
    case TINYGLTF_MODE_TRIANGLE_STRIP: {
      std::vector<std::uint32_t> out;
      for (std::size_t i = 2; i < indices.size(); ++i) {
        const bool even = (i % 2) == 0;
        out.insert(out.end(), {indices[i - 2], even ? indices[i - 1] : indices[i],
                               even ? indices[i] : indices[i - 1]});
      }
      return out;
    }
    case TINYGLTF_MODE_TRIANGLE_FAN: {
      std::vector<std::uint32_t> out;
      for (std::size_t i = 2; i < indices.size(); ++i) {
        out.insert(out.end(), {indices[0], indices[i - 1], indices[i]});
      }
      return out;
    }
    case TINYGLTF_MODE_POINTS:
    case TINYGLTF_MODE_LINE:
    case TINYGLTF_MODE_LINE_LOOP:
    case TINYGLTF_MODE_LINE_STRIP:
      return error_at(what, "mode " + std::to_string(mode) +
                                " (points or lines) is not supported; only triangles, strips and fans");
    default:
      return error_at(what, "mode " + std::to_string(mode) + " is not a glTF primitive mode");
  }
}

bool has_prefix(const std::string& text, const std::string& prefix) {
  return text.compare(0, prefix.size(), prefix) == 0;
}

// JOINTS_n/WEIGHTS_n sets 0..k-1, both present for each n and nothing beyond.
Status read_influences(ImportContext& ctx, const tinygltf::Primitive& source, const std::string& what,
                       Primitive& primitive) {
  int sets = 0;
  while (source.attributes.count("JOINTS_" + std::to_string(sets)) != 0 ||
         source.attributes.count("WEIGHTS_" + std::to_string(sets)) != 0) {
    ++sets;
  }
  for (const auto& [name, accessor] : source.attributes) {
    (void)accessor;
    if (!has_prefix(name, "JOINTS_") && !has_prefix(name, "WEIGHTS_")) continue;
    const std::string suffix = name.substr(name.find('_') + 1);
    const bool in_range = !suffix.empty() && suffix.size() < 4 &&
                          std::all_of(suffix.begin(), suffix.end(), [](char c) { return c >= '0' && c <= '9'; }) &&
                          std::stoi(suffix) < sets && std::to_string(std::stoi(suffix)) == suffix;
    if (!in_range) return error_at(what, "attribute " + name + " does not continue JOINTS_0/WEIGHTS_0");
  }
  const std::size_t vertices = primitive.positions.size();
  const auto per_vertex = static_cast<std::size_t>(4 * sets);
  primitive.influences_per_vertex = 4 * sets;
  primitive.joints.assign(vertices * per_vertex, 0);
  primitive.weights.assign(vertices * per_vertex, 0.0f);
  for (int set = 0; set < sets; ++set) {
    const std::string joints_name = "JOINTS_" + std::to_string(set);
    const std::string weights_name = "WEIGHTS_" + std::to_string(set);
    const auto joints_it = source.attributes.find(joints_name);
    const auto weights_it = source.attributes.find(weights_name);
    if (joints_it == source.attributes.end() || weights_it == source.attributes.end()) {
      return error_at(what, "has " + (joints_it == source.attributes.end() ? weights_name : joints_name) +
                                " without " +
                                (joints_it == source.attributes.end() ? joints_name : weights_name));
    }
    auto joints = read_uint_accessor(ctx, joints_it->second, what + " " + joints_name,
                                     {TINYGLTF_TYPE_VEC4}, {kUByte, kUShort});
    if (!joints) return joints.error();
    auto weights = read_float_accessor(ctx, weights_it->second, what + " " + weights_name,
                                       {TINYGLTF_TYPE_VEC4}, {kFloat, kUByte, kUShort});
    if (!weights) return weights.error();
    if (joints->count != vertices || weights->count != vertices) {
      return error_at(what, joints_name + "/" + weights_name + " have " +
                                std::to_string(joints->count) + "/" + std::to_string(weights->count) +
                                " elements, POSITION has " + std::to_string(vertices));
    }
    for (std::size_t v = 0; v < vertices; ++v) {
      for (std::size_t k = 0; k < 4; ++k) {
        const std::size_t slot = v * per_vertex + static_cast<std::size_t>(set) * 4 + k;
        primitive.joints[slot] = static_cast<std::uint16_t>(joints->values[4 * v + k]);
        const float weight = weights->values[4 * v + k];
        if (weight < 0.0f) {
          return error_at(what + " " + weights_name, "vertex " + std::to_string(v) +
                                                         " has negative weight " + std::to_string(weight));
        }
        primitive.weights[slot] = weight;
      }
    }
  }
  // Renormalize; an all-zero vertex is bound rigidly to joint 0 (documented in character.h).
  for (std::size_t v = 0; v < vertices && per_vertex > 0; ++v) {
    float* w = primitive.weights.data() + v * per_vertex;
    double sum = 0.0;
    for (std::size_t k = 0; k < per_vertex; ++k) sum += w[k];
    if (sum > 0.0 && std::isfinite(sum)) {
      for (std::size_t k = 0; k < per_vertex; ++k) w[k] = static_cast<float>(w[k] / sum);
    } else {
      std::fill(w, w + per_vertex, 0.0f);
      w[0] = 1.0f;
      primitive.joints[v * per_vertex] = 0;
    }
  }
  return {};
}

Status read_morph_targets(ImportContext& ctx, const tinygltf::Primitive& source, const std::string& what,
                          Primitive& primitive) {
  for (std::size_t t = 0; t < source.targets.size(); ++t) {
    const std::string target_what = what + " target " + std::to_string(t);
    MorphTarget target;
    for (const auto& [name, accessor] : source.targets[t]) {
      if (name != "POSITION" && name != "NORMAL") continue;  // TANGENT etc. are not used
      auto deltas = read_vec3(ctx, accessor, target_what + " " + name, primitive.positions.size());
      if (!deltas) return deltas.error();
      (name == "POSITION" ? target.position_deltas : target.normal_deltas) = std::move(*deltas);
    }
    primitive.morph_targets.push_back(std::move(target));
  }
  return {};
}

Result<Primitive> convert_primitive(ImportContext& ctx, const tinygltf::Primitive& source,
                                    const std::string& what) {
  Primitive primitive;
  const auto position_it = source.attributes.find("POSITION");
  if (position_it == source.attributes.end()) return error_at(what, "has no POSITION attribute");
  auto positions = read_float_accessor(ctx, position_it->second, what + " POSITION",
                                       {TINYGLTF_TYPE_VEC3}, {kFloat});
  if (!positions) return positions.error();
  primitive.positions = to_vec3(*positions);
  const std::size_t vertices = primitive.positions.size();

  if (source.material < -1 || (source.material >= 0 && static_cast<std::size_t>(source.material) >= ctx.model.materials.size())) {
    return error_at(what, "material " + std::to_string(source.material) + " out of range (" +
                              std::to_string(ctx.model.materials.size()) + " materials)");
  }
  primitive.material = source.material;

  std::vector<std::uint32_t> indices;
  if (source.indices >= 0) {
    auto read = read_uint_accessor(ctx, source.indices, what + " indices", {TINYGLTF_TYPE_SCALAR},
                                   {kUByte, kUShort, kUInt});
    if (!read) return read.error();
    for (std::size_t i = 0; i < read->values.size(); ++i) {
      if (read->values[i] >= vertices) {
        return error_at(what + " indices", "index " + std::to_string(read->values[i]) + " at position " +
                                               std::to_string(i) + " out of range (" +
                                               std::to_string(vertices) + " vertices)");
      }
    }
    indices = std::move(read->values);
  } else {
    indices.resize(vertices);
    for (std::size_t i = 0; i < vertices; ++i) indices[i] = static_cast<std::uint32_t>(i);
  }
  auto triangles = triangulate(std::move(indices), source.mode, what);
  if (!triangles) return triangles.error();
  primitive.indices = std::move(*triangles);

  if (const auto it = source.attributes.find("NORMAL"); it != source.attributes.end()) {
    auto normals = read_vec3(ctx, it->second, what + " NORMAL", vertices);
    if (!normals) return normals.error();
    primitive.normals = std::move(*normals);
    for (glm::vec3& n : primitive.normals) {
      const float length = glm::length(n);
      n = length > 1e-12f ? n / length : glm::vec3(0.0f, 1.0f, 0.0f);
    }
  } else {
    primitive.normals = compute_vertex_normals(primitive.positions, primitive.indices);
  }
  if (const auto it = source.attributes.find("TEXCOORD_0"); it != source.attributes.end()) {
    auto uvs = read_float_accessor(ctx, it->second, what + " TEXCOORD_0", {TINYGLTF_TYPE_VEC2},
                                   {kFloat, kUByte, kUShort});
    if (!uvs) return uvs.error();
    if (uvs->count != vertices) {
      return error_at(what + " TEXCOORD_0", std::to_string(uvs->count) + " elements, POSITION has " +
                                                std::to_string(vertices));
    }
    primitive.uvs.resize(vertices);
    for (std::size_t i = 0; i < vertices; ++i) {
      primitive.uvs[i] = glm::vec2(uvs->values[2 * i], uvs->values[2 * i + 1]);
    }
  }
  PROXYGI_IMPORT_TRY(read_influences(ctx, source, what, primitive));
  PROXYGI_IMPORT_TRY(read_morph_targets(ctx, source, what, primitive));
  return primitive;
}

}  // namespace

Status import_meshes(ImportContext& ctx, Character& character) {
  const auto& meshes = ctx.model.meshes;
  character.meshes.clear();
  character.meshes.reserve(meshes.size());
  for (std::size_t m = 0; m < meshes.size(); ++m) {
    const std::string mesh_what = "mesh " + std::to_string(m);
    const tinygltf::Mesh& source = meshes[m];
    if (source.primitives.empty()) return error_at(mesh_what, "has no primitives");
    if (source.primitives.size() > ctx.limits.max_objects) {
      return error_at(mesh_what, std::to_string(source.primitives.size()) +
                                     " primitives exceed the limit of " +
                                     std::to_string(ctx.limits.max_objects));
    }
    Mesh mesh;
    mesh.name = source.name;
    for (std::size_t p = 0; p < source.primitives.size(); ++p) {
      auto primitive = convert_primitive(ctx, source.primitives[p],
                                         mesh_what + " primitive " + std::to_string(p));
      if (!primitive) return primitive.error();
      if (p > 0 && primitive->morph_targets.size() != mesh.primitives[0].morph_targets.size()) {
        return error_at(mesh_what + " primitive " + std::to_string(p),
                        std::to_string(primitive->morph_targets.size()) + " morph targets, primitive 0 has " +
                            std::to_string(mesh.primitives[0].morph_targets.size()));
      }
      mesh.primitives.push_back(std::move(*primitive));
    }
    const std::size_t targets = mesh.primitives[0].morph_targets.size();
    if (!source.weights.empty() && source.weights.size() != targets) {
      return error_at(mesh_what, "has " + std::to_string(source.weights.size()) + " weights for " +
                                     std::to_string(targets) + " morph targets");
    }
    for (double w : source.weights) {
      if (!std::isfinite(w)) return error_at(mesh_what, "weights contain NaN or infinity");
      mesh.default_morph_weights.push_back(static_cast<float>(w));
    }
    if (source.weights.empty()) mesh.default_morph_weights.assign(targets, 0.0f);
    character.meshes.push_back(std::move(mesh));
  }
  for (std::size_t n = 0; n < character.nodes.size(); ++n) {  // node.weights override mesh.weights
    const Node& node = character.nodes[n];
    if (node.morph_weights.empty()) continue;
    const std::size_t targets = character.meshes[static_cast<std::size_t>(node.mesh)].primitives[0].morph_targets.size();
    if (node.morph_weights.size() != targets) {
      return error_at("node " + std::to_string(n), "has " + std::to_string(node.morph_weights.size()) +
                                                       " weights for " + std::to_string(targets) +
                                                       " morph targets of mesh " + std::to_string(node.mesh));
    }
  }
  return {};
}

}  // namespace proxygi::anim::detail
