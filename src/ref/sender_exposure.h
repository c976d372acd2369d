#pragma once
// Sender exposure (render.indirect_method vsgl): per vertex of a character, the fraction of its
// diffuse (cosine-weighted) emission that leaves the character, i.e. is not blocked by the
// character's own surfaces. vsgl_lights.comp (and its CPU twin sh::triangle_light) scales each
// triangle's VPL flux by the mean of its three vertices' exposures, so a triangle buried inside
// another closed body part (the mannequin's capsules overlap at every joint: 31 % of its VPL flux,
// tests/study/bounce_excess_mannequin_test.cpp) sends nothing, and a crease sends its open part.
//
//   exposure(v) = (1/K) Σ_k [the ray from p_v + ε N_v along d_k hits no triangle of the character]
//
// d_k: K cosine-weighted directions about the vertex normal N_v (Owen-scrambled Sobol points keyed
// by the vertex index: deterministic, independent of threads); ε = 1e-4 × the character's bounding
// box diagonal (at least 1e-6 m). A vertex whose hemisphere is open (any convex closed mesh with
// normals in its vertices' normal cones) gets exactly 1, one enclosed by a closed surface exactly 0.
// Computed once per model in its rest pose (clip −1: buried parts stay buried as it moves), on
// first need (a renderer with indirect_method vsgl), and kept by the renderer beside the model's
// other shared buffers (SceneRenderer::ensure_sender_exposure, gpu/scene_meshes.cpp). No visibility toward
// any receiver: the VPLs still shine through the body where they are exposed.
//
// Units: dimensionless in [0, 1]. Conventions: vertex order of each primitive as stored (the same
// vertices the skin pass writes).
#include <cstdint>
#include <span>
#include <vector>

#include "anim/character.h"
#include "anim/posed_character.h"
#include "base/result.h"

namespace proxygi::ref {

inline constexpr int kSenderExposureDirections = 64;  // K of the renderer's exposures
inline constexpr int kMinSenderExposureDirections = 1;
inline constexpr int kMaxSenderExposureDirections = 65536;

struct SenderExposureJob {
  // The character's primitives in one pose (one space: world or model), all of them the occluders.
  std::span<const anim::PosedPrimitive> primitives;
  int directions = kSenderExposureDirections;  // K
  std::uint32_t seed = 1;
  // Out: one vector per primitive, one exposure per vertex (resized by run). A primitive without
  // normals gets 1 everywhere (no hemisphere to test).
  std::vector<std::vector<float>>* exposure = nullptr;

  // K in range, an output, indices in range ("primitive 2: index 9 out of range (8 vertices)"),
  // normals empty or one per position, finite positions.
  Status validate() const;
  Status run() const;  // validate(), then trace (Embree, all hardware threads)
};

// The exposures of a model's primitives in its rest pose, in anim::pose_meshes order.
Result<std::vector<std::vector<float>>> rest_pose_sender_exposure(const anim::Character& character,
                                                                  int directions = kSenderExposureDirections);

}  // namespace proxygi::ref
