// validate_gltf: the checks of anim/gltf_validate.h, each collecting issues instead of stopping.
// Structure and references first (so data checks only follow indices known to be in range), then
// every accessor's data through the importer's checked reader (import_accessor.h), then the
// per-primitive, per-skin and per-animation checks that need decoded values.
#include "anim/gltf_validate.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <optional>
#include <set>
#include <sstream>

#include <glm/gtc/type_ptr.hpp>

#include "anim/import_accessor.h"
#include "anim/import_context.h"
#include "base/atomic_file.h"

namespace proxygi::anim {
namespace {

using Severity = ValidationIssue::Severity;
using detail::FloatAccessor;

constexpr double kWeightSumTolerance = 2e-3;  // glTF-Validator's bound for float weights

std::string at(const std::string& kind, std::size_t index) { return "/" + kind + "/" + std::to_string(index); }

std::string list(const std::vector<double>& values) {
  std::ostringstream out;
  out << '[';
  for (std::size_t i = 0; i < values.size(); ++i) out << (i ? ", " : "") << values[i];
  out << ']';
  return out.str();
}

class Validator {
 public:
  Validator(const tinygltf::Model& model, const ImportLimits& limits, const std::filesystem::path& root, ValidationReport& report)
      : model_(model), ctx_{model, limits, root}, report_(report) {}

  void run() {
    references();
    hierarchy();
    names();
    for (std::size_t i = 0; i < model_.accessors.size(); ++i) accessor_data(int(i));
    for (std::size_t m = 0; m < model_.meshes.size(); ++m)
      for (std::size_t p = 0; p < model_.meshes[m].primitives.size(); ++p) primitive(m, p);
    for (std::size_t s = 0; s < model_.skins.size(); ++s) skin(s);
    for (std::size_t a = 0; a < model_.animations.size(); ++a) animation(a);
  }

 private:
  void add(Severity severity, const std::string& pointer, const std::string& message) {
    report_.issues.push_back({severity, pointer, message});
  }
  // True when `index` is a valid index into `count` objects; else reports it.
  bool in_range(int index, std::size_t count, const std::string& pointer, const std::string& kind) {
    if (index >= 0 && std::size_t(index) < count) return true;
    add(Severity::error, pointer, kind + " " + std::to_string(index) + " out of range (" + std::to_string(count) + " " + kind + "s)");
    return false;
  }
  bool accessor_ok(int index) const { return index >= 0 && std::size_t(index) < model_.accessors.size() && decoded_.count(index); }

  void references() {
    for (std::size_t s = 0; s < model_.scenes.size(); ++s)
      for (std::size_t k = 0; k < model_.scenes[s].nodes.size(); ++k)
        in_range(model_.scenes[s].nodes[k], model_.nodes.size(), at("scenes", s) + "/nodes/" + std::to_string(k), "node");
    for (std::size_t n = 0; n < model_.nodes.size(); ++n) {
      const tinygltf::Node& node = model_.nodes[n];
      if (node.mesh >= 0) in_range(node.mesh, model_.meshes.size(), at("nodes", n) + "/mesh", "mesh");
      if (node.skin >= 0) in_range(node.skin, model_.skins.size(), at("nodes", n) + "/skin", "skin");
      for (std::size_t c = 0; c < node.children.size(); ++c)
        in_range(node.children[c], model_.nodes.size(), at("nodes", n) + "/children/" + std::to_string(c), "node");
    }
    for (std::size_t m = 0; m < model_.meshes.size(); ++m)
      for (std::size_t p = 0; p < model_.meshes[m].primitives.size(); ++p) {
        const tinygltf::Primitive& primitive = model_.meshes[m].primitives[p];
        const std::string where = at("meshes", m) + "/primitives/" + std::to_string(p);
        for (const auto& [name, accessor] : primitive.attributes)
          in_range(accessor, model_.accessors.size(), where + "/attributes/" + name, "accessor");
        if (primitive.indices >= 0) in_range(primitive.indices, model_.accessors.size(), where + "/indices", "accessor");
        if (primitive.material >= 0) in_range(primitive.material, model_.materials.size(), where + "/material", "material");
        if (primitive.mode != TINYGLTF_MODE_TRIANGLES && primitive.mode != TINYGLTF_MODE_TRIANGLE_STRIP &&
            primitive.mode != TINYGLTF_MODE_TRIANGLE_FAN)
          add(Severity::error, where + "/mode", "mode " + std::to_string(primitive.mode) + " is not triangles (proxygi draws triangles only)");
        if (!primitive.attributes.count("POSITION")) add(Severity::error, where + "/attributes", "no POSITION attribute");
      }
    for (std::size_t s = 0; s < model_.skins.size(); ++s) {
      const tinygltf::Skin& skin = model_.skins[s];
      for (std::size_t j = 0; j < skin.joints.size(); ++j)
        in_range(skin.joints[j], model_.nodes.size(), at("skins", s) + "/joints/" + std::to_string(j), "node");
      if (skin.skeleton >= 0) in_range(skin.skeleton, model_.nodes.size(), at("skins", s) + "/skeleton", "node");
      if (skin.inverseBindMatrices >= 0)
        in_range(skin.inverseBindMatrices, model_.accessors.size(), at("skins", s) + "/inverseBindMatrices", "accessor");
      else
        add(Severity::warning, at("skins", s), "no inverseBindMatrices: every joint's is taken as the identity");
    }
    for (std::size_t a = 0; a < model_.animations.size(); ++a) {
      const tinygltf::Animation& animation = model_.animations[a];
      for (std::size_t c = 0; c < animation.channels.size(); ++c) {
        const std::string where = at("animations", a) + "/channels/" + std::to_string(c);
        in_range(animation.channels[c].sampler, animation.samplers.size(), where + "/sampler", "sampler");
        in_range(animation.channels[c].target_node, model_.nodes.size(), where + "/target/node", "node");
      }
      for (std::size_t k = 0; k < animation.samplers.size(); ++k) {
        const std::string where = at("animations", a) + "/samplers/" + std::to_string(k);
        in_range(animation.samplers[k].input, model_.accessors.size(), where + "/input", "accessor");
        in_range(animation.samplers[k].output, model_.accessors.size(), where + "/output", "accessor");
      }
    }
    for (std::size_t m = 0; m < model_.materials.size(); ++m) {
      const int texture = model_.materials[m].pbrMetallicRoughness.baseColorTexture.index;
      if (texture >= 0)
        in_range(texture, model_.textures.size(), at("materials", m) + "/pbrMetallicRoughness/baseColorTexture/index", "texture");
    }
    for (std::size_t t = 0; t < model_.textures.size(); ++t)
      if (model_.textures[t].source >= 0) in_range(model_.textures[t].source, model_.images.size(), at("textures", t) + "/source", "image");
    for (std::size_t i = 0; i < model_.accessors.size(); ++i)
      if (model_.accessors[i].bufferView >= 0)
        in_range(model_.accessors[i].bufferView, model_.bufferViews.size(), at("accessors", i) + "/bufferView", "bufferView");
    for (std::size_t v = 0; v < model_.bufferViews.size(); ++v) {
      const tinygltf::BufferView& view = model_.bufferViews[v];
      if (!in_range(view.buffer, model_.buffers.size(), at("bufferViews", v) + "/buffer", "buffer")) continue;
      const std::uint64_t size = model_.buffers[std::size_t(view.buffer)].data.size();
      if (std::uint64_t(view.byteOffset) + std::uint64_t(view.byteLength) > size)
        add(Severity::error, at("bufferViews", v),
            "range [" + std::to_string(view.byteOffset) + ", +" + std::to_string(view.byteLength) + ") exceeds buffer " +
                std::to_string(view.buffer) + " (" + std::to_string(size) + " bytes)");
    }
  }

  // Every node at most one parent, and no cycles.
  void hierarchy() {
    std::vector<int> parent(model_.nodes.size(), -1);
    for (std::size_t n = 0; n < model_.nodes.size(); ++n)
      for (int child : model_.nodes[n].children) {
        if (child < 0 || std::size_t(child) >= parent.size()) continue;
        if (parent[std::size_t(child)] >= 0)
          add(Severity::error, at("nodes", std::size_t(child)),
              "has two parents (nodes " + std::to_string(parent[std::size_t(child)]) + " and " + std::to_string(n) + ")");
        else
          parent[std::size_t(child)] = int(n);
      }
    for (std::size_t n = 0; n < parent.size(); ++n) {
      std::size_t steps = 0;
      for (int p = parent[n]; p >= 0 && steps <= parent.size(); p = parent[std::size_t(p)]) ++steps;
      if (steps > parent.size()) add(Severity::error, at("nodes", n), "is its own ancestor (a cycle in the node graph)");
    }
  }

  void names() {
    std::map<std::string, std::size_t> first;
    for (std::size_t n = 0; n < model_.nodes.size(); ++n) {
      const std::string& name = model_.nodes[n].name;
      if (name.empty()) {
        add(Severity::warning, at("nodes", n), "has no name (rigs bind by node index; a person cannot tell it apart)");
      } else if (auto [it, fresh] = first.emplace(name, n); !fresh) {
        add(Severity::warning, at("nodes", n), "name \"" + name + "\" is also node " + std::to_string(it->second) + "'s");
      }
    }
  }

  // Reads the accessor's data as floats (float or normalized components) or unsigned integers;
  // reports what the reader refuses, and min/max that differ from the data.
  void accessor_data(int index) {
    const tinygltf::Accessor& accessor = model_.accessors[std::size_t(index)];
    const std::string pointer = at("accessors", std::size_t(index));
    if (accessor.bufferView >= 0 && std::size_t(accessor.bufferView) >= model_.bufferViews.size()) return;  // reported
    const std::vector<int> types = {TINYGLTF_TYPE_SCALAR, TINYGLTF_TYPE_VEC2, TINYGLTF_TYPE_VEC3, TINYGLTF_TYPE_VEC4,
                                    TINYGLTF_TYPE_MAT2,   TINYGLTF_TYPE_MAT3, TINYGLTF_TYPE_MAT4};
    FloatAccessor data;
    const bool floats = accessor.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT || accessor.normalized;
    if (floats) {
      auto read = detail::read_float_accessor(ctx_, index, "", types,
                                              {TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_COMPONENT_TYPE_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE,
                                               TINYGLTF_COMPONENT_TYPE_SHORT, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT});
      if (!read) return add(Severity::error, pointer, reader_message(read.message(), index));
      data = std::move(*read);
    } else {
      auto read = detail::read_uint_accessor(ctx_, index, "", types,
                                             {TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT,
                                              TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT});
      if (!read) {
        if (accessor.componentType == TINYGLTF_COMPONENT_TYPE_BYTE || accessor.componentType == TINYGLTF_COMPONENT_TYPE_SHORT)
          return;  // signed integers that are not normalized: no proxygi attribute uses them
        return add(Severity::error, pointer, reader_message(read.message(), index));
      }
      data.count = read->count;
      data.components = read->components;
      data.values.assign(read->values.begin(), read->values.end());
    }
    decoded_[index] = data;
    if (accessor.minValues.empty() && accessor.maxValues.empty()) return;
    std::vector<double> low(std::size_t(data.components), HUGE_VAL), high(std::size_t(data.components), -HUGE_VAL);
    for (std::size_t i = 0; i < data.values.size(); ++i) {
      const std::size_t c = i % std::size_t(data.components);
      low[c] = std::min(low[c], double(data.values[i]));
      high[c] = std::max(high[c], double(data.values[i]));
    }
    compare_bound(pointer, "min", accessor.minValues, low);
    compare_bound(pointer, "max", accessor.maxValues, high);
  }

  void compare_bound(const std::string& pointer, const char* which, const std::vector<double>& declared,
                     const std::vector<double>& actual) {
    if (declared.empty()) return;
    if (declared.size() != actual.size())
      return add(Severity::error, pointer + "/" + which,
                 std::string(which) + " has " + std::to_string(declared.size()) + " values, the type " + std::to_string(actual.size()));
    for (std::size_t c = 0; c < actual.size(); ++c)
      if (float(declared[c]) != float(actual[c]))  // as glTF-Validator: exact at the data's precision
        return add(Severity::error, pointer + "/" + which,
                   std::string(which) + " " + list(declared) + " is not the data's " + which + " " + list(actual));
  }

  // "...: accessor 3: problem" from the reader, without the parts the pointer already says.
  static std::string reader_message(const std::string& message, int index) {
    const std::string prefix = "accessor " + std::to_string(index) + ": ";
    const std::size_t found = message.find(prefix);
    return found == std::string::npos ? message : message.substr(found + prefix.size());
  }

  // Skins drawing this mesh (through nodes that have both).
  std::vector<std::size_t> skins_of_mesh(std::size_t mesh) const {
    std::set<std::size_t> skins;
    for (const tinygltf::Node& node : model_.nodes)
      if (node.mesh == int(mesh) && node.skin >= 0 && std::size_t(node.skin) < model_.skins.size()) skins.insert(std::size_t(node.skin));
    return {skins.begin(), skins.end()};
  }

  void primitive(std::size_t m, std::size_t p) {
    const tinygltf::Primitive& primitive = model_.meshes[m].primitives[p];
    const std::string where = at("meshes", m) + "/primitives/" + std::to_string(p);
    const auto position = primitive.attributes.find("POSITION");
    if (position == primitive.attributes.end() || !accessor_ok(position->second)) return;
    const std::size_t vertices = decoded_.at(position->second).count;
    for (const auto& [name, accessor] : primitive.attributes)
      if (accessor_ok(accessor) && decoded_.at(accessor).count != vertices)
        add(Severity::error, where + "/attributes/" + name,
            "count " + std::to_string(decoded_.at(accessor).count) + " differs from POSITION's " + std::to_string(vertices));
    if (accessor_ok(primitive.indices)) {
      const FloatAccessor& indices = decoded_.at(primitive.indices);
      std::size_t bad = 0, first = 0;
      for (std::size_t i = 0; i < indices.values.size(); ++i)
        if (indices.values[i] >= float(vertices) && bad++ == 0) first = i;
      if (bad > 0)
        add(Severity::error, where + "/indices",
            std::to_string(bad) + " indices >= the vertex count " + std::to_string(vertices) + " (index " + std::to_string(first) +
                " is " + std::to_string(std::uint64_t(indices.values[first])) + ")");
    }
    // Weights: the sum over every WEIGHTS_n set, per vertex.
    std::vector<double> sums(vertices, 0.0);
    bool weighted = false;
    for (int set = 0;; ++set) {
      const auto weights = primitive.attributes.find("WEIGHTS_" + std::to_string(set));
      if (weights == primitive.attributes.end()) break;
      if (!accessor_ok(weights->second) || decoded_.at(weights->second).count != vertices) return;
      const FloatAccessor& w = decoded_.at(weights->second);
      for (std::size_t v = 0; v < vertices; ++v)
        for (int c = 0; c < w.components; ++c) sums[v] += w.values[v * std::size_t(w.components) + std::size_t(c)];
      weighted = true;
    }
    if (weighted) {
      std::size_t bad = 0, first = 0;
      for (std::size_t v = 0; v < vertices; ++v)
        if (std::fabs(sums[v] - 1.0) > kWeightSumTolerance && bad++ == 0) first = v;
      if (bad > 0) {
        char text[160];
        std::snprintf(text, sizeof text, "%zu vertices' weights do not sum to 1 (vertex %zu: %.6g)", bad, first, sums[first]);
        add(Severity::error, where + "/attributes/WEIGHTS_0", text);
      }
    }
    for (std::size_t s : skins_of_mesh(m)) joints(where, primitive, s);
  }

  void joints(const std::string& where, const tinygltf::Primitive& primitive, std::size_t skin) {
    const std::size_t count = model_.skins[skin].joints.size();
    for (int set = 0;; ++set) {
      const std::string name = "JOINTS_" + std::to_string(set);
      const auto joints = primitive.attributes.find(name);
      if (joints == primitive.attributes.end()) break;
      if (!accessor_ok(joints->second)) continue;
      const FloatAccessor& j = decoded_.at(joints->second);
      std::size_t bad = 0, first = 0;
      for (std::size_t i = 0; i < j.values.size(); ++i)
        if (j.values[i] >= float(count) && bad++ == 0) first = i;
      if (bad > 0)
        add(Severity::error, where + "/attributes/" + name,
            std::to_string(bad) + " joint indices >= the " + std::to_string(count) + " joints of skin " + std::to_string(skin) +
                " (vertex " + std::to_string(first / std::size_t(std::max(j.components, 1))) + ": " +
                std::to_string(std::uint64_t(j.values[first])) + ")");
    }
  }

  void skin(std::size_t s) {
    const tinygltf::Skin& skin = model_.skins[s];
    if (!accessor_ok(skin.inverseBindMatrices)) return;
    const FloatAccessor& matrices = decoded_.at(skin.inverseBindMatrices);
    const std::string pointer = at("skins", s) + "/inverseBindMatrices";
    if (matrices.components != 16) return add(Severity::error, pointer, "accessor type is not MAT4");
    if (matrices.count != skin.joints.size())
      add(Severity::error, pointer,
          std::to_string(matrices.count) + " matrices for " + std::to_string(skin.joints.size()) + " joints");
    for (std::size_t i = 0; i < matrices.count; ++i) {
      const glm::mat4 matrix = glm::make_mat4(matrices.values.data() + 16 * i);
      if (!(std::fabs(glm::determinant(matrix)) > 1e-12f))
        return add(Severity::error, pointer, "matrix " + std::to_string(i) + " is not invertible");
    }
  }

  void animation(std::size_t a) {
    const tinygltf::Animation& animation = model_.animations[a];
    for (std::size_t k = 0; k < animation.samplers.size(); ++k) {
      const tinygltf::AnimationSampler& sampler = animation.samplers[k];
      const std::string where = at("animations", a) + "/samplers/" + std::to_string(k);
      if (!accessor_ok(sampler.input)) continue;
      const FloatAccessor& times = decoded_.at(sampler.input);
      for (std::size_t i = 0; i < times.values.size(); ++i)
        if (times.values[i] < 0.0f || (i > 0 && !(times.values[i] > times.values[i - 1]))) {
          add(Severity::error, where + "/input", "key time " + std::to_string(i) + " is negative or not after the one before");
          break;
        }
      if (!accessor_ok(sampler.output)) continue;
      const std::size_t outputs = decoded_.at(sampler.output).count;
      const std::size_t per_key = sampler.interpolation == "CUBICSPLINE" ? 3 : 1;
      if (outputs == 0 || outputs % (times.count * per_key) != 0)
        add(Severity::error, where + "/output",
            std::to_string(outputs) + " outputs for " + std::to_string(times.count) + " key times" +
                (per_key == 3 ? " (CUBICSPLINE needs 3 per key)" : ""));
    }
  }

  const tinygltf::Model& model_;
  detail::ImportContext ctx_;
  ValidationReport& report_;
  std::map<int, FloatAccessor> decoded_;  // accessors whose data read cleanly
};

}  // namespace

std::size_t ValidationReport::errors() const {
  return std::size_t(std::count_if(issues.begin(), issues.end(), [](const ValidationIssue& i) { return i.severity == Severity::error; }));
}
std::size_t ValidationReport::warnings() const { return issues.size() - errors(); }

const char* severity_name(ValidationIssue::Severity severity) { return severity == Severity::error ? "error" : "warning"; }

ValidationReport validate_gltf(const std::filesystem::path& path, const ImportLimits& limits) {
  ValidationReport report;
  report.source = path.string();
  auto bytes = read_file(path, limits.max_file_bytes);
  if (!bytes) {
    report.issues.push_back({Severity::error, "", bytes.message()});
    return report;
  }
  std::filesystem::path folder = path.parent_path();
  if (folder.empty()) folder = ".";
  tinygltf::Model model;
  std::filesystem::path root;
  std::string warning;
  if (Status loaded = detail::load_model(*bytes, folder, limits, model, root, warning); !loaded) {
    report.issues.push_back({Severity::error, "", loaded.message()});
    return report;
  }
  std::istringstream lines(warning);
  for (std::string line; std::getline(lines, line);)
    if (!line.empty()) report.issues.push_back({Severity::warning, "", "tinygltf: " + line});
  Validator(model, limits, root, report).run();
  // The importer has the last word: a refusal no check above named is an error too.
  if (report.errors() == 0)
    if (auto imported = import_gltf_bytes(*bytes, path.string(), folder, limits); !imported)
      report.issues.push_back({Severity::error, "", imported.message()});
  return report;
}

}  // namespace proxygi::anim
