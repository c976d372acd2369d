#pragma once
// Internal to the mannequin builder (anim/mannequin*.cpp): the skeleton table, the body-part
// surfaces and the procedural clips. Positions are bind-pose world space, meters, +Y up, +Z front.
#include <array>
#include <vector>

#include "anim/character.h"
#include "anim/mannequin.h"

namespace proxygi::anim::mannequin {

enum Joint : int {
  kRoot, kHips, kSpine, kChest, kNeck, kHead,
  kLeftShoulder, kLeftUpperArm, kLeftLowerArm, kLeftHand,
  kRightShoulder, kRightUpperArm, kRightLowerArm, kRightHand,
  kLeftUpperLeg, kLeftLowerLeg, kLeftFoot, kLeftToes,
  kRightUpperLeg, kRightLowerLeg, kRightFoot, kRightToes,
  kJointCount
};

enum MaterialId : int { kShirt, kTrousers, kSkin, kShoes, kMaterialCount };

struct JointInfo {
  const char* name;
  int parent;  // joint index, -1 for the root
};
extern const std::array<JointInfo, kJointCount> kJoints;

// Bind-pose joint positions before the ground shift (the builder moves everything so the lowest
// vertex lands on y = 0).
std::array<glm::vec3, kJointCount> initial_joint_positions();

// Appends the skinned surface, one primitive per material, to `mesh`. Joint indices are skin
// palette indices (== Joint values). `positions` are the bind-pose joint positions.
void build_surface(const std::array<glm::vec3, kJointCount>& positions, const MannequinOptions& options, Mesh& mesh);

// The three clips; channel node indices equal Joint values (joints are nodes 0..kJointCount-1).
std::vector<Clip> build_clips(const std::array<glm::vec3, kJointCount>& positions);

}  // namespace proxygi::anim::mannequin
