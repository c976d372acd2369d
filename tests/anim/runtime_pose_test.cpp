// Local-to-model, blending, and whole-character posing on rigs written by the project's writer
// and read back by the importer: fixed-matrix nodes, the ignored skinned-mesh node transform,
// missing inverse bind matrices, rigid (unskinned) meshes, clip lookup.
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "anim/blending.h"
#include "anim/local_to_model.h"
#include "anim/posed_character.h"
#include "runtime_rigs.h"

namespace proxygi::anim {
namespace {

using testing::chain;
using testing::make_channel;
using testing::round_trip;

glm::quat about_z(float degrees) { return glm::angleAxis(glm::radians(degrees), glm::vec3(0, 0, 1)); }

// Parses the JSON chunk of a GLB (bytes 20 .. 20 + chunk length).
nlohmann::json glb_json(const std::vector<std::uint8_t>& glb) {
  std::uint32_t length = 0;
  std::memcpy(&length, glb.data() + 12, 4);
  return nlohmann::json::parse(glb.begin() + 20, glb.begin() + 20 + length);
}

TEST(LocalToModel, ComposesParentsFirstAndUsesFixedMatrices) {
  Character character = chain(3);
  character.nodes[1].rest.rotation = about_z(90.0f);
  character.nodes[1].rest.scale = glm::vec3(2.0f);
  glm::mat4 fixed(1.0f);
  fixed[3] = glm::vec4(5, 0, 0, 1);
  character.nodes[2].matrix = fixed;
  character.nodes[2].rest = Transform{};
  character = round_trip(character);
  ASSERT_TRUE(character.nodes[2].matrix.has_value());

  std::vector<Transform> locals(3);
  rest_pose(character, locals);
  locals[2].translation = glm::vec3(100, 100, 100);  // an "animated" matrix node: ignored
  std::vector<glm::mat4> world(3);
  glm::mat4 root(1.0f);
  root[3] = glm::vec4(0, 0, 10, 1);
  ASSERT_TRUE((LocalToModelJob{&character, locals, root, world}.run().ok()));
  EXPECT_EQ(world[0], root);
  // Node 2 origin: root + (0, 1, 0) + R90 · 2 · (5, 0, 0) = (0, 11, 10) up to rotation rounding.
  const glm::vec3 origin(world[2][3]);
  EXPECT_NEAR(origin.x, 0.0f, 1e-5f);
  EXPECT_NEAR(origin.y, 11.0f, 1e-5f);
  EXPECT_EQ(origin.z, 10.0f);

  std::vector<glm::mat4> short_world(2);
  EXPECT_FALSE((LocalToModelJob{&character, locals, root, short_world}.validate().ok()));
  Character broken = character;
  broken.evaluation_order[1] = 7;
  EXPECT_FALSE((LocalToModelJob{&broken, locals, root, world}.validate().ok()));
  EXPECT_FALSE((LocalToModelJob{nullptr, locals, root, world}.validate().ok()));
}

TEST(Blending, LerpsTranslationsAndSlerpsRotationsTheShortWay) {
  const std::vector<Transform> a = {{glm::vec3(0, 0, 0), about_z(0.0f), glm::vec3(1.0f)}};
  const std::vector<Transform> b = {{glm::vec3(4, 8, -2), -about_z(90.0f), glm::vec3(3.0f)}};
  const std::vector<float> morph_a = {0.0f, 1.0f}, morph_b = {1.0f, 0.0f};
  std::vector<Transform> out(1);
  std::vector<float> morph_out(2);
  BlendJob job{a, b, morph_a, morph_b, 0.25f, out, morph_out};
  ASSERT_TRUE(job.run().ok());
  EXPECT_EQ(out[0].translation, glm::vec3(1, 2, -0.5f));
  EXPECT_EQ(out[0].scale, glm::vec3(1.5f));
  EXPECT_EQ(morph_out, (std::vector<float>{0.25f, 0.75f}));
  const glm::vec3 v = out[0].rotation * glm::vec3(1, 0, 0);
  EXPECT_NEAR(v.x, std::cos(glm::radians(22.5f)), 1e-6f);
  EXPECT_NEAR(v.y, std::sin(glm::radians(22.5f)), 1e-6f);

  job.weight = 0.0f;
  ASSERT_TRUE(job.run().ok());
  EXPECT_EQ(out[0].translation, a[0].translation);
  EXPECT_EQ(out[0].rotation, a[0].rotation);
  job.weight = 1.0f;
  ASSERT_TRUE(job.run().ok());
  EXPECT_EQ(out[0].translation, b[0].translation);
  EXPECT_EQ(out[0].rotation, -b[0].rotation);  // same rotation, sign on a's side
  job.weight = 1.5f;
  EXPECT_FALSE(job.validate().ok());
  job.weight = 0.5f;
  job.output = {};
  EXPECT_FALSE(job.validate().ok());
}

// A two-joint skin whose mesh node (and that node's parent) carry transforms that must be
// ignored: vertices follow joint world × inverse bind only.
Character skinned_rig(bool identity_inverse_binds) {
  Character character = chain(2);  // joints: node 0 at origin, node 1 at (0, 1, 0)
  Node parent;
  parent.name = "mesh_parent";
  parent.rest.scale = glm::vec3(3.0f);
  parent.rest.translation = glm::vec3(0, 0, -7);
  parent.children = {3};
  character.nodes.push_back(parent);  // node 2
  Node mesh_node;
  mesh_node.name = "skinned_mesh";
  mesh_node.parent = 2;
  mesh_node.rest.translation = glm::vec3(5, 0, 0);
  mesh_node.rest.rotation = about_z(45.0f);
  mesh_node.mesh = 0;
  mesh_node.skin = 0;
  character.nodes.push_back(mesh_node);  // node 3
  character.roots = {0, 2};
  character.evaluation_order = {0, 1, 2, 3};

  Primitive primitive;
  primitive.positions = {{0, 0, 0}, {1, 0, 0}, {0, 2, 0}};
  primitive.normals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
  primitive.indices = {0, 1, 2};
  primitive.influences_per_vertex = 4;
  primitive.joints = {0, 0, 0, 0, 0, 1, 0, 0, 1, 0, 0, 0};
  primitive.weights = {1, 0, 0, 0, 0.5f, 0.5f, 0, 0, 1, 0, 0, 0};
  Mesh mesh;
  mesh.name = "skinned";
  mesh.primitives.push_back(primitive);
  character.meshes.push_back(mesh);

  Skin skin;
  skin.name = "skin";
  skin.joints = {0, 1};
  glm::mat4 ibm1(1.0f);
  if (!identity_inverse_binds) ibm1[3] = glm::vec4(0, -1, 0, 1);
  skin.inverse_bind_matrices = {glm::mat4(1.0f), ibm1};
  character.skins.push_back(skin);

  Clip clip;
  clip.name = "bend";
  clip.duration = 1.0f;
  const glm::quat q = about_z(90.0f);
  clip.channels.push_back(make_channel(1, ChannelPath::rotation, Interpolation::step, {0.0f},
                                       {q.x, q.y, q.z, q.w}));
  clip.channels.push_back(make_channel(0, ChannelPath::translation, Interpolation::linear, {0.0f, 1.0f},
                                       {0, 0, 0, 2, 0, 0}));
  // Animating the skinned mesh node has no visible effect either.
  clip.channels.push_back(make_channel(3, ChannelPath::translation, Interpolation::linear, {0.0f, 1.0f},
                                       {9, 9, 9, -9, -9, -9}));
  character.clips.push_back(clip);
  return character;
}

TEST(PosedCharacter, SkinnedMeshNodeTransformIsIgnored) {
  const Character character = round_trip(skinned_rig(false));
  PoseBuffers pose;
  ASSERT_TRUE(evaluate_pose(character, 0, 0.5f, WrapMode::clamp, pose).ok());
  Result<std::vector<PosedPrimitive>> meshes = pose_meshes(character, pose);
  ASSERT_TRUE(meshes.ok()) << meshes.message();
  ASSERT_EQ(meshes->size(), 1u);
  const PosedPrimitive& p = meshes->front();
  // Joint 0 at (1, 0, 0) (half-way through its translation), joint 1 at (1, 1, 0) turned 90°.
  EXPECT_EQ(p.positions[0], glm::vec3(1, 0, 0));
  // Vertex 1 (1, 0, 0): half joint 0 → (2, 0, 0); half joint 1: bind offset (1, −1, 0) turned
  // 90° → (1, 1, 0), plus (1, 1, 0) → (2, 2, 0); the blend is (2, 1, 0) up to rotation rounding.
  EXPECT_NEAR(p.positions[1].x, 2.0f, 1e-6f);
  EXPECT_NEAR(p.positions[1].y, 1.0f, 1e-6f);
  // Vertex 2 (0, 2, 0) on joint 1: offset (0, 1, 0) turned 90° → (−1, 0, 0), plus (1, 1, 0).
  EXPECT_NEAR(p.positions[2].x, 0.0f, 1e-6f);
  EXPECT_NEAR(p.positions[2].y, 1.0f, 1e-6f);
  EXPECT_EQ(p.positions[2].z, 0.0f);
  EXPECT_NEAR(p.normals[2].z, 1.0f, 1e-6f);
}

TEST(PosedCharacter, MissingInverseBindMatricesMeanIdentity) {
  const Character written = skinned_rig(true);
  Result<std::vector<std::uint8_t>> glb = encode_glb(written);
  ASSERT_TRUE(glb.ok());
  const nlohmann::json json = glb_json(*glb);
  ASSERT_FALSE(json["skins"][0].contains("inverseBindMatrices"));  // the file really lacks them

  const Character character = round_trip(written);
  ASSERT_EQ(character.skins[0].inverse_bind_matrices.size(), 2u);
  EXPECT_EQ(character.skins[0].inverse_bind_matrices[1], glm::mat4(1.0f));
  PoseBuffers pose;
  ASSERT_TRUE(evaluate_pose(character, -1, 0.0f, WrapMode::clamp, pose).ok());  // rest pose
  Result<std::vector<PosedPrimitive>> meshes = pose_meshes(character, pose);
  ASSERT_TRUE(meshes.ok());
  // Identity inverse bind: joint 1's rest world (translation (0, 1, 0)) moves its vertices up by 1.
  EXPECT_EQ(meshes->front().positions[2], glm::vec3(0, 3, 0));
  EXPECT_EQ(meshes->front().positions[1], glm::vec3(1, 0.5f, 0));
}

TEST(PosedCharacter, UnskinnedMeshFollowsItsNodeRigidly) {
  Character character = chain(2);
  const int node = testing::add_triangle_node(character, {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
  // Re-parent the mesh node under joint 1 so the joint's animation carries it.
  character.roots.pop_back();
  character.nodes[static_cast<std::size_t>(node)].parent = 1;
  character.nodes[1].children.push_back(node);
  character.nodes[static_cast<std::size_t>(node)].rest.translation = glm::vec3(0, 0, 2);
  Clip clip;
  clip.name = "lift";
  clip.duration = 2.0f;
  clip.channels.push_back(make_channel(0, ChannelPath::translation, Interpolation::linear, {0.0f, 2.0f}, {0, 0, 0, 0, 4, 0}));
  character.clips.push_back(clip);
  character = round_trip(character);

  PoseBuffers pose;
  ASSERT_TRUE(evaluate_pose(character, 0, 1.0f, WrapMode::clamp, pose).ok());
  Result<std::vector<PosedPrimitive>> meshes = pose_meshes(character, pose);
  ASSERT_TRUE(meshes.ok());
  EXPECT_EQ(meshes->front().positions[1], glm::vec3(1, 3, 2));  // (1,0,0) + (0,2,0) + (0,1,0) + (0,0,2)
  EXPECT_EQ(meshes->front().normals[0], glm::vec3(0, 0, 1));
}

TEST(PosedCharacter, FindsClipsByNameOrIndexAndListsThemOtherwise) {
  const Character character = round_trip(skinned_rig(false));
  EXPECT_EQ(*find_clip(character, "bend"), 0);
  EXPECT_EQ(*find_clip(character, "0"), 0);
  Result<int> missing = find_clip(character, "dance");
  ASSERT_FALSE(missing.ok());
  EXPECT_NE(missing.message().find("'bend'"), std::string::npos) << missing.message();
  EXPECT_FALSE(find_clip(character, "1").ok());
  EXPECT_FALSE(find_clip(character, "-1").ok());
  EXPECT_FALSE(find_clip(character, "0x").ok());
  PoseBuffers pose;
  EXPECT_FALSE(evaluate_pose(character, 3, 0.0f, WrapMode::clamp, pose).ok());
}

}  // namespace
}  // namespace proxygi::anim
