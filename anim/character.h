#pragma once
// Character: everything proxygi knows about one glTF asset, as plain structs with no tinygltf
// type. Produced by anim::import_gltf (validated) or built in code (the mannequin), consumed by
// sampling, skinning, proxy fitting and the GPU passes.
//
// Conventions (glTF 2.0): right-handed, +Y up, meters, seconds. GLM matrices are column-major
// (m[column][row]); a node's local matrix is T * R * S. Quaternions are glm::quat (w, x, y, z
// in the constructor; stored x, y, z, w in glTF files). Indices into the vectors below are the
// indices the source file used, so error messages can name them ("node 12", "mesh 2").
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

namespace proxygi::anim {

// Translation, rotation (unit quaternion), scale. to_matrix() = T * R * S.
struct Transform {
  glm::vec3 translation{0.0f};
  glm::quat rotation{1.0f, 0.0f, 0.0f, 0.0f};
  glm::vec3 scale{1.0f};
};

struct Node {
  std::string name;
  int parent = -1;             // -1 for scene roots
  std::vector<int> children;
  Transform rest;              // rest-pose TRS (identity when the node has a matrix)
  std::optional<glm::mat4> matrix;  // glTF "matrix" nodes: fixed, never animated
  int mesh = -1;               // index into Character::meshes, -1 if none
  int skin = -1;               // index into Character::skins, -1 if none
  std::vector<float> morph_weights;  // glTF node.weights (overrides mesh weights); empty if absent
};

// RGBA8 image in row-major order, top row first, sRGB-encoded as stored in the file.
struct Image {
  std::string name;
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgba;  // width * height * 4 bytes
};

// glTF sampler of a texture. glTF leaves absent filters to the implementation; proxygi takes
// LINEAR magnification and LINEAR_MIPMAP_LINEAR minification then. Wrap defaults to REPEAT.
enum class TextureWrap { repeat, clamp_to_edge, mirrored_repeat };
enum class TextureFilter { nearest, linear };
struct TextureSampler {
  TextureFilter magnification = TextureFilter::linear;
  TextureFilter minification = TextureFilter::linear;
  bool mipmaps = true;                           // false: minFilter NEAREST or LINEAR (level 0 only)
  TextureFilter mipmap = TextureFilter::linear;  // between levels (…_MIPMAP_NEAREST / _LINEAR)
  TextureWrap wrap_s = TextureWrap::repeat;      // along u
  TextureWrap wrap_t = TextureWrap::repeat;      // along v
};

struct Material {
  std::string name;
  glm::vec4 base_color_factor{1.0f};  // linear RGBA
  int base_color_image = -1;          // index into Character::images, -1 if untextured
  int base_color_texcoord = 0;        // which TEXCOORD_n the texture reads (only 0 is imported;
                                      // KHR_texture_transform's texCoord overrides it)
  TextureSampler base_color_sampler;
  // KHR_texture_transform of the base color texture: uv' = (M * vec3(uv, 1)).xy with
  // M = translation(offset) * rotation(counter-clockwise) * scale; identity when absent.
  glm::mat3 base_color_uv_transform{1.0f};
  bool double_sided = false;
};

// Morph target displacements, applied before skinning: p' = p + sum_k w_k * position_deltas_k.
struct MorphTarget {
  std::vector<glm::vec3> position_deltas;  // empty or vertex_count entries
  std::vector<glm::vec3> normal_deltas;    // empty or vertex_count entries
};

// One drawable primitive, always triangles with 32-bit indices after import.
struct Primitive {
  std::vector<glm::vec3> positions;  // mesh-local space, meters
  std::vector<glm::vec3> normals;    // unit length; computed (OpenMesh) when the file has none
  std::vector<glm::vec2> uvs;        // TEXCOORD_0, empty if absent
  std::vector<std::uint32_t> indices;  // 3 per triangle, each < positions.size()
  // Skinning: influences_per_vertex entries per vertex (0, 4, 8, ...), joint indices index the
  // skin's joint list (not nodes). Weights are non-negative and sum to 1 per vertex after
  // import (renormalized; an all-zero vertex is bound rigidly to joint 0 with weight 1).
  int influences_per_vertex = 0;
  std::vector<std::uint16_t> joints;
  std::vector<float> weights;
  std::vector<MorphTarget> morph_targets;
  int material = -1;  // index into Character::materials, -1 = default white
};

struct Mesh {
  std::string name;
  std::vector<Primitive> primitives;
  std::vector<float> default_morph_weights;  // mesh.weights, one per morph target
};

struct Skin {
  std::string name;
  std::vector<int> joints;                        // node indices; palette index = position here
  std::vector<glm::mat4> inverse_bind_matrices;   // one per joint (identity when absent)
  int skeleton = -1;                              // optional hint, node index or -1
};

enum class Interpolation { step, linear, cubic_spline };
enum class ChannelPath { translation, rotation, scale, weights };

// One animated property of one node. For cubic_spline each key stores in-tangent, value,
// out-tangent (3 * components floats per key), tangents not yet scaled by the key interval.
struct Channel {
  int node = -1;
  ChannelPath path = ChannelPath::translation;
  Interpolation interpolation = Interpolation::linear;
  std::vector<float> times;   // seconds, strictly increasing, >= 0
  std::vector<float> values;  // components per element: 3 (T, S), 4 (R as x,y,z,w), or morph count
  int components = 3;
};

struct Clip {
  std::string name;
  std::vector<Channel> channels;
  float duration = 0.0f;  // seconds: max key time over channels (playback starts at t = 0)
};

struct Character {
  std::string source;  // file path or "mannequin"; prefixes error messages
  std::vector<Node> nodes;
  std::vector<int> roots;             // scene root nodes (default scene, else all parentless)
  std::vector<int> evaluation_order;  // every node, parents before children
  std::vector<Mesh> meshes;
  std::vector<Skin> skins;
  std::vector<Material> materials;
  std::vector<Image> images;
  std::vector<Clip> clips;
};

glm::mat4 to_matrix(const Transform& transform);

}  // namespace proxygi::anim
