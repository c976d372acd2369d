#pragma once
// Skinning: skin matrices from world matrices, then CPU linear blend skinning. This is the CPU
// reference the GPU skinning pass mirrors formula for formula.
//
// Spaces. Mesh vertices are in mesh-local (bind) space. skin matrix j = world[skin.joints[j]] ·
// inverse_bind_matrices[j] maps bind space to world space. The skinned-mesh node's own world
// transform is NOT applied (glTF: "the transform of the skinned mesh node MUST be ignored").
//
// Formula, per vertex with I = influences_per_vertex, joints j_k and weights w_k (k = 0..I−1,
// summed in that order, zero weights included):
//   M  = Σ_k w_k · S[j_k]                      (S: skin matrices, column-major mat4)
//   p' = (M · vec4(p, 1)).xyz
//   N  = Σ_k w_k · mat3(Ninv[j_k])             (Ninv: normal matrices; mat3(M) when none given)
//   n' = normalize(N · n), or (0, 0, 0) when N · n is the zero vector
// GPU buffer layout: joints as uint16 × I per vertex, weights as float × I per vertex, skin and
// normal matrices as column-major mat4 (normal matrices: inverse-transpose in the upper 3×3,
// column 3 = (0, 0, 0, 1), other entries of row 3 zero).
//
//   std::vector<glm::mat4> skin(skin.joints.size()), normal(skin.joints.size());
//   SkinMatricesJob{&skin, world, skin_m, normal_m}.run();
//   SkinningJob job; job.influences_per_vertex = 4; job.skin_matrices = skin_m; ...; job.run();
#include <cstdint>
#include <span>

#include "anim/character.h"
#include "base/result.h"

namespace proxygi::anim {

// Skin matrices (and optionally their inverse-transposes) of one skin from node world matrices.
struct SkinMatricesJob {
  const Skin* skin = nullptr;            // joints (node indices) and inverse bind matrices
  std::span<const glm::mat4> world;      // one per node of the character, world space
  std::span<glm::mat4> skin_matrices;    // out: one per skin joint, bind → world
  std::span<glm::mat4> normal_matrices;  // out, optional (empty = skip): inverse-transpose of
                                         // mat3(skin matrix), embedded in a mat4 as above

  Status validate() const;  // joint node indices < world.size(), span sizes == joint count
  Status run() const;
};

// Which CPU kernel SkinningJob::run uses. `automatic`: AVX2 + FMA when the CPU has both (checked
// at run time; the binary stays portable), else `portable` (GCC vector extensions on the target's
// baseline, SSE2 on x86-64). The two agree up to rounding (FMA, summation order).
enum class SkinningKernel { automatic, portable, avx2_fma };
bool skinning_kernel_available(SkinningKernel kernel);

// Linear blend skinning of one primitive's positions (and optionally normals). No allocation.
struct SkinningJob {
  SkinningKernel kernel = SkinningKernel::automatic;
  int influences_per_vertex = 4;              // I ≥ 1 (any number, not only 4)
  std::span<const glm::mat4> skin_matrices;   // palette: bind → world
  std::span<const glm::mat4> normal_matrices; // optional, same size as the palette. Empty: use
                                              // mat3(skin matrix), exact for rotation + uniform
                                              // scale only (the fast path)
  std::span<const std::uint16_t> joints;      // vertex_count × I palette indices
  std::span<const float> weights;             // vertex_count × I, expected to sum to 1
  std::span<const glm::vec3> positions;       // vertex_count, bind space (after morphing)
  std::span<const glm::vec3> normals;         // empty, or vertex_count, bind space

  std::span<glm::vec3> out_positions;         // vertex_count, world space
  std::span<glm::vec3> out_normals;           // empty iff normals is; world space, unit length

  // Sizes consistent and every joint index < palette size (one pass over `joints`).
  Status validate() const;  // also: the kernel asked for runs on this CPU
  Status run() const;  // validate(), then skin
};

// A mesh on a node without a skin moves rigidly with its node: p' = W · p, n' = normalize(
// inverse-transpose(mat3(W)) · n).
struct RigidTransformJob {
  glm::mat4 world{1.0f};                   // the node's world matrix
  std::span<const glm::vec3> positions;    // mesh-local space
  std::span<const glm::vec3> normals;      // empty, or same size as positions
  std::span<glm::vec3> out_positions;      // world space
  std::span<glm::vec3> out_normals;        // empty iff normals is; unit length

  Status validate() const;
  Status run() const;
};

// Morph targets, applied before skinning: p = p0 + Σ_t w_t · Δp_t, n = n0 + Σ_t w_t · Δn_t
// (normals not renormalized here: skinning and rigid transforms normalize).
struct MorphJob {
  std::span<const MorphTarget> targets;   // a primitive's targets
  std::span<const float> weights;         // one per target
  std::span<const glm::vec3> positions;   // base positions, mesh-local space
  std::span<const glm::vec3> normals;     // empty, or base normals
  std::span<glm::vec3> out_positions;     // same size as positions
  std::span<glm::vec3> out_normals;       // empty iff normals is

  Status validate() const;  // sizes; each target's deltas empty or vertex_count long
  Status run() const;
};

// Inverse-transpose of mat3(m), embedded in a mat4 (see layout above). For singular m the
// cofactor matrix is used instead (same direction up to scale; normals are renormalized).
glm::mat4 normal_matrix(const glm::mat4& m);

}  // namespace proxygi::anim
