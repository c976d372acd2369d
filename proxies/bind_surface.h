#pragma once
// The character's surface in its bind pose, in one space, with what proxy fitting needs per
// vertex: bone influences (as node indices), UVs and the material per triangle.
//
// Spaces:
//  - bind space: where the whole surface lives here. For a skinned mesh it is the mesh space
//    the positions are stored in (glTF skinning ignores the mesh node's transform, and at the
//    bind pose joint_world = inverse(inverse_bind_matrix) so skinned positions equal stored
//    ones). For a mesh without skin it is the model space of the rest pose:
//    rest_world(node) * position.
//  - bone space of node j: the node's local frame; world = node_world[j] * bone-space point.
//    bind_to_bone[j] maps bind space to it: the skin's inverse bind matrix for a joint, or
//    inverse(rest_world(node)) for the node of an unskinned mesh.
// A vertex's dominant bone is its largest-weight influence (the first listed).
#include <array>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "anim/character.h"
#include "base/result.h"
#include "proxies/mesh_index.h"

namespace proxygi::proxies {

inline constexpr int kMaxInfluences = 8;

// Bone influences as node indices, sorted by weight (largest first), weights summing to 1;
// unused slots have node -1 and weight 0.
struct Influences {
  std::array<int, kMaxInfluences> nodes;
  std::array<float, kMaxInfluences> weights;
  Influences() { nodes.fill(-1); weights.fill(0.0f); }
  int dominant() const { return nodes[0]; }
};

// Adds `weight` for `node` into an accumulator keyed by node (keeps the largest kMaxInfluences).
void accumulate(std::vector<std::pair<int, float>>& sum, int node, float weight);
// Turns an accumulator into sorted, normalized Influences.
Influences to_influences(std::vector<std::pair<int, float>> sum);

struct BindSurface {
  TriangleSoup soup;                      // bind space, meters
  std::vector<Influences> influences;     // per vertex
  std::vector<glm::vec2> uvs;             // per vertex, (0, 0) when the primitive has none
  std::vector<int> triangle_material;     // per triangle, index into Character::materials or -1
  std::vector<float> triangle_area;       // per triangle, m² (OpenMesh sector areas)
  std::vector<glm::mat4> bind_to_bone;    // per node (bind_to_bone_matrices)
  std::vector<int> vertex_count_per_bone; // per node: vertices whose dominant bone it is
  // OpenMesh connectivity after welding equal positions: boundary edges mean the surface is
  // open, which makes inside tests (and so inner points and outside volume) less reliable.
  int welded_vertices = 0;
  int boundary_edges = 0;
  int non_manifold_faces = 0;  // faces OpenMesh refused (added as detached triangles)
  std::vector<std::string> warnings;
};

// Collects every mesh instance of the character (nodes with a mesh), skinned or not.
// Fails when there is no triangle at all, or on inconsistent data (joint index outside the
// skin, non-finite position), naming mesh, primitive and index.
Result<BindSurface> extract_bind_surface(const anim::Character& character);

// Rest-pose model matrices of every node (parents before children via evaluation_order).
std::vector<glm::mat4> rest_world_matrices(const anim::Character& character);

// bind_to_bone for every node: the inverse bind matrix from the first skin that lists the node
// as a joint, else inverse(rest_world(node)). `rest_world` comes from rest_world_matrices().
std::vector<glm::mat4> bind_to_bone_matrices(const anim::Character& character,
                                             const std::vector<glm::mat4>& rest_world);

// Linear base color of a material at `uv`: factor × texture (bilinear, repeat, sRGB → linear).
glm::vec3 base_color(const anim::Character& character, int material, const glm::vec2& uv);

}  // namespace proxygi::proxies
