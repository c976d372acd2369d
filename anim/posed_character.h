#pragma once
// Convenience over the jobs: pose a whole character at (clip, time) and get world matrices,
// skin matrices, and world-space meshes. Allocates; for per-frame work keep a PoseBuffers and
// call evaluate_pose() again (buffers are reused when the character is the same).
//
//   PoseBuffers pose;
//   if (Status s = evaluate_pose(character, clip_index, 0.5f, WrapMode::loop, pose); !s) ...
//   pose.world[node];          // world matrix of every node
//   pose.skin_matrices[skin];  // palette of each skin
//   Result<std::vector<PosedPrimitive>> meshes = pose_meshes(character, pose);
#include <string>
#include <vector>

#include "anim/character.h"
#include "anim/sampling.h"
#include "base/result.h"

namespace proxygi::anim {

struct PoseBuffers {
  std::vector<Transform> locals;     // per node, node-local space
  std::vector<float> morph_weights;  // flat layout of sampling.h
  std::vector<glm::mat4> world;      // per node, world space (column-major)
  std::vector<std::vector<glm::mat4>> skin_matrices;    // per skin, per joint: bind → world
  std::vector<std::vector<glm::mat4>> normal_matrices;  // inverse-transposes of the above
};

// Samples clip `clip` (index into character.clips; -1 = rest pose) at `time` seconds, then
// computes world, skin and normal matrices. Errors name the character source and the clip.
Status evaluate_pose(const Character& character, int clip, float time, WrapMode wrap,
                     PoseBuffers& pose, const glm::mat4& root_transform = glm::mat4(1.0f));

// The second half of evaluate_pose: world, skin and normal matrices from pose.locals (and
// pose.morph_weights) already filled in, e.g. by blending two sampled clips (blending.h).
Status pose_from_locals(const Character& character, PoseBuffers& pose, const glm::mat4& root_transform = glm::mat4(1.0f));

// One primitive of one mesh instance, in world space.
struct PosedPrimitive {
  std::string name;  // "<node name>/<mesh name>/<primitive index>"
  int node = -1;
  int mesh = -1;
  int primitive = -1;
  int material = -1;
  std::vector<glm::vec3> positions;  // world space, meters
  std::vector<glm::vec3> normals;    // world space, unit length (empty when the source has none)
  std::vector<glm::vec2> uvs;
  std::vector<std::uint32_t> indices;
};

// Every mesh instance (each node with a mesh) in world space: morph targets first, then
// skinning (node has a skin: the node's own transform is ignored) or the node's world matrix.
Result<std::vector<PosedPrimitive>> pose_meshes(const Character& character, const PoseBuffers& pose);

// Finds a clip by name or by decimal index ("walk", "2"). Error lists the available names.
Result<int> find_clip(const Character& character, const std::string& name_or_index);

}  // namespace proxygi::anim
