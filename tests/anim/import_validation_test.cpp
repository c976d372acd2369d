// One malformed input per validation rule: the import fails (no crash) with one line that names
// the file, the object and its index.
#include <gtest/gtest.h>

#include "anim/gltf_import.h"
#include "anim/import_builder.h"

namespace proxygi::anim {
namespace {

using testing::GltfBuilder;
using testing::kFloat;
using testing::kUByte;
using testing::kUShort;

// Imports and expects failure with a message "test.gltf: <object>: ..." containing each needle.
void expect_refused(const std::vector<std::uint8_t>& bytes, const std::vector<std::string>& needles,
                    const ImportLimits& limits = {}, const std::filesystem::path& folder = {}) {
  auto result = import_gltf_bytes(bytes, "test.gltf", folder, limits);
  ASSERT_FALSE(result.ok()) << "import succeeded";
  const std::string& message = result.message();
  EXPECT_EQ(message.rfind("test.gltf: ", 0), 0u) << message;
  EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  for (const auto& needle : needles) EXPECT_NE(message.find(needle), std::string::npos) << "'" << needle << "' not in: " << message;
}

GltfBuilder quad() { return testing::skinned_quad(); }

TEST(ImportValidation, ValidQuadImports) {
  ASSERT_TRUE(import_gltf_bytes(quad().gltf_bytes(), "test.gltf", {}).ok());
}

TEST(ImportValidation, AccessorExceedsBufferView) {
  auto b = quad();
  b.json()["accessors"][0]["count"] = 5;  // 5 * 12 bytes > the view's 48
  b.json()["accessors"][1]["count"] = 5;
  expect_refused(b.gltf_bytes(), {"mesh 0 primitive 0 POSITION: accessor 0: bufferView 0", "exceed the view's 48 bytes"});
}

TEST(ImportValidation, AccessorByteOffsetHuge) {
  auto b = quad();
  b.json()["accessors"][0]["byteOffset"] = 1000000000000ull;
  expect_refused(b.gltf_bytes(), {"POSITION: accessor 0: bufferView 0", "byteOffset 1000000000000 outside the view"});
}

TEST(ImportValidation, BufferViewExceedsBuffer) {
  auto b = quad();
  b.json()["bufferViews"][0]["byteLength"] = 4096;
  expect_refused(b.gltf_bytes(), {"accessor 0: bufferView 0", "exceeds buffer 0"});
}

TEST(ImportValidation, BufferViewBufferIndexOutOfRange) {
  auto b = quad();
  b.json()["bufferViews"][1]["buffer"] = 3;
  expect_refused(b.gltf_bytes(), {"bufferView 1", "buffer 3 out of range (1 buffers)"});
}

TEST(ImportValidation, AccessorIndexOutOfRange) {
  auto b = quad();
  b.json()["meshes"][0]["primitives"][0]["attributes"]["NORMAL"] = 99;
  expect_refused(b.gltf_bytes(), {"mesh 0 primitive 0 NORMAL: accessor 99 out of range"});
}

TEST(ImportValidation, StrideSmallerThanElement) {
  auto b = quad();
  b.json()["bufferViews"][0]["byteStride"] = 8;
  expect_refused(b.gltf_bytes(), {"POSITION: accessor 0: bufferView 0", "byteStride 8 smaller than the element size 12"});
}

TEST(ImportValidation, VertexIndexOutOfRange) {
  auto b = quad();
  const int indices = b.accessor_of(std::vector<std::uint16_t>{0, 1, 7}, kUShort, 3, "SCALAR");
  b.json()["meshes"][0]["primitives"][0]["indices"] = indices;
  expect_refused(b.gltf_bytes(), {"mesh 0 primitive 0 indices", "index 7 at position 2 out of range (4 vertices)"});
}

TEST(ImportValidation, NodeCycle) {
  auto b = quad();
  b.json()["nodes"][2]["children"] = {0};
  expect_refused(b.gltf_bytes(), {"node 0: is part of a cycle"});
}

TEST(ImportValidation, NodeWithTwoParents) {
  auto b = quad();
  b.json()["nodes"][3]["children"] = {2};
  expect_refused(b.gltf_bytes(), {"node 2: has two parents (node 1 and node 3)"});
}

TEST(ImportValidation, NodeIsOwnChild) {
  auto b = quad();
  b.json()["nodes"][2]["children"] = {2};
  expect_refused(b.gltf_bytes(), {"node 2: lists itself as a child"});
}

TEST(ImportValidation, ChildIndexOutOfRange) {
  auto b = quad();
  b.json()["nodes"][2]["children"] = {12};
  expect_refused(b.gltf_bytes(), {"node 2: child 12 out of range (4 nodes)"});
}

TEST(ImportValidation, NodeMeshAndSkinOutOfRange) {
  auto b = quad();
  b.json()["nodes"][3]["mesh"] = 5;
  expect_refused(b.gltf_bytes(), {"node 3: mesh 5 out of range (1 meshes)"});
  auto c = quad();
  c.json()["nodes"][3]["skin"] = 2;
  expect_refused(c.gltf_bytes(), {"node 3: skin 2 out of range (1 skins)"});
}

TEST(ImportValidation, SceneRootWithParent) {
  auto b = quad();
  b.json()["scenes"][0]["nodes"] = {0, 2};
  expect_refused(b.gltf_bytes(), {"scene 0: node 2 is not a root (its parent is node 1)"});
}

TEST(ImportValidation, SkinJointNodeOutOfRange) {
  auto b = quad();
  b.json()["skins"][0]["joints"] = {1, 40};
  expect_refused(b.gltf_bytes(), {"skin 0: joint 1 is node 40, out of range (4 nodes)"});
}

TEST(ImportValidation, JointIndexOutOfRangeEvenWithZeroWeight) {
  auto b = quad();
  // Vertex 1 uses palette index 2 with weight 0: still refused.
  const int joints = b.accessor_of(std::vector<std::uint8_t>{0, 1, 0, 0, 0, 2, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0}, kUByte, 4, "VEC4");
  const int weights = b.accessor_of(std::vector<float>{1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0}, kFloat, 4, "VEC4");
  b.json()["meshes"][0]["primitives"][0]["attributes"]["JOINTS_0"] = joints;
  b.json()["meshes"][0]["primitives"][0]["attributes"]["WEIGHTS_0"] = weights;
  expect_refused(b.gltf_bytes(), {"skin 0: joint index 2 out of range (2 joints) in mesh 0 primitive 0 (vertex 1"});
}

TEST(ImportValidation, InverseBindMatrixCountAndType) {
  auto b = quad();
  b.json()["accessors"][5]["count"] = 1;
  expect_refused(b.gltf_bytes(), {"skin 0: inverseBindMatrices has 1 matrices for 2 joints"});
  auto c = quad();
  c.json()["accessors"][5]["type"] = "VEC4";
  c.json()["accessors"][5]["count"] = 8;
  expect_refused(c.gltf_bytes(), {"skin 0 inverseBindMatrices: accessor 5: type VEC4 not allowed"});
}

TEST(ImportValidation, KeyTimesNotIncreasing) {
  auto b = quad();
  const int times = b.accessor_of(std::vector<float>{0.0f, 1.0f, 1.0f}, kFloat, 3, "SCALAR");
  b.json()["animations"][0]["samplers"][0]["input"] = times;
  expect_refused(b.gltf_bytes(), {"animation 0 channel 0 sampler 0 input", "key 2 time", "is not greater than key 1"});
}

TEST(ImportValidation, NegativeKeyTime) {
  auto b = quad();
  const int times = b.accessor_of(std::vector<float>{-0.5f, 1.0f, 2.0f}, kFloat, 3, "SCALAR");
  b.json()["animations"][0]["samplers"][0]["input"] = times;
  expect_refused(b.gltf_bytes(), {"animation 0 channel 0 sampler 0 input", "key 0 time", "negative"});
}

TEST(ImportValidation, SamplerOutputCount) {
  auto b = quad();
  b.json()["animations"][0]["samplers"][0]["interpolation"] = "CUBICSPLINE";  // needs 9 outputs, has 3
  expect_refused(b.gltf_bytes(), {"animation 0 channel 0 sampler 0 output", "3 elements for 3 keys (expected 9)"});
  auto c = quad();
  c.json()["accessors"][7]["count"] = 2;
  expect_refused(c.gltf_bytes(), {"animation 0 channel 0 sampler 0 output", "2 elements for 3 keys (expected 3)"});
}

TEST(ImportValidation, ChannelSamplerAndNodeRanges) {
  auto b = quad();
  b.json()["animations"][0]["channels"][0]["sampler"] = 5;
  expect_refused(b.gltf_bytes(), {"animation 0 channel 0: sampler 5 out of range (1 samplers)"});
  auto c = quad();
  c.json()["animations"][0]["channels"][0]["target"]["node"] = 9;
  expect_refused(c.gltf_bytes(), {"animation 0 channel 0: target node 9 out of range (4 nodes)"});
}

TEST(ImportValidation, DuplicateChannelTarget) {
  auto b = quad();
  b.json()["animations"][0]["channels"].push_back(b.json()["animations"][0]["channels"][0]);
  expect_refused(b.gltf_bytes(), {"animation 0 channel 1: targets node 2 rotation a second time"});
}

// Spec: a channel without target.node SHOULD be ignored. Debian's tinygltf 2.7 drops channels
// that fail to parse (this one included) instead of failing the file.
TEST(ImportValidation, ChannelWithoutTargetNodeIsIgnored) {
  auto b = quad();
  auto& channels = b.json()["animations"][0]["channels"];
  channels.push_back({{"sampler", 0}, {"target", {{"path", "rotation"}}}});
  auto result = import_gltf_bytes(b.gltf_bytes(), "test.gltf", {});
  ASSERT_TRUE(result.ok()) << result.message();
  ASSERT_EQ(result->clips.at(0).channels.size(), 1u);
  EXPECT_EQ(result->clips[0].channels[0].node, 2);
}

TEST(ImportValidation, AnimatedMatrixNode) {
  auto b = quad();
  b.json()["nodes"][2].erase("translation");
  b.json()["nodes"][2]["matrix"] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 1, 0, 1};
  expect_refused(b.gltf_bytes(), {"animation 0 channel 0: animates node 2 which has a matrix"});
}

TEST(ImportValidation, WeightsChannelWithoutMorphTargets) {
  auto b = quad();
  b.json()["animations"][0]["channels"][0]["target"] = {{"node", 3}, {"path", "weights"}};
  expect_refused(b.gltf_bytes(), {"animation 0 channel 0: animates weights of node 3 but mesh 0 has no morph targets"});
}

TEST(ImportValidation, NodeWeightsCountDiffersFromTargets) {
  auto b = quad();
  const int deltas = b.accessor_of(std::vector<float>(12, 0.5f), kFloat, 4, "VEC3");
  b.json()["meshes"][0]["primitives"][0]["targets"] = {{{"POSITION", deltas}}};
  b.json()["nodes"][3]["weights"] = {0.5, 0.5};
  expect_refused(b.gltf_bytes(), {"node 3: has 2 weights for 1 morph targets of mesh 0"});
}

TEST(ImportValidation, NodeWeightsWithoutMesh) {
  auto b = quad();
  b.json()["nodes"][0]["weights"] = {1.0};
  expect_refused(b.gltf_bytes(), {"node 0: weights set without a mesh"});
}

TEST(ImportValidation, NonFiniteFloats) {
  auto b = quad();
  const int positions = b.accessor_of(std::vector<float>{0, 0, 0, 1, 0, 0, 0, std::numeric_limits<float>::quiet_NaN(), 0, 1, 1, 0},
                                      kFloat, 4, "VEC3");
  b.json()["meshes"][0]["primitives"][0]["attributes"]["POSITION"] = positions;
  expect_refused(b.gltf_bytes(), {"mesh 0 primitive 0 POSITION: accessor " + std::to_string(positions), "element 2 is not finite"});
  auto c = quad();
  const int times = c.accessor_of(std::vector<float>{0.0f, 1.0f, std::numeric_limits<float>::infinity()}, kFloat, 3, "SCALAR");
  c.json()["animations"][0]["samplers"][0]["input"] = times;
  expect_refused(c.gltf_bytes(), {"animation 0 channel 0 sampler 0 input", "element 2 is not finite"});
  auto d = quad();
  const int ibm = d.accessor_of(std::vector<float>(32, std::numeric_limits<float>::infinity()), kFloat, 2, "MAT4");
  d.json()["skins"][0]["inverseBindMatrices"] = ibm;
  expect_refused(d.gltf_bytes(), {"skin 0 inverseBindMatrices", "not finite"});
}

TEST(ImportValidation, NegativeWeight) {
  auto b = quad();
  const int weights = b.accessor_of(std::vector<float>{1, 0, 0, 0, 1.5f, -0.5f, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0}, kFloat, 4, "VEC4");
  b.json()["meshes"][0]["primitives"][0]["attributes"]["WEIGHTS_0"] = weights;
  expect_refused(b.gltf_bytes(), {"mesh 0 primitive 0 WEIGHTS_0", "vertex 1 has negative weight"});
}

TEST(ImportValidation, UnpairedJointsSet) {
  auto b = quad();
  b.json()["meshes"][0]["primitives"][0]["attributes"]["JOINTS_1"] = 3;
  expect_refused(b.gltf_bytes(), {"mesh 0 primitive 0: has JOINTS_1 without WEIGHTS_1"});
  auto c = quad();
  c.json()["meshes"][0]["primitives"][0]["attributes"]["WEIGHTS_2"] = 4;
  expect_refused(c.gltf_bytes(), {"mesh 0 primitive 0: attribute WEIGHTS_2 does not continue"});
}

TEST(ImportValidation, NormalizedFlagRules) {
  auto b = quad();
  const int weights = b.accessor_of(std::vector<std::uint8_t>(16, 64), kUByte, 4, "VEC4");  // normalized missing
  b.json()["meshes"][0]["primitives"][0]["attributes"]["WEIGHTS_0"] = weights;
  expect_refused(b.gltf_bytes(), {"WEIGHTS_0: accessor " + std::to_string(weights), "must be normalized"});
}

TEST(ImportValidation, SkinnedNodeWithUnskinnedMesh) {
  auto b = quad();
  b.json()["meshes"][0]["primitives"][0]["attributes"].erase("JOINTS_0");
  b.json()["meshes"][0]["primitives"][0]["attributes"].erase("WEIGHTS_0");
  expect_refused(b.gltf_bytes(), {"node 3: uses skin 0 but mesh 0 primitive 0 has no JOINTS_0/WEIGHTS_0"});
}

TEST(ImportValidation, PointsAndLinesRefused) {
  for (int mode : {0, 1, 2, 3}) {
    auto b = quad();
    b.json()["meshes"][0]["primitives"][0]["mode"] = mode;
    expect_refused(b.gltf_bytes(), {"mesh 0 primitive 0: mode " + std::to_string(mode), "not supported"});
  }
}

TEST(ImportValidation, SparseIndicesRules) {
  auto b = quad();
  const int indices = b.view(std::vector<std::uint16_t>{2, 1});
  const int values = b.view(std::vector<float>{5, 6, 7, 8, 9, 10});
  b.json()["accessors"][0]["sparse"] = {{"count", 2}, {"indices", {{"bufferView", indices}, {"componentType", kUShort}}},
                                        {"values", {{"bufferView", values}}}};
  expect_refused(b.gltf_bytes(), {"POSITION: accessor 0: sparse", "index 1 at position 1 is not strictly increasing"});
  auto c = quad();
  const int far = c.view(std::vector<std::uint16_t>{9, 0});
  const int v = c.view(std::vector<float>{5, 6, 7});
  c.json()["accessors"][0]["sparse"] = {{"count", 1}, {"indices", {{"bufferView", far}, {"componentType", kUShort}}},
                                        {"values", {{"bufferView", v}}}};
  expect_refused(c.gltf_bytes(), {"POSITION: accessor 0: sparse", "index 9 out of range (count 4)"});
  auto d = quad();
  const int ok_index = d.view(std::vector<std::uint16_t>{1, 0});
  d.json()["accessors"][0]["sparse"] = {{"count", 1}, {"indices", {{"bufferView", ok_index}, {"componentType", kUShort}}},
                                        {"values", {{"bufferView", 44}}}};
  expect_refused(d.gltf_bytes(), {"POSITION: accessor 0: sparse values: bufferView 44 out of range"});
}

TEST(ImportValidation, ExternalUrisConfinedToModelFolder) {
  const auto folder = std::filesystem::path(PROXYGI_TEST_OUTPUT_DIR) / "import_sandbox" / "model";
  std::filesystem::create_directories(folder / "sub");
  for (const std::string uri : {"/etc/passwd", "file:///etc/passwd", "http://example.com/a.bin", "../outside.bin",
                                "sub/../../outside.bin", "%2e%2e/outside.bin", "..%2Foutside.bin", "%2Fetc%2Fpasswd"}) {
    auto b = quad();
    auto json = nlohmann::json::parse(b.gltf_text());
    json["buffers"][0]["uri"] = uri;
    const std::string text = json.dump();
    expect_refused(std::vector<std::uint8_t>(text.begin(), text.end()), {"buffer 0: uri \"" + uri + "\""}, {}, folder);
  }
  // A symbolic link inside the folder that points outside it.
  std::ofstream(folder.parent_path() / "outside.bin") << "0123456789";
  std::filesystem::remove(folder / "link.bin");
  std::filesystem::create_symlink(folder.parent_path() / "outside.bin", folder / "link.bin");
  auto b = quad();
  auto json = nlohmann::json::parse(b.gltf_text());
  json["images"] = {{{"uri", "link.bin"}}};
  const std::string text = json.dump();
  expect_refused(std::vector<std::uint8_t>(text.begin(), text.end()), {"image 0: uri \"link.bin\" resolves outside the model's folder"}, {}, folder);
  // Without a model folder every external file is refused.
  expect_refused(std::vector<std::uint8_t>(text.begin(), text.end()), {"image 0: uri \"link.bin\"", "not allowed"});
}

TEST(ImportValidation, DirectoryAndMissingExternalFiles) {
  const auto folder = std::filesystem::path(PROXYGI_TEST_OUTPUT_DIR) / "import_sandbox_dir";
  std::filesystem::create_directories(folder / "adir");
  for (const std::string uri : {"adir", "missing.bin"}) {
    auto b = quad();
    auto json = nlohmann::json::parse(b.gltf_text());
    json["buffers"][0]["uri"] = uri;
    const std::string text = json.dump();
    auto result = import_gltf_bytes(std::vector<std::uint8_t>(text.begin(), text.end()), "test.gltf", folder);
    ASSERT_FALSE(result.ok());
    EXPECT_NE(result.message().find(uri), std::string::npos) << result.message();
  }
}

TEST(ImportValidation, Limits) {
  ImportLimits small;
  small.max_accessor_elements = 3;
  expect_refused(quad().gltf_bytes(), {"mesh 0 primitive 0 POSITION: accessor 0: count 4 exceeds the limit of 3"}, small);
  ImportLimits few_objects;
  few_objects.max_objects = 3;
  expect_refused(quad().gltf_bytes(), {"4 nodes exceed the limit of 3"}, few_objects);
  ImportLimits tiny_file;
  tiny_file.max_file_bytes = 100;
  expect_refused(quad().gltf_bytes(), {"exceeds the limit of 100"}, tiny_file);
}

TEST(ImportValidation, ImageSizeLimitAndBadImage) {
  auto b = quad();
  const std::vector<std::uint8_t> png = {
      0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a, 0x00, 0x00, 0x00, 0x0d, 0x49, 0x48, 0x44, 0x52, 0x00, 0x00, 0x00,
      0x01, 0x00, 0x00, 0x00, 0x01, 0x08, 0x06, 0x00, 0x00, 0x00, 0x1f, 0x15, 0xc4, 0x89, 0x00, 0x00, 0x00, 0x0d, 0x49,
      0x44, 0x41, 0x54, 0x78, 0x9c, 0x63, 0xf8, 0xcf, 0xc0, 0xf0, 0x1f, 0x00, 0x05, 0x00, 0x01, 0xff, 0x89, 0x99, 0x3d,
      0x1d, 0x00, 0x00, 0x00, 0x00, 0x49, 0x45, 0x4e, 0x44, 0xae, 0x42, 0x60, 0x82};
  const int view = b.raw_view(png);
  auto& j = b.json();
  j["images"] = {{{"bufferView", view}, {"mimeType", "image/png"}}};
  j["textures"] = {{{"source", 0}}};
  j["materials"] = {{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}};
  ASSERT_TRUE(import_gltf_bytes(b.glb_bytes(), "test.gltf", {}).ok());
  ImportLimits limits;
  limits.max_image_pixels = 0;
  expect_refused(b.glb_bytes(), {"image 0: image size 1x1 exceeds the limit"}, limits);
  j["bufferViews"][static_cast<std::size_t>(view)]["byteLength"] = 8;  // PNG signature only
  {
    // A texture that does not decode falls back to the base color factor (a warning), as glTF
    // viewers do; size limits still refuse the model.
    auto fallback = import_gltf_bytes(b.glb_bytes(), "test.gltf", {});
    ASSERT_TRUE(fallback.ok()) << fallback.message();
    EXPECT_EQ(fallback->materials[0].base_color_image, -1);
    EXPECT_TRUE(fallback->images[0].rgba.empty());
  }
  j["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"]["index"] = 4;
  expect_refused(b.glb_bytes(), {"material 0: baseColorTexture 4 out of range (1 textures)"});
}

TEST(ImportValidation, TruncatedAndGarbageFilesFailCleanly) {
  const auto glb = quad().glb_bytes();
  for (std::size_t size : {std::size_t{0}, std::size_t{3}, std::size_t{12}, std::size_t{20}, glb.size() / 2, glb.size() - 1}) {
    auto result = import_gltf_bytes(std::vector<std::uint8_t>(glb.begin(), glb.begin() + static_cast<std::ptrdiff_t>(size)), "test.gltf", {});
    ASSERT_FALSE(result.ok()) << "size " << size;
    EXPECT_EQ(result.message().rfind("test.gltf: ", 0), 0u) << result.message();
  }
  const std::string garbage = "{\"asset\":{\"version\":\"2.0\"},\"nodes\":[{\"children\":[1";
  EXPECT_FALSE(import_gltf_bytes(std::vector<std::uint8_t>(garbage.begin(), garbage.end()), "test.gltf", {}).ok());
}

TEST(ImportValidation, RequiredUnsupportedExtension) {
  auto b = quad();
  b.json()["extensionsRequired"] = {"KHR_draco_mesh_compression"};
  b.json()["extensionsUsed"] = {"KHR_draco_mesh_compression"};
  expect_refused(b.gltf_bytes(), {"requires extension KHR_draco_mesh_compression"});
}

}  // namespace
}  // namespace proxygi::anim
