// Import of the glTF features proxygi supports, on small synthetic files (tests/anim/import_builder.h).
#include <cmath>

#include <gtest/gtest.h>

#include "anim/gltf_import.h"
#include "anim/import_builder.h"
#include "anim/sampling.h"

namespace proxygi::anim {
namespace {

using testing::GltfBuilder;
using testing::kFloat;
using testing::kShort;
using testing::kUByte;
using testing::kUShort;

Character import_ok(const std::vector<std::uint8_t>& bytes) {
  auto result = import_gltf_bytes(bytes, "test.gltf", {});
  EXPECT_TRUE(result.ok()) << (result.ok() ? "" : result.message());
  return result.ok() ? std::move(result).value() : Character{};
}

TEST(ImportFeatures, SkinnedQuadAsDataUriGltf) {
  const Character c = import_ok(testing::skinned_quad().gltf_bytes());
  ASSERT_EQ(c.nodes.size(), 4u);
  EXPECT_EQ(c.source, "test.gltf");
  EXPECT_EQ(c.nodes[2].parent, 1);
  EXPECT_EQ(c.nodes[0].children, (std::vector<int>{1, 3}));
  EXPECT_EQ(c.roots, (std::vector<int>{0}));
  ASSERT_EQ(c.evaluation_order.size(), 4u);
  std::vector<int> position(4);
  for (std::size_t i = 0; i < 4; ++i) position[static_cast<std::size_t>(c.evaluation_order[i])] = static_cast<int>(i);
  for (std::size_t n = 0; n < 4; ++n) {
    if (c.nodes[n].parent >= 0) {
      EXPECT_LT(position[static_cast<std::size_t>(c.nodes[n].parent)], position[n]);
    }
  }
  EXPECT_EQ(c.nodes[2].rest.translation, glm::vec3(0, 1, 0));
  ASSERT_EQ(c.meshes.size(), 1u);
  const Primitive& p = c.meshes[0].primitives.at(0);
  EXPECT_EQ(p.positions.size(), 4u);
  EXPECT_EQ(p.indices, (std::vector<std::uint32_t>{0, 1, 2, 2, 1, 3}));
  EXPECT_EQ(p.influences_per_vertex, 4);
  EXPECT_FLOAT_EQ(p.weights[4], 0.5f);
  EXPECT_FLOAT_EQ(p.weights[5], 0.5f);
  EXPECT_EQ(p.joints[5], 1);
  ASSERT_EQ(c.skins.size(), 1u);
  EXPECT_EQ(c.skins[0].joints, (std::vector<int>{1, 2}));
  EXPECT_FLOAT_EQ(c.skins[0].inverse_bind_matrices[1][3][1], -1.0f);
  ASSERT_EQ(c.clips.size(), 1u);
  EXPECT_EQ(c.clips[0].name, "bend");
  const Channel& ch = c.clips[0].channels.at(0);
  EXPECT_EQ(ch.node, 2);
  EXPECT_EQ(ch.path, ChannelPath::rotation);
  EXPECT_EQ(ch.components, 4);
  EXPECT_EQ(ch.times, (std::vector<float>{0.5f, 1.0f, 2.0f}));
  // Duration is the last key time; playback starts at 0 even though the first key is at 0.5 s.
  EXPECT_FLOAT_EQ(c.clips[0].duration, 2.0f);
  EXPECT_NEAR(ch.values[6], 0.70710678f, 1e-6f);
}

TEST(ImportFeatures, GlbMatchesGltf) {
  const auto builder = testing::skinned_quad();
  const Character from_glb = import_ok(builder.glb_bytes());
  const Character from_gltf = import_ok(builder.gltf_bytes());
  ASSERT_EQ(from_glb.meshes.size(), 1u);
  EXPECT_EQ(from_glb.meshes[0].primitives[0].positions, from_gltf.meshes[0].primitives[0].positions);
  EXPECT_EQ(from_glb.clips[0].channels[0].values, from_gltf.clips[0].channels[0].values);
}

TEST(ImportFeatures, ExternalBinInModelFolder) {
  const auto folder = std::filesystem::path(PROXYGI_TEST_OUTPUT_DIR) / "import_external";
  const auto path = testing::skinned_quad().write_with_external_bin(folder, "quad", "quad%20data.bin");
  // The URI is percent-encoded: the file on disk is "quad%20data.bin" -> decoded "quad data.bin".
  std::filesystem::rename(folder / "quad%20data.bin", folder / "quad data.bin");
  auto result = import_gltf(path);
  ASSERT_TRUE(result.ok()) << result.message();
  EXPECT_EQ(result->meshes[0].primitives[0].positions[3], glm::vec3(1, 1, 0));
}

TEST(ImportFeatures, MissingInverseBindMatricesAreIdentity) {
  auto b = testing::skinned_quad();
  b.json()["skins"][0].erase("inverseBindMatrices");
  const Character c = import_ok(b.gltf_bytes());
  ASSERT_EQ(c.skins.at(0).inverse_bind_matrices.size(), 2u);
  EXPECT_EQ(c.skins[0].inverse_bind_matrices[0], glm::mat4(1.0f));
  EXPECT_EQ(c.skins[0].inverse_bind_matrices[1], glm::mat4(1.0f));
}

TEST(ImportFeatures, EightInfluencesAndNormalizedIntegerWeights) {
  auto b = testing::skinned_quad();
  // WEIGHTS_0 as normalized UNSIGNED_BYTE, WEIGHTS_1 as normalized UNSIGNED_SHORT.
  const int w0 = b.accessor_of(std::vector<std::uint8_t>{51, 51, 0, 0, 255, 0, 0, 0, 0, 0, 0, 0, 255, 0, 0, 0}, kUByte, 4,
                               "VEC4", {{"normalized", true}});
  const int j1 = b.accessor_of(std::vector<std::uint16_t>{1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0}, kUShort, 4, "VEC4");
  const int w1 = b.accessor_of(std::vector<std::uint16_t>{26214, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0}, kUShort, 4,
                               "VEC4", {{"normalized", true}});
  auto& attributes = b.json()["meshes"][0]["primitives"][0]["attributes"];
  attributes["WEIGHTS_0"] = w0;
  attributes["JOINTS_1"] = j1;
  attributes["WEIGHTS_1"] = w1;
  const Character c = import_ok(b.gltf_bytes());
  const Primitive& p = c.meshes.at(0).primitives.at(0);
  ASSERT_EQ(p.influences_per_vertex, 8);
  ASSERT_EQ(p.weights.size(), 32u);
  // Vertex 0: 51/255 = 0.2, 0.2 and 26214/65535 = 0.4: sum 0.8, renormalized to 0.25, 0.25, 0.5.
  EXPECT_NEAR(p.weights[0], 0.25f, 1e-5f);
  EXPECT_NEAR(p.weights[1], 0.25f, 1e-5f);
  EXPECT_NEAR(p.weights[4], 0.5f, 1e-5f);
  EXPECT_EQ(p.joints[4], 1);
  // Vertex 2 has all-zero weights: bound rigidly to joint 0.
  EXPECT_FLOAT_EQ(p.weights[16], 1.0f);
  EXPECT_EQ(p.joints[16], 0);
  for (std::size_t v = 0; v < 4; ++v) {
    float sum = 0.0f;
    for (std::size_t k = 0; k < 8; ++k) sum += p.weights[v * 8 + k];
    EXPECT_NEAR(sum, 1.0f, 1e-6f) << "vertex " << v;
  }
}

TEST(ImportFeatures, InterleavedAttributesHonourByteStride) {
  auto b = testing::skinned_quad();
  // position (12 bytes) + padding (4) + normal (12) + padding (4): stride 32.
  std::vector<float> data;
  for (int v = 0; v < 4; ++v) {
    data.insert(data.end(), {static_cast<float>(v), static_cast<float>(10 * v), 0.0f, -7.0f, 0.0f, 0.0f, 1.0f, -7.0f});
  }
  const int view = b.view(data, 32);
  const int position = b.accessor(view, kFloat, 4, "VEC3");
  const int normal = b.accessor(view, kFloat, 4, "VEC3", {{"byteOffset", 16}});
  auto& attributes = b.json()["meshes"][0]["primitives"][0]["attributes"];
  attributes["POSITION"] = position;
  attributes["NORMAL"] = normal;
  const Character c = import_ok(b.glb_bytes());
  const Primitive& p = c.meshes.at(0).primitives.at(0);
  EXPECT_EQ(p.positions[3], glm::vec3(3, 30, 0));
  EXPECT_EQ(p.normals[2], glm::vec3(0, 0, 1));
}

TEST(ImportFeatures, SparseAccessorsWithAndWithoutBufferView) {
  auto b = testing::skinned_quad();
  // POSITION: base data plus one substituted vertex.
  const int indices = b.view(std::vector<std::uint16_t>{2, 0});
  const int values = b.view(std::vector<float>{5, 6, 7});
  auto& positions = b.json()["accessors"][0];
  positions["sparse"] = {{"count", 1}, {"indices", {{"bufferView", indices}, {"componentType", kUShort}}},
                         {"values", {{"bufferView", values}}}};
  // Animation input and output as sparse accessors without bufferView: zeros + substitutions.
  const int time_indices = b.view(std::vector<std::uint8_t>{1, 2, 0, 0});
  const int time_values = b.view(std::vector<float>{0.25f, 1.5f});
  const int times = b.accessor(-1, kFloat, 3, "SCALAR",
                               {{"sparse", {{"count", 2}, {"indices", {{"bufferView", time_indices}, {"componentType", kUByte}}},
                                            {"values", {{"bufferView", time_values}}}}}});
  const int out_indices = b.view(std::vector<std::uint32_t>{0, 1, 2});
  const int out_values = b.view(std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1});
  const int outputs = b.accessor(-1, kFloat, 3, "VEC4",
                                 {{"sparse", {{"count", 3}, {"indices", {{"bufferView", out_indices}, {"componentType", 5125}}},
                                              {"values", {{"bufferView", out_values}}}}}});
  b.json()["animations"][0]["samplers"][0] = {{"input", times}, {"output", outputs}};
  const Character c = import_ok(b.gltf_bytes());
  EXPECT_EQ(c.meshes.at(0).primitives.at(0).positions[2], glm::vec3(5, 6, 7));
  EXPECT_EQ(c.meshes[0].primitives[0].positions[1], glm::vec3(1, 0, 0));
  const Channel& ch = c.clips.at(0).channels.at(0);
  EXPECT_EQ(ch.times, (std::vector<float>{0.0f, 0.25f, 1.5f}));
  EXPECT_FLOAT_EQ(c.clips[0].duration, 1.5f);
}

TEST(ImportFeatures, QuantizedRotationsAreDecoded) {
  auto b = testing::skinned_quad();
  const int rotations = b.accessor_of(std::vector<std::int16_t>{0, 0, 0, 32767, 0, 0, 23170, 23170, -32768, 0, 0, 0},
                                      kShort, 3, "VEC4", {{"normalized", true}});
  b.json()["animations"][0]["samplers"][0]["output"] = rotations;
  const Character c = import_ok(b.gltf_bytes());
  const auto& v = c.clips.at(0).channels.at(0).values;
  EXPECT_FLOAT_EQ(v[3], 1.0f);
  EXPECT_NEAR(v[6], 0.70710678f, 1e-6f);
  EXPECT_NEAR(v[7], 0.70710678f, 1e-6f);
  EXPECT_FLOAT_EQ(v[8], -1.0f);  // max(-32768 / 32767, -1)
}

TEST(ImportFeatures, StepCubicAndAnimatedNonJointNode) {
  auto b = testing::skinned_quad();
  const int times = b.accessor_of(std::vector<float>{0.0f, 1.0f}, kFloat, 2, "SCALAR");
  const int cubic = b.accessor_of(std::vector<float>{9, 9, 9, 0, 0, 0, 1, 1, 1, 2, 2, 2, 3, 0, 0, 4, 4, 4}, kFloat, 6, "VEC3");
  const int step = b.accessor_of(std::vector<float>{1, 1, 1, 2, 2, 2}, kFloat, 2, "VEC3");
  auto& animation = b.json()["animations"][0];
  animation["samplers"].push_back({{"input", times}, {"output", cubic}, {"interpolation", "CUBICSPLINE"}});
  animation["samplers"].push_back({{"input", times}, {"output", step}, {"interpolation", "STEP"}});
  animation["channels"].push_back({{"sampler", 1}, {"target", {{"node", 0}, {"path", "translation"}}}});
  animation["channels"].push_back({{"sampler", 2}, {"target", {{"node", 3}, {"path", "scale"}}}});
  const Character c = import_ok(b.gltf_bytes());
  const auto& channels = c.clips.at(0).channels;
  ASSERT_EQ(channels.size(), 3u);
  EXPECT_EQ(channels[1].node, 0);
  EXPECT_EQ(channels[1].interpolation, Interpolation::cubic_spline);
  EXPECT_EQ(channels[1].values.size(), 18u);  // in-tangent, value, out-tangent per key
  EXPECT_EQ(channels[1].values[3], 0.0f);
  EXPECT_EQ(channels[2].interpolation, Interpolation::step);
  EXPECT_EQ(channels[2].node, 3);
  EXPECT_FLOAT_EQ(c.clips[0].duration, 2.0f);
}

TEST(ImportFeatures, StripsFansAndNonIndexedPrimitives) {
  auto b = testing::skinned_quad();
  auto& primitives = b.json()["meshes"][0]["primitives"];
  nlohmann::json strip = primitives[0];
  strip["mode"] = 5;
  strip["indices"] = b.accessor_of(std::vector<std::uint8_t>{0, 1, 2, 3}, kUByte, 4, "SCALAR");
  nlohmann::json fan = primitives[0];
  fan["mode"] = 6;
  fan.erase("indices");
  nlohmann::json list = primitives[0];
  list.erase("indices");
  list["attributes"].erase("NORMAL");
  // Triangle list of 3 vertices for the non-indexed case.
  const int three = b.accessor_of(std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0}, kFloat, 3, "VEC3");
  list["attributes"] = {{"POSITION", three}};
  primitives.push_back(strip);
  primitives.push_back(fan);
  primitives.push_back(list);
  b.json()["nodes"][3].erase("skin");
  const Character c = import_ok(b.gltf_bytes());
  const auto& p = c.meshes.at(0).primitives;
  ASSERT_EQ(p.size(), 4u);
  // glTF strips: triangle i = {v_i, v_(i+1+i%2), v_(i+2-i%2)}.
  EXPECT_EQ(p[1].indices, (std::vector<std::uint32_t>{0, 1, 2, 1, 3, 2}));
  EXPECT_EQ(p[2].indices, (std::vector<std::uint32_t>{0, 1, 2, 0, 2, 3}));
  EXPECT_EQ(p[3].indices, (std::vector<std::uint32_t>{0, 1, 2}));
  // Normals computed for the primitive without NORMAL: the triangle faces +Z.
  ASSERT_EQ(p[3].normals.size(), 3u);
  for (const glm::vec3& n : p[3].normals) EXPECT_NEAR(glm::distance(n, glm::vec3(0, 0, 1)), 0.0f, 1e-6f);
}

TEST(ImportFeatures, ComputedNormalsOnNonManifoldMesh) {
  GltfBuilder b;
  // Three triangles sharing edge 0-1 (a complex edge OpenMesh refuses), all in the z = 0 plane.
  const int positions = b.accessor_of(std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0, 0, -1, 0, 0.5f, 1, 0}, kFloat, 5, "VEC3");
  const int indices = b.accessor_of(std::vector<std::uint16_t>{0, 1, 2, 1, 0, 3, 0, 1, 4}, kUShort, 9, "SCALAR");
  b.json()["meshes"] = {{{"primitives", {{{"attributes", {{"POSITION", positions}}}, {"indices", indices}}}}}};
  b.json()["nodes"] = {{{"mesh", 0}}};
  const Character c = import_ok(b.gltf_bytes());
  for (const glm::vec3& n : c.meshes.at(0).primitives.at(0).normals) {
    EXPECT_NEAR(glm::length(n), 1.0f, 1e-5f);
    EXPECT_NEAR(std::abs(n.z), 1.0f, 1e-5f);
  }
}

TEST(ImportFeatures, MorphTargetsAndWeightsChannel) {
  auto b = testing::skinned_quad();
  const int deltas = b.accessor_of(std::vector<float>{0, 0, 1, 0, 0, 2, 0, 0, 3, 0, 0, 4}, kFloat, 4, "VEC3");
  b.json()["meshes"][0]["primitives"][0]["targets"] = {{{"POSITION", deltas}}};
  b.json()["meshes"][0]["weights"] = {0.25};
  const int times = b.accessor_of(std::vector<float>{0.0f, 3.0f}, kFloat, 2, "SCALAR");
  const int weights = b.accessor_of(std::vector<std::uint8_t>{0, 255}, kUByte, 2, "SCALAR", {{"normalized", true}});
  b.json()["animations"][0]["samplers"].push_back({{"input", times}, {"output", weights}});
  b.json()["animations"][0]["channels"].push_back({{"sampler", 1}, {"target", {{"node", 3}, {"path", "weights"}}}});
  const Character c = import_ok(b.gltf_bytes());
  const Mesh& mesh = c.meshes.at(0);
  EXPECT_EQ(mesh.default_morph_weights, (std::vector<float>{0.25f}));
  ASSERT_EQ(mesh.primitives[0].morph_targets.size(), 1u);
  EXPECT_EQ(mesh.primitives[0].morph_targets[0].position_deltas[3], glm::vec3(0, 0, 4));
  const Channel& ch = c.clips.at(0).channels.at(1);
  EXPECT_EQ(ch.path, ChannelPath::weights);
  EXPECT_EQ(ch.components, 1);
  EXPECT_EQ(ch.values, (std::vector<float>{0.0f, 1.0f}));
  EXPECT_FLOAT_EQ(c.clips[0].duration, 3.0f);
}

TEST(ImportFeatures, NodeWeightsOverrideMeshWeights) {
  auto b = testing::skinned_quad();
  const int deltas = b.accessor_of(std::vector<float>{0, 0, 1, 0, 0, 2, 0, 0, 3, 0, 0, 4}, kFloat, 4, "VEC3");
  b.json()["meshes"][0]["primitives"][0]["targets"] = {{{"POSITION", deltas}}};
  b.json()["meshes"][0]["weights"] = {0.25};
  b.json()["nodes"][3]["weights"] = {0.75};
  const Character c = import_ok(b.gltf_bytes());
  EXPECT_EQ(c.nodes.at(3).morph_weights, (std::vector<float>{0.75f}));
  EXPECT_EQ(c.meshes.at(0).default_morph_weights, (std::vector<float>{0.25f}));
  std::vector<float> weights(std::size_t(morph_weight_count(c)));
  default_morph_weights(c, weights);
  EXPECT_EQ(weights, (std::vector<float>{0.75f}));
}

TEST(ImportFeatures, SeveralSkinsAndMeshes) {
  auto b = testing::skinned_quad();
  auto& j = b.json();
  j["meshes"].push_back(j["meshes"][0]);
  j["skins"].push_back({{"joints", {2, 1}}});
  j["nodes"].push_back({{"name", "second"}, {"mesh", 1}, {"skin", 1}});
  j["nodes"].push_back({{"name", "third"}, {"mesh", 0}, {"skin", 1}});
  j["nodes"][0]["children"] = {1, 3, 4, 5};
  const Character c = import_ok(b.gltf_bytes());
  EXPECT_EQ(c.meshes.size(), 2u);
  ASSERT_EQ(c.skins.size(), 2u);
  EXPECT_EQ(c.skins[1].joints, (std::vector<int>{2, 1}));
  EXPECT_EQ(c.nodes[5].skin, 1);
  EXPECT_EQ(c.nodes[5].mesh, 0);
}

TEST(ImportFeatures, BaseColorTextureFromDataUri) {
  auto b = testing::skinned_quad();
  // 1x1 RGBA PNG, pixel (255, 0, 0, 255).
  const std::vector<std::uint8_t> png = {
      0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a, 0x00, 0x00, 0x00, 0x0d, 0x49, 0x48, 0x44, 0x52, 0x00, 0x00, 0x00,
      0x01, 0x00, 0x00, 0x00, 0x01, 0x08, 0x06, 0x00, 0x00, 0x00, 0x1f, 0x15, 0xc4, 0x89, 0x00, 0x00, 0x00, 0x0d, 0x49,
      0x44, 0x41, 0x54, 0x78, 0x9c, 0x63, 0xf8, 0xcf, 0xc0, 0xf0, 0x1f, 0x00, 0x05, 0x00, 0x01, 0xff, 0x89, 0x99, 0x3d,
      0x1d, 0x00, 0x00, 0x00, 0x00, 0x49, 0x45, 0x4e, 0x44, 0xae, 0x42, 0x60, 0x82};
  auto& j = b.json();
  j["images"] = {{{"name", "red"}, {"uri", "data:image/png;base64," + GltfBuilder::base64(png)}}, {{"name", "unused"}, {"uri", "data:image/png;base64," + GltfBuilder::base64(png)}}};
  j["textures"] = {{{"source", 0}}};
  j["materials"] = {{{"name", "skin"}, {"pbrMetallicRoughness", {{"baseColorFactor", {0.5, 0.5, 0.5, 1}}, {"baseColorTexture", {{"index", 0}}}}}}};
  j["meshes"][0]["primitives"][0]["material"] = 0;
  const Character c = import_ok(b.gltf_bytes());
  ASSERT_EQ(c.materials.size(), 1u);
  EXPECT_EQ(c.materials[0].base_color_image, 0);
  EXPECT_EQ(c.materials[0].base_color_factor, glm::vec4(0.5f, 0.5f, 0.5f, 1.0f));
  ASSERT_EQ(c.images.size(), 2u);
  EXPECT_EQ(c.images[0].width, 1);
  EXPECT_EQ(c.images[0].rgba, (std::vector<std::uint8_t>{255, 0, 0, 255}));
  EXPECT_TRUE(c.images[1].rgba.empty());  // not a base color texture: not decoded
  EXPECT_EQ(c.images[1].name, "unused");
  EXPECT_EQ(c.meshes[0].primitives[0].material, 0);
}

TEST(ImportFeatures, ExternalImageInModelFolder) {
  const std::vector<std::uint8_t> png = {
      0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a, 0x00, 0x00, 0x00, 0x0d, 0x49, 0x48, 0x44, 0x52, 0x00, 0x00, 0x00,
      0x01, 0x00, 0x00, 0x00, 0x01, 0x08, 0x06, 0x00, 0x00, 0x00, 0x1f, 0x15, 0xc4, 0x89, 0x00, 0x00, 0x00, 0x0d, 0x49,
      0x44, 0x41, 0x54, 0x78, 0x9c, 0x63, 0xf8, 0xcf, 0xc0, 0xf0, 0x1f, 0x00, 0x05, 0x00, 0x01, 0xff, 0x89, 0x99, 0x3d,
      0x1d, 0x00, 0x00, 0x00, 0x00, 0x49, 0x45, 0x4e, 0x44, 0xae, 0x42, 0x60, 0x82};
  const auto folder = std::filesystem::path(PROXYGI_TEST_OUTPUT_DIR) / "import_external_image";
  std::filesystem::create_directories(folder / "textures");
  std::ofstream(folder / "textures" / "red.png", std::ios::binary)
      .write(reinterpret_cast<const char*>(png.data()), static_cast<std::streamsize>(png.size()));
  auto b = testing::skinned_quad();
  auto& j = b.json();
  j["images"] = {{{"uri", "textures/red.png"}}};
  j["textures"] = {{{"source", 0}}};
  j["materials"] = {{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}};
  const auto path = b.write_with_external_bin(folder, "textured", "textured.bin");
  auto result = import_gltf(path);
  ASSERT_TRUE(result.ok()) << result.message();
  ASSERT_EQ(result->images.size(), 1u);
  EXPECT_EQ(result->images[0].rgba, (std::vector<std::uint8_t>{255, 0, 0, 255}));
}

}  // namespace
}  // namespace proxygi::anim

namespace proxygi::anim {
namespace {

// Inputs the fuzzer (tests/fuzz) found crashing, kept as regression files.
TEST(ImportRegression, FuzzFoundInputsDoNotCrash) {
  // OpenMesh's add_face asserted (abort) on this non-manifold triangle soup without normals.
  const auto path = std::filesystem::path(PROXYGI_SOURCE_DIR) / "tests/anim/data/fuzz_openmesh_add_face.glb";
  auto result = import_gltf(path);
  if (result.ok()) {
    for (const auto& mesh : result->meshes) {
      for (const auto& primitive : mesh.primitives) {
        for (const glm::vec3& n : primitive.normals) EXPECT_NEAR(glm::length(n), 1.0f, 1e-5f);
      }
    }
  } else {
    EXPECT_NE(result.message().find("fuzz_openmesh_add_face.glb: "), std::string::npos) << result.message();
  }
}

}  // namespace
}  // namespace proxygi::anim
