#version 460
// Skin pass: linear blend skinning of one primitive for push.instances instances of it (one
// dispatch; instance i = gl_WorkGroupID.y reads joints i × push.joints .. of the palettes and
// morph weights i × push.morph_targets .., and writes vertices i × push.instance_stride ..),
// formula for formula the CPU reference
// anim::SkinningJob (anim/skinning.h): M = sum_k w_k S[j_k], p' = M p, n' = normalize(N n),
// after anim::MorphJob: p = p0 + sum_t w_t dp_t, n = n0 + sum_t w_t dn_t.
// The palettes are uniform buffers (up to kSkinUniformPaletteJoints joints) or, compiled with
// STORAGE_PALETTE, storage buffers (shared/skin_palette.h); the arithmetic is the same.
#extension GL_GOOGLE_include_directive : require
#include "shared/layouts.h"
#include "shared/skin_palette.h"

layout(local_size_x = kSkinLocalSize) in;
layout(push_constant) uniform Push { SkinPush push; };
layout(std430, set = 0, binding = kSkinBindBindPositions) readonly buffer Positions { float bind_positions[]; };
layout(std430, set = 0, binding = kSkinBindBindNormals) readonly buffer Normals { float bind_normals[]; };
layout(std430, set = 0, binding = kSkinBindJoints) readonly buffer Joints { uint packed_joints[]; };
layout(std430, set = 0, binding = kSkinBindWeights) readonly buffer Weights { float weights[]; };
#ifdef STORAGE_PALETTE
layout(std430, set = 0, binding = kSkinBindSkinMatrices) readonly buffer SkinMatrices { mat4 skin_matrices[]; };
layout(std430, set = 0, binding = kSkinBindNormalMatrices) readonly buffer NormalMatrices { mat4 normal_matrices[]; };
#else
layout(std140, set = 0, binding = kSkinBindSkinMatrices) uniform SkinMatrices { mat4 skin_matrices[kSkinUniformPaletteJoints]; };
layout(std140, set = 0, binding = kSkinBindNormalMatrices) uniform NormalMatrices { mat4 normal_matrices[kSkinUniformPaletteJoints]; };
#endif
layout(std430, set = 0, binding = kSkinBindOutPositions) writeonly buffer OutPositions { vec4 out_positions[]; };
layout(std430, set = 0, binding = kSkinBindOutNormals) writeonly buffer OutNormals { vec4 out_normals[]; };
layout(std430, set = 0, binding = kSkinBindPositionDeltas) readonly buffer PositionDeltas { float position_deltas[]; };
layout(std430, set = 0, binding = kSkinBindNormalDeltas) readonly buffer NormalDeltas { float normal_deltas[]; };
layout(std430, set = 0, binding = kSkinBindMorphWeights) readonly buffer MorphWeights { float morph_weights[]; };

uint palette_index(uint flat_index) {
  uint word = packed_joints[flat_index >> 1];
  return (flat_index & 1u) == 0u ? (word & 0xFFFFu) : (word >> 16);
}

void main() {
  uint vertex = gl_GlobalInvocationID.x;
  if (vertex >= push.vertex_count) return;
  uint instance = gl_WorkGroupID.y;
  uint first_joint = instance * push.joints;
  uint out_vertex = instance * push.instance_stride + vertex;
  mat4 blended = mat4(0.0);
  mat3 blended_normal = mat3(0.0);
  for (uint k = 0u; k < push.influences; ++k) {
    uint flat_index = vertex * push.influences + k;
    uint joint = first_joint + palette_index(flat_index);
    float weight = weights[flat_index];
    blended += weight * skin_matrices[joint];
    if (push.use_normal_matrices != 0u) blended_normal += weight * mat3(normal_matrices[joint]);
  }
  vec3 position = vec3(bind_positions[3u * vertex], bind_positions[3u * vertex + 1u], bind_positions[3u * vertex + 2u]);
  vec3 normal = vec3(0.0);
  if (push.has_normals != 0u)
    normal = vec3(bind_normals[3u * vertex], bind_normals[3u * vertex + 1u], bind_normals[3u * vertex + 2u]);
  for (uint t = 0u; t < push.morph_targets; ++t) {
    float w = morph_weights[instance * push.morph_targets + t];
    if (w == 0.0) continue;
    uint at = 3u * (t * push.vertex_count + vertex);
    position += w * vec3(position_deltas[at], position_deltas[at + 1u], position_deltas[at + 2u]);
    if (push.has_normals != 0u) normal += w * vec3(normal_deltas[at], normal_deltas[at + 1u], normal_deltas[at + 2u]);
  }
  out_positions[out_vertex] = vec4((blended * vec4(position, 1.0)).xyz, 1.0);
  if (push.has_normals != 0u) {
    if (push.use_normal_matrices == 0u) blended_normal = mat3(blended);
    vec3 skinned = blended_normal * normal;
    float length_squared = dot(skinned, skinned);
    out_normals[out_vertex] = vec4(length_squared > 0.0 ? skinned * inversesqrt(length_squared) : vec3(0.0), 0.0);
  }
}
