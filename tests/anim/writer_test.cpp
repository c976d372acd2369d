// glTF writer: everything in a Character that the importer reads comes back unchanged, as GLB
// and as .gltf text, and files are written atomically.
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "anim/gltf_import.h"
#include "anim/gltf_writer.h"

namespace proxygi::anim {
namespace {

Character everything() {
  Character c;
  c.source = "everything";
  Node root;
  root.name = "root";
  root.children = {1, 2};
  root.rest.translation = {1, 2, 3};
  root.rest.rotation = glm::normalize(glm::quat(0.9f, 0.1f, 0.3f, -0.2f));
  root.rest.scale = {1, 2, 0.5f};
  Node joint;
  joint.name = "joint";
  joint.parent = 0;
  joint.rest.translation = {0, 1, 0};
  Node fixed;
  fixed.name = "fixed_matrix";
  fixed.parent = 0;
  glm::mat4 m(1.0f);
  m[0][1] = 0.25f;
  m[3] = glm::vec4(4, 5, 6, 1);
  fixed.matrix = m;
  Node mesh_node;
  mesh_node.name = "mesh_node";
  mesh_node.mesh = 0;
  mesh_node.skin = 0;
  mesh_node.morph_weights = {0.5f};
  c.nodes = {root, joint, fixed, mesh_node};
  c.roots = {0, 3};
  c.evaluation_order = {0, 1, 2, 3};

  Primitive p;
  p.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  p.normals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
  p.uvs = {{0, 0}, {1, 0}, {0, 1}};
  p.indices = {0, 1, 2};
  p.influences_per_vertex = 8;  // two JOINTS_n/WEIGHTS_n sets
  p.joints = {0, 1, 0, 0, 0, 0, 0, 1, 1, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 1, 0, 1, 0, 1};
  p.weights = {0.5f, 0.5f, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0,
               0.125f, 0.125f, 0.125f, 0.125f, 0.125f, 0.125f, 0.125f, 0.125f};
  p.morph_targets.resize(1);
  p.morph_targets[0].position_deltas = {{0, 0, 1}, {0, 0, 2}, {0, 0, 3}};
  p.morph_targets[0].normal_deltas = {{0, 0.5f, 0}, {0, 0, 0}, {0, 0, 0}};
  p.material = 0;
  Mesh mesh;
  mesh.name = "mesh";
  mesh.primitives = {p};
  mesh.default_morph_weights = {0.25f};
  c.meshes = {mesh};

  Material material;
  material.name = "textured";
  material.base_color_factor = {0.5f, 0.25f, 1.0f, 0.75f};
  material.base_color_image = 0;
  material.double_sided = true;
  c.materials = {material};
  Image image;
  image.name = "checker";
  image.width = 2;
  image.height = 2;
  image.rgba = {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 255, 128};
  c.images = {image};

  Skin skin;
  skin.name = "skin";
  skin.joints = {0, 1};
  glm::mat4 ibm(1.0f);
  ibm[3] = glm::vec4(0, -1, 0, 1);
  skin.inverse_bind_matrices = {glm::mat4(1.0f), ibm};
  skin.skeleton = 0;
  c.skins = {skin};

  Clip clip;
  clip.name = "all_modes";
  auto channel = [](int node, ChannelPath path, Interpolation interpolation, int components, std::vector<float> times,
                    std::vector<float> values) {
    Channel ch;
    ch.node = node;
    ch.path = path;
    ch.interpolation = interpolation;
    ch.components = components;
    ch.times = std::move(times);
    ch.values = std::move(values);
    return ch;
  };
  clip.channels.push_back(channel(1, ChannelPath::translation, Interpolation::step, 3, {0.5f, 1.0f}, {1, 2, 3, 4, 5, 6}));
  clip.channels.push_back(channel(1, ChannelPath::rotation, Interpolation::linear, 4, {0.0f, 2.0f},
                                  {0, 0, 0, 1, 0, 0, 1, 0}));
  clip.channels.push_back(channel(1, ChannelPath::scale, Interpolation::cubic_spline, 3, {0.0f, 1.5f},
                                  {0, 0, 0, 1, 1, 1, 2, 0, 0, 0, 0, 3, 2, 2, 2, 0, 0, 0}));
  clip.channels.push_back(channel(3, ChannelPath::weights, Interpolation::linear, 1, {0.0f, 1.0f}, {0.0f, 1.0f}));
  clip.duration = 2.0f;
  c.clips = {clip};
  return c;
}

void expect_same(const Character& a, const Character& b) {
  ASSERT_EQ(a.nodes.size(), b.nodes.size());
  for (std::size_t i = 0; i < a.nodes.size(); ++i) {
    SCOPED_TRACE("node " + std::to_string(i));
    EXPECT_EQ(a.nodes[i].name, b.nodes[i].name);
    EXPECT_EQ(a.nodes[i].parent, b.nodes[i].parent);
    EXPECT_EQ(a.nodes[i].children, b.nodes[i].children);
    EXPECT_EQ(a.nodes[i].rest.translation, b.nodes[i].rest.translation);
    EXPECT_EQ(a.nodes[i].rest.scale, b.nodes[i].rest.scale);
    EXPECT_NEAR(glm::dot(a.nodes[i].rest.rotation, b.nodes[i].rest.rotation), 1.0f, 1e-6f);
    EXPECT_EQ(a.nodes[i].matrix, b.nodes[i].matrix);
    EXPECT_EQ(a.nodes[i].mesh, b.nodes[i].mesh);
    EXPECT_EQ(a.nodes[i].skin, b.nodes[i].skin);
    // Node::morph_weights (glTF node.weights) is written (checked on the JSON below) but not
    // read by the importer yet; compare it once the importer fills it.
    if (!b.nodes[i].morph_weights.empty()) {
      EXPECT_EQ(a.nodes[i].morph_weights, b.nodes[i].morph_weights);
    }
  }
  EXPECT_EQ(a.roots, b.roots);
  ASSERT_EQ(a.meshes.size(), b.meshes.size());
  for (std::size_t m = 0; m < a.meshes.size(); ++m) {
    EXPECT_EQ(a.meshes[m].name, b.meshes[m].name);
    EXPECT_EQ(a.meshes[m].default_morph_weights, b.meshes[m].default_morph_weights);
    ASSERT_EQ(a.meshes[m].primitives.size(), b.meshes[m].primitives.size());
    for (std::size_t p = 0; p < a.meshes[m].primitives.size(); ++p) {
      const Primitive& x = a.meshes[m].primitives[p];
      const Primitive& y = b.meshes[m].primitives[p];
      EXPECT_EQ(x.positions, y.positions);
      EXPECT_EQ(x.normals, y.normals);
      EXPECT_EQ(x.uvs, y.uvs);
      EXPECT_EQ(x.indices, y.indices);
      EXPECT_EQ(x.influences_per_vertex, y.influences_per_vertex);
      EXPECT_EQ(x.joints, y.joints);
      EXPECT_EQ(x.weights, y.weights);  // binary fractions summing to 1: renormalizing keeps them
      EXPECT_EQ(x.material, y.material);
      ASSERT_EQ(x.morph_targets.size(), y.morph_targets.size());
      for (std::size_t t = 0; t < x.morph_targets.size(); ++t) {
        EXPECT_EQ(x.morph_targets[t].position_deltas, y.morph_targets[t].position_deltas);
        EXPECT_EQ(x.morph_targets[t].normal_deltas, y.morph_targets[t].normal_deltas);
      }
    }
  }
  ASSERT_EQ(a.materials.size(), b.materials.size());
  for (std::size_t i = 0; i < a.materials.size(); ++i) {
    EXPECT_EQ(a.materials[i].name, b.materials[i].name);
    EXPECT_EQ(a.materials[i].base_color_factor, b.materials[i].base_color_factor);
    EXPECT_EQ(a.materials[i].base_color_image, b.materials[i].base_color_image);
    EXPECT_EQ(a.materials[i].double_sided, b.materials[i].double_sided);
  }
  ASSERT_EQ(a.images.size(), b.images.size());
  for (std::size_t i = 0; i < a.images.size(); ++i) {
    EXPECT_EQ(a.images[i].width, b.images[i].width);
    EXPECT_EQ(a.images[i].height, b.images[i].height);
    EXPECT_EQ(a.images[i].rgba, b.images[i].rgba);
  }
  ASSERT_EQ(a.skins.size(), b.skins.size());
  for (std::size_t i = 0; i < a.skins.size(); ++i) {
    EXPECT_EQ(a.skins[i].name, b.skins[i].name);
    EXPECT_EQ(a.skins[i].joints, b.skins[i].joints);
    EXPECT_EQ(a.skins[i].inverse_bind_matrices, b.skins[i].inverse_bind_matrices);
    EXPECT_EQ(a.skins[i].skeleton, b.skins[i].skeleton);
  }
  ASSERT_EQ(a.clips.size(), b.clips.size());
  for (std::size_t i = 0; i < a.clips.size(); ++i) {
    EXPECT_EQ(a.clips[i].name, b.clips[i].name);
    EXPECT_EQ(a.clips[i].duration, b.clips[i].duration);
    ASSERT_EQ(a.clips[i].channels.size(), b.clips[i].channels.size());
    for (std::size_t k = 0; k < a.clips[i].channels.size(); ++k) {
      const Channel& x = a.clips[i].channels[k];
      const Channel& y = b.clips[i].channels[k];
      EXPECT_EQ(x.node, y.node);
      EXPECT_EQ(x.path, y.path);
      EXPECT_EQ(x.interpolation, y.interpolation);
      EXPECT_EQ(x.components, y.components);
      EXPECT_EQ(x.times, y.times);
      EXPECT_EQ(x.values, y.values);
    }
  }
}

TEST(Writer, GlbRoundTripsEverythingTheImporterReads) {
  const Character original = everything();
  Result<std::vector<std::uint8_t>> glb = encode_glb(original);
  ASSERT_TRUE(glb.ok()) << glb.message();
  Result<Character> imported = import_gltf_bytes(*glb, "everything.glb", {});
  ASSERT_TRUE(imported.ok()) << imported.message();
  expect_same(original, *imported);

  std::uint32_t json_length = 0;
  std::memcpy(&json_length, glb->data() + 12, 4);
  const nlohmann::json json = nlohmann::json::parse(glb->begin() + 20, glb->begin() + 20 + json_length);
  EXPECT_EQ(json["nodes"][3]["weights"], nlohmann::json::array({0.5}));
  EXPECT_EQ(json["meshes"][0]["primitives"][0]["attributes"].count("JOINTS_1"), 1u);
  EXPECT_EQ(json["materials"][0]["pbrMetallicRoughness"]["metallicFactor"], 0.0);
}

TEST(Writer, GltfTextAndGlbFilesAreWrittenAtomically) {
  const std::filesystem::path folder = std::filesystem::path(PROXYGI_TEST_OUTPUT_DIR) / "writer";
  std::filesystem::remove_all(folder);
  std::filesystem::create_directories(folder);
  const Character original = everything();
  for (const char* name : {"everything.gltf", "everything.glb"}) {
    const std::filesystem::path path = folder / name;
    ASSERT_TRUE(write_character(original, path).ok());
    Result<Character> imported = import_gltf(path);
    ASSERT_TRUE(imported.ok()) << imported.message();
    expect_same(original, *imported);
  }
  // Only the two files: no temporary left behind.
  std::size_t files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(folder)) files += entry.is_regular_file() ? 1 : 0;
  EXPECT_EQ(files, 2u);
  EXPECT_FALSE(write_character(original, folder / "everything.obj").ok());
  EXPECT_FALSE(write_glb(original, folder / "missing_folder" / "x.glb").ok());
}

TEST(Writer, RejectsInconsistentCharacters) {
  Character broken = everything();
  broken.meshes[0].primitives[0].weights.pop_back();
  EXPECT_FALSE(encode_glb(broken).ok());
  broken = everything();
  broken.clips[0].channels[0].values.pop_back();
  EXPECT_FALSE(encode_glb(broken).ok());
}

}  // namespace
}  // namespace proxygi::anim
