#include "anim/posed_character.h"

#include <charconv>
#include <string>

#include "anim/local_to_model.h"
#include "anim/skinning.h"

namespace proxygi::anim {

Status evaluate_pose(const Character& character, int clip, float time, WrapMode wrap, PoseBuffers& pose,
                     const glm::mat4& root_transform) {
  const std::size_t node_count = character.nodes.size();
  pose.locals.resize(node_count);
  pose.morph_weights.resize(static_cast<std::size_t>(morph_weight_count(character)));
  pose.world.resize(node_count);
  if (clip < 0) {
    rest_pose(character, pose.locals);
    default_morph_weights(character, pose.morph_weights);
  } else {
    if (static_cast<std::size_t>(clip) >= character.clips.size()) {
      return make_error(character.source + ": clip " + std::to_string(clip) + " out of range (" +
                        std::to_string(character.clips.size()) + " clips)");
    }
    SampleClipJob sample;
    sample.character = &character;
    sample.clip = &character.clips[static_cast<std::size_t>(clip)];
    sample.time = time;
    sample.wrap = wrap;
    sample.locals = pose.locals;
    sample.morph_weights = pose.morph_weights;
    if (Status status = sample.run(); !status) return make_error(character.source + ": " + status.message());
  }
  return pose_from_locals(character, pose, root_transform);
}

Status pose_from_locals(const Character& character, PoseBuffers& pose, const glm::mat4& root_transform) {
  if (pose.locals.size() != character.nodes.size())
    return make_error(character.source + ": pose_from_locals: " + std::to_string(pose.locals.size()) + " locals for " +
                      std::to_string(character.nodes.size()) + " nodes");
  pose.world.resize(character.nodes.size());
  LocalToModelJob to_model;
  to_model.character = &character;
  to_model.locals = pose.locals;
  to_model.root_transform = root_transform;
  to_model.world = pose.world;
  if (Status status = to_model.run(); !status) return status;

  pose.skin_matrices.resize(character.skins.size());
  pose.normal_matrices.resize(character.skins.size());
  for (std::size_t s = 0; s < character.skins.size(); ++s) {
    pose.skin_matrices[s].resize(character.skins[s].joints.size());
    pose.normal_matrices[s].resize(character.skins[s].joints.size());
    SkinMatricesJob job;
    job.skin = &character.skins[s];
    job.world = pose.world;
    job.skin_matrices = pose.skin_matrices[s];
    job.normal_matrices = pose.normal_matrices[s];
    if (Status status = job.run(); !status) return make_error(character.source + ": " + status.message());
  }
  return {};
}

Result<std::vector<PosedPrimitive>> pose_meshes(const Character& character, const PoseBuffers& pose) {
  if (pose.world.size() != character.nodes.size()) {
    return make_error(character.source + ": pose_meshes: the pose does not belong to this character");
  }
  std::vector<PosedPrimitive> result;
  std::vector<glm::vec3> morphed_positions;
  std::vector<glm::vec3> morphed_normals;
  for (std::size_t n = 0; n < character.nodes.size(); ++n) {
    const Node& node = character.nodes[n];
    if (node.mesh < 0) continue;
    if (static_cast<std::size_t>(node.mesh) >= character.meshes.size() ||
        (node.skin >= 0 && static_cast<std::size_t>(node.skin) >= pose.skin_matrices.size())) {
      return make_error(character.source + ": node " + std::to_string(n) + ": mesh or skin index out of range");
    }
    const Mesh& mesh = character.meshes[static_cast<std::size_t>(node.mesh)];
    const std::size_t morph_offset = static_cast<std::size_t>(morph_weight_offset(character, static_cast<int>(n)));
    for (std::size_t p = 0; p < mesh.primitives.size(); ++p) {
      const Primitive& primitive = mesh.primitives[p];
      const std::string where = character.source + ": node " + std::to_string(n) + " mesh " +
                                std::to_string(node.mesh) + " primitive " + std::to_string(p);
      PosedPrimitive out;
      out.name = node.name + "/" + mesh.name + "/" + std::to_string(p);
      out.node = static_cast<int>(n);
      out.mesh = node.mesh;
      out.primitive = static_cast<int>(p);
      out.material = primitive.material;
      out.uvs = primitive.uvs;
      out.indices = primitive.indices;
      out.positions.resize(primitive.positions.size());
      out.normals.resize(primitive.normals.empty() ? 0 : primitive.positions.size());

      // Morph targets first (glTF: before skinning and node transforms).
      std::span<const glm::vec3> positions = primitive.positions;
      std::span<const glm::vec3> normals = primitive.normals;
      if (!primitive.morph_targets.empty()) {
        morphed_positions.resize(positions.size());
        morphed_normals.resize(normals.size());
        MorphJob morph;
        morph.targets = primitive.morph_targets;
        morph.weights = std::span<const float>(pose.morph_weights).subspan(morph_offset, primitive.morph_targets.size());
        morph.positions = positions;
        morph.normals = normals;
        morph.out_positions = morphed_positions;
        morph.out_normals = morphed_normals;
        if (Status status = morph.run(); !status) return make_error(where + ": " + status.message());
        positions = morphed_positions;
        normals = morphed_normals;
      }

      if (node.skin >= 0 && primitive.influences_per_vertex > 0) {
        SkinningJob skin;
        skin.influences_per_vertex = primitive.influences_per_vertex;
        skin.skin_matrices = pose.skin_matrices[static_cast<std::size_t>(node.skin)];
        skin.normal_matrices = pose.normal_matrices[static_cast<std::size_t>(node.skin)];
        skin.joints = primitive.joints;
        skin.weights = primitive.weights;
        skin.positions = positions;
        skin.normals = normals;
        skin.out_positions = out.positions;
        skin.out_normals = out.normals;
        if (Status status = skin.run(); !status) return make_error(where + ": " + status.message());
      } else {
        RigidTransformJob rigid;
        rigid.world = pose.world[n];
        rigid.positions = positions;
        rigid.normals = normals;
        rigid.out_positions = out.positions;
        rigid.out_normals = out.normals;
        if (Status status = rigid.run(); !status) return make_error(where + ": " + status.message());
      }
      result.push_back(std::move(out));
    }
  }
  return result;
}

Result<int> find_clip(const Character& character, const std::string& name_or_index) {
  for (std::size_t i = 0; i < character.clips.size(); ++i) {
    if (character.clips[i].name == name_or_index) return static_cast<int>(i);
  }
  int index = -1;
  const char* end = name_or_index.data() + name_or_index.size();
  const auto [last, error] = std::from_chars(name_or_index.data(), end, index);
  if (error == std::errc() && last == end && !name_or_index.empty()) {
    if (index >= 0 && static_cast<std::size_t>(index) < character.clips.size()) return index;
  }
  std::string names;
  for (std::size_t i = 0; i < character.clips.size(); ++i) {
    names += (i ? ", " : "") + std::to_string(i) + " '" + character.clips[i].name + "'";
  }
  return make_error(character.source + ": no clip '" + name_or_index + "' (clips: " +
                    (names.empty() ? std::string("none") : names) + ")");
}

}  // namespace proxygi::anim
