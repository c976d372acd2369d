#include "anim/mannequin.h"

#include <algorithm>
#include <limits>

#include "anim/mannequin_parts.h"

namespace proxygi::anim {
namespace mannequin {

const std::array<JointInfo, kJointCount> kJoints = {{
    {"root", -1}, {"hips", kRoot}, {"spine", kHips}, {"chest", kSpine}, {"neck", kChest}, {"head", kNeck},
    {"left_shoulder", kChest}, {"left_upper_arm", kLeftShoulder}, {"left_lower_arm", kLeftUpperArm},
    {"left_hand", kLeftLowerArm},
    {"right_shoulder", kChest}, {"right_upper_arm", kRightShoulder}, {"right_lower_arm", kRightUpperArm},
    {"right_hand", kRightLowerArm},
    {"left_upper_leg", kHips}, {"left_lower_leg", kLeftUpperLeg}, {"left_foot", kLeftLowerLeg},
    {"left_toes", kLeftFoot},
    {"right_upper_leg", kHips}, {"right_lower_leg", kRightUpperLeg}, {"right_foot", kRightLowerLeg},
    {"right_toes", kRightFoot},
}};

std::array<glm::vec3, kJointCount> initial_joint_positions() {
  std::array<glm::vec3, kJointCount> p{};
  p[kRoot] = {0.0f, 0.0f, 0.0f};
  p[kHips] = {0.0f, 0.95f, 0.0f};
  p[kSpine] = {0.0f, 1.07f, 0.0f};
  p[kChest] = {0.0f, 1.25f, 0.0f};
  p[kNeck] = {0.0f, 1.49f, 0.0f};
  p[kHead] = {0.0f, 1.60f, 0.0f};
  // Left side (+X); the right side mirrors it.
  p[kLeftShoulder] = {0.035f, 1.45f, 0.0f};
  p[kLeftUpperArm] = {0.185f, 1.445f, 0.0f};
  p[kLeftLowerArm] = {0.225f, 1.16f, 0.0f};
  p[kLeftHand] = {0.255f, 0.91f, 0.0f};
  p[kLeftUpperLeg] = {0.095f, 0.93f, 0.0f};
  p[kLeftLowerLeg] = {0.095f, 0.50f, 0.0f};
  p[kLeftFoot] = {0.095f, 0.085f, 0.0f};
  p[kLeftToes] = {0.095f, 0.035f, 0.13f};
  for (int j = kLeftShoulder; j <= kLeftHand; ++j) {
    p[static_cast<std::size_t>(j + kRightShoulder - kLeftShoulder)] = p[static_cast<std::size_t>(j)] * glm::vec3(-1, 1, 1);
  }
  for (int j = kLeftUpperLeg; j <= kLeftToes; ++j) {
    p[static_cast<std::size_t>(j + kRightUpperLeg - kLeftUpperLeg)] = p[static_cast<std::size_t>(j)] * glm::vec3(-1, 1, 1);
  }
  return p;
}

}  // namespace mannequin

Character build_mannequin(const MannequinOptions& options) {
  using namespace mannequin;
  Character character;
  character.source = "mannequin";

  std::array<glm::vec3, kJointCount> positions = initial_joint_positions();
  Mesh mesh;
  mesh.name = "mannequin";
  build_surface(positions, options, mesh);

  // Ground shift: the lowest vertex of the rest pose lands exactly on y = 0.
  float lowest = std::numeric_limits<float>::max();
  for (const Primitive& primitive : mesh.primitives) {
    for (const glm::vec3& v : primitive.positions) lowest = std::min(lowest, v.y);
  }
  for (Primitive& primitive : mesh.primitives) {
    for (glm::vec3& v : primitive.positions) v.y -= lowest;
  }
  for (glm::vec3& p : positions) p.y -= lowest;
  positions[kRoot] = glm::vec3(0.0f);  // the root stays on the ground at the origin

  // Joints are nodes 0..kJointCount−1 with identity rest rotations; node kJointCount carries the
  // skinned mesh (a scene root with identity transform, which skinning ignores anyway).
  for (int j = 0; j < kJointCount; ++j) {
    const JointInfo& info = kJoints[static_cast<std::size_t>(j)];
    Node node;
    node.name = info.name;
    node.parent = info.parent;
    node.rest.translation = info.parent < 0 ? positions[static_cast<std::size_t>(j)]
                                            : positions[static_cast<std::size_t>(j)] - positions[static_cast<std::size_t>(info.parent)];
    character.nodes.push_back(node);
  }
  for (int j = 1; j < kJointCount; ++j) {
    character.nodes[static_cast<std::size_t>(kJoints[static_cast<std::size_t>(j)].parent)].children.push_back(j);
  }
  Node mesh_node;
  mesh_node.name = "mannequin_mesh";
  mesh_node.mesh = 0;
  mesh_node.skin = 0;
  character.nodes.push_back(mesh_node);
  character.roots = {kRoot, kJointCount};
  // Evaluation order: joint indices already list parents first (see kJoints), then the mesh node.
  for (int n = 0; n <= kJointCount; ++n) character.evaluation_order.push_back(n);

  Skin skin;
  skin.name = "mannequin_skin";
  skin.skeleton = kRoot;
  for (int j = 0; j < kJointCount; ++j) {
    skin.joints.push_back(j);
    // Bind pose: identity rotations, so the inverse bind matrix is a pure translation.
    glm::mat4 inverse_bind(1.0f);
    inverse_bind[3] = glm::vec4(-positions[static_cast<std::size_t>(j)], 1.0f);
    skin.inverse_bind_matrices.push_back(inverse_bind);
  }
  character.skins.push_back(std::move(skin));
  character.meshes.push_back(std::move(mesh));

  const std::array<std::pair<const char*, glm::vec4>, kMaterialCount> materials = {{
      {"shirt", {0.80f, 0.05f, 0.04f, 1.0f}},
      {"trousers", {0.06f, 0.14f, 0.60f, 1.0f}},
      {"skin", {0.80f, 0.56f, 0.42f, 1.0f}},
      {"shoes", {0.04f, 0.035f, 0.03f, 1.0f}},
  }};
  for (const auto& [name, color] : materials) {
    Material material;
    material.name = name;
    material.base_color_factor = color;
    character.materials.push_back(material);
  }
  character.clips = build_clips(positions);
  return character;
}

}  // namespace proxygi::anim
