#include "tests/cli/write_defects.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <limits>
#include <vector>

#include <nlohmann/json.hpp>

#include "anim/gltf_writer.h"
#include "anim/mannequin.h"

namespace {

using Bytes = std::vector<std::uint8_t>;

std::uint32_t read_u32(const Bytes& bytes, std::size_t at) {
  std::uint32_t value = 0;
  std::memcpy(&value, bytes.data() + at, 4);
  return value;
}
void append_u32(Bytes& bytes, std::uint32_t value) {
  const auto* p = reinterpret_cast<const std::uint8_t*>(&value);
  bytes.insert(bytes.end(), p, p + 4);
}

// Byte offset in the BIN chunk of component `component` of element `element` of an accessor.
std::size_t element_offset(const nlohmann::json& gltf, int accessor, std::size_t element, std::size_t component,
                           std::size_t component_size, std::size_t components) {
  const nlohmann::json& a = gltf["accessors"][std::size_t(accessor)];
  const nlohmann::json& view = gltf["bufferViews"][a["bufferView"].get<std::size_t>()];
  const std::size_t stride = view.value("byteStride", component_size * components);
  return view.value("byteOffset", std::size_t(0)) + a.value("byteOffset", std::size_t(0)) + element * stride +
         component * component_size;
}

}  // namespace

std::string write_defects(const std::filesystem::path& dir) {
  auto glb = proxygi::anim::encode_glb(proxygi::anim::build_mannequin());
  if (!glb) return glb.message();
  const Bytes& bytes = *glb;
  const std::uint32_t json_length = read_u32(bytes, 12);
  nlohmann::json gltf = nlohmann::json::parse(bytes.begin() + 20, bytes.begin() + 20 + json_length);
  const std::size_t bin_at = 20 + json_length;
  Bytes bin(bytes.begin() + std::ptrdiff_t(bin_at + 8), bytes.begin() + std::ptrdiff_t(bin_at + 8 + read_u32(bytes, bin_at)));
  std::vector<std::string> expected;

  // The first skinned primitive with normals and indices.
  std::size_t mesh = 0;
  while (mesh < gltf["meshes"].size() && !gltf["meshes"][mesh]["primitives"][0]["attributes"].contains("JOINTS_0")) ++mesh;
  if (mesh == gltf["meshes"].size()) return "the mannequin has no skinned mesh";
  nlohmann::json& primitive = gltf["meshes"][mesh]["primitives"][0];
  const std::string where = "/meshes/" + std::to_string(mesh) + "/primitives/0";
  const int position = primitive["attributes"]["POSITION"], normal = primitive["attributes"]["NORMAL"];
  const int joints = primitive["attributes"]["JOINTS_0"], weights = primitive["attributes"]["WEIGHTS_0"];
  const int indices = primitive["indices"];

  // 1. POSITION max unlike the data.
  gltf["accessors"][std::size_t(position)]["max"] = {9.0, 9.0, 9.0};
  expected.push_back("error /accessors/" + std::to_string(position) + "/max");
  // 2. A vertex index past the vertex count.
  const std::uint32_t too_far = 99999;
  std::memcpy(bin.data() + element_offset(gltf, indices, 0, 0, 4, 1), &too_far, 4);
  expected.push_back("error " + where + "/indices");
  // 3. Vertex 0's weights sum to 0.5.
  const float half[4] = {0.5f, 0.0f, 0.0f, 0.0f};
  std::memcpy(bin.data() + element_offset(gltf, weights, 0, 0, 4, 4), half, sizeof half);
  expected.push_back("error " + where + "/attributes/WEIGHTS_0");
  // 4. Vertex 1's first joint out of the skin's range.
  const std::uint16_t joint = 999;
  std::memcpy(bin.data() + element_offset(gltf, joints, 1, 0, 2, 4), &joint, 2);
  expected.push_back("error " + where + "/attributes/JOINTS_0");
  // 5. A NaN normal.
  const float nan = std::numeric_limits<float>::quiet_NaN();
  std::memcpy(bin.data() + element_offset(gltf, normal, 2, 0, 4, 3), &nan, 4);
  expected.push_back("error /accessors/" + std::to_string(normal));
  // 6. An unnamed node, and a node named like another.
  gltf["nodes"][1].erase("name");
  gltf["nodes"][3]["name"] = gltf["nodes"][2]["name"];
  expected.push_back("warning /nodes/1");
  expected.push_back("warning /nodes/3");
  // 7. A skin without inverse bind matrices.
  gltf["skins"][0].erase("inverseBindMatrices");
  expected.push_back("warning /skins/0");
  // 8. An animation output accessor longer than its bufferView.
  const int output = gltf["animations"][0]["samplers"][0]["output"];
  gltf["accessors"][std::size_t(output)]["count"] = gltf["accessors"][std::size_t(output)]["count"].get<int>() + 1000;
  expected.push_back("error /accessors/" + std::to_string(output));

  std::string json = gltf.dump();
  while (json.size() % 4 != 0) json += ' ';
  Bytes out;
  append_u32(out, 0x46546C67u);  // "glTF"
  append_u32(out, 2);
  append_u32(out, std::uint32_t(12 + 8 + json.size() + 8 + bin.size()));
  append_u32(out, std::uint32_t(json.size()));
  append_u32(out, 0x4E4F534Au);  // "JSON"
  out.insert(out.end(), json.begin(), json.end());
  append_u32(out, std::uint32_t(bin.size()));
  append_u32(out, 0x004E4942u);  // "BIN\0"
  out.insert(out.end(), bin.begin(), bin.end());
  std::ofstream(dir / "defects.glb", std::ios::binary).write(reinterpret_cast<const char*>(out.data()), std::streamsize(out.size()));
  std::ofstream list(dir / "defects.expected");
  for (const std::string& line : expected) list << line << '\n';
  return list ? std::string() : "cannot write " + (dir / "defects.expected").string();
}
