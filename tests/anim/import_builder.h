#pragma once
// Test helper: builds small glTF assets in memory (JSON via nlohmann, one binary buffer) and
// serializes them as .gltf with a data: URI, as .gltf with an external .bin, or as .glb. Tests
// then edit the JSON to break exactly one rule.
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace proxygi::anim::testing {

inline constexpr int kByte = 5120, kUByte = 5121, kShort = 5122, kUShort = 5123, kUInt = 5125, kFloat = 5126;

class GltfBuilder {
 public:
  GltfBuilder() { json_ = {{"asset", {{"version", "2.0"}}}, {"bufferViews", nlohmann::json::array()}, {"accessors", nlohmann::json::array()}}; }

  nlohmann::json& json() { return json_; }
  std::vector<std::uint8_t>& bin() { return bin_; }

  template <class T>
  int view(const std::vector<T>& values, int stride = 0) {
    const auto* first = reinterpret_cast<const std::uint8_t*>(values.data());
    return raw_view(std::vector<std::uint8_t>(first, first + values.size() * sizeof(T)), stride);
  }

  // Not inlined: GCC 12 reports a false free-nonheap-object when it inlines this into tests.
  [[gnu::noinline]] int raw_view(const std::vector<std::uint8_t>& bytes, int stride = 0) {
    while (bin_.size() % 4 != 0) bin_.push_back(0);
    nlohmann::json v = {{"buffer", 0}, {"byteOffset", bin_.size()}, {"byteLength", bytes.size()}};
    if (stride != 0) v["byteStride"] = stride;
    bin_.insert(bin_.end(), bytes.begin(), bytes.end());
    json_["bufferViews"].push_back(v);
    return static_cast<int>(json_["bufferViews"].size()) - 1;
  }

  int accessor(int view, int component_type, std::size_t count, const std::string& type, nlohmann::json extra = {}) {
    nlohmann::json a = {{"componentType", component_type}, {"count", count}, {"type", type}};
    if (view >= 0) a["bufferView"] = view;
    if (extra.is_object()) a.update(extra);
    json_["accessors"].push_back(a);
    return static_cast<int>(json_["accessors"].size()) - 1;
  }

  template <class T>
  int accessor_of(const std::vector<T>& values, int component_type, std::size_t count, const std::string& type,
                  nlohmann::json extra = {}) {
    return accessor(view(values), component_type, count, type, std::move(extra));
  }

  // .gltf text with the buffer as a base64 data: URI.
  std::string gltf_text() const {
    nlohmann::json j = json_;
    j["buffers"] = nlohmann::json::array({{{"byteLength", bin_.size()}, {"uri", "data:application/octet-stream;base64," + base64(bin_)}}});
    return j.dump();
  }
  std::vector<std::uint8_t> gltf_bytes() const {
    const std::string text = gltf_text();
    return std::vector<std::uint8_t>(text.begin(), text.end());
  }

  // Writes <folder>/<name>.gltf and <folder>/<bin_name>; returns the .gltf path.
  std::filesystem::path write_with_external_bin(const std::filesystem::path& folder, const std::string& name,
                                                const std::string& bin_name) const {
    std::filesystem::create_directories(folder);
    nlohmann::json j = json_;
    j["buffers"] = nlohmann::json::array({{{"byteLength", bin_.size()}, {"uri", bin_name}}});
    std::ofstream(folder / bin_name, std::ios::binary).write(reinterpret_cast<const char*>(bin_.data()),
                                                             static_cast<std::streamsize>(bin_.size()));
    const auto path = folder / (name + ".gltf");
    std::ofstream(path) << j.dump();
    return path;
  }

  std::vector<std::uint8_t> glb_bytes() const {
    nlohmann::json j = json_;
    j["buffers"] = nlohmann::json::array({{{"byteLength", bin_.size()}}});
    std::string text = j.dump();
    while (text.size() % 4 != 0) text.push_back(' ');
    std::vector<std::uint8_t> binary = bin_;
    while (binary.size() % 4 != 0) binary.push_back(0);
    std::vector<std::uint8_t> out = {'g', 'l', 'T', 'F'};
    put(out, 2);
    put(out, static_cast<std::uint32_t>(12 + 8 + text.size() + 8 + binary.size()));
    put(out, static_cast<std::uint32_t>(text.size()));
    put(out, 0x4E4F534Au);
    out.insert(out.end(), text.begin(), text.end());
    put(out, static_cast<std::uint32_t>(binary.size()));
    put(out, 0x004E4942u);
    out.insert(out.end(), binary.begin(), binary.end());
    return out;
  }

  static std::string base64(const std::vector<std::uint8_t>& data) {
    static const char* table = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (std::size_t i = 0; i < data.size(); i += 3) {
      const std::uint32_t n = (static_cast<std::uint32_t>(data[i]) << 16) |
                              (i + 1 < data.size() ? static_cast<std::uint32_t>(data[i + 1]) << 8 : 0u) |
                              (i + 2 < data.size() ? static_cast<std::uint32_t>(data[i + 2]) : 0u);
      out.push_back(table[(n >> 18) & 63]);
      out.push_back(table[(n >> 12) & 63]);
      out.push_back(i + 1 < data.size() ? table[(n >> 6) & 63] : '=');
      out.push_back(i + 2 < data.size() ? table[n & 63] : '=');
    }
    return out;
  }

 private:
  static void put(std::vector<std::uint8_t>& out, std::uint32_t value) {
    for (int i = 0; i < 4; ++i) out.push_back(static_cast<std::uint8_t>(value >> (8 * i)));
  }

  nlohmann::json json_;
  std::vector<std::uint8_t> bin_;
};

// A skinned quad (2 triangles, 4 vertices, 2 joints), one clip rotating joint 1. Accessors:
// 0 POSITION, 1 NORMAL, 2 indices, 3 JOINTS_0, 4 WEIGHTS_0, 5 IBM, 6 times, 7 rotations.
// Nodes: 0 root (children 1, 3), 1 joint0 (child 2), 2 joint1, 3 skinned mesh node.
inline GltfBuilder skinned_quad() {
  GltfBuilder b;
  b.accessor_of(std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0}, kFloat, 4, "VEC3",
                {{"min", {0, 0, 0}}, {"max", {1, 1, 0}}});
  b.accessor_of(std::vector<float>{0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1}, kFloat, 4, "VEC3");
  b.accessor_of(std::vector<std::uint16_t>{0, 1, 2, 2, 1, 3}, kUShort, 6, "SCALAR");
  b.accessor_of(std::vector<std::uint8_t>{0, 1, 0, 0, 0, 1, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0}, kUByte, 4, "VEC4");
  b.accessor_of(std::vector<float>{1, 0, 0, 0, 0.5f, 0.5f, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0}, kFloat, 4, "VEC4");
  b.accessor_of(std::vector<float>{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1,
                                   1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, -1, 0, 1},
                kFloat, 2, "MAT4");
  b.accessor_of(std::vector<float>{0.5f, 1.0f, 2.0f}, kFloat, 3, "SCALAR", {{"min", {0.5}}, {"max", {2.0}}});
  b.accessor_of(std::vector<float>{0, 0, 0, 1, 0, 0, 0.70710678f, 0.70710678f, 0, 0, 1, 0}, kFloat, 3, "VEC4");
  auto& j = b.json();
  j["meshes"] = {{{"name", "quad"},
                  {"primitives", {{{"attributes", {{"POSITION", 0}, {"NORMAL", 1}, {"JOINTS_0", 3}, {"WEIGHTS_0", 4}}},
                                   {"indices", 2}}}}}};
  j["nodes"] = {{{"name", "root"}, {"children", {1, 3}}},
                {{"name", "joint0"}, {"children", {2}}},
                {{"name", "joint1"}, {"translation", {0, 1, 0}}},
                {{"name", "body"}, {"mesh", 0}, {"skin", 0}}};
  j["skins"] = {{{"joints", {1, 2}}, {"inverseBindMatrices", 5}}};
  j["animations"] = {{{"name", "bend"},
                      {"samplers", {{{"input", 6}, {"output", 7}}}},
                      {"channels", {{{"sampler", 0}, {"target", {{"node", 2}, {"path", "rotation"}}}}}}}};
  j["scenes"] = {{{"nodes", {0}}}};
  j["scene"] = 0;
  return b;
}

}  // namespace proxygi::anim::testing
