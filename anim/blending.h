#pragma once
// Blending two sampled local poses by a weight: out = (1 − weight) · a + weight · b per node.
// Translation and scale are lerped; rotations use shortest-path slerp (sign of b flipped when
// dot(a, b) < 0), falling back to normalized lerp when dot(a, b) > 0.99999 (nearly parallel). Morph
// weights are lerped. weight = 0 returns a exactly, weight = 1 returns b (sign-corrected).
//
//   BlendJob job;
//   job.a = walk_locals; job.b = run_locals; job.weight = 0.3f; job.output = blended;
//   job.run();
#include <span>

#include "anim/character.h"
#include "base/result.h"

namespace proxygi::anim {

struct BlendJob {
  // Inputs: two local poses of the same character (node-local space), same sizes.
  std::span<const Transform> a;
  std::span<const Transform> b;
  std::span<const float> morph_a;  // may be empty (then morph_b and morph_output must be too)
  std::span<const float> morph_b;
  float weight = 0.0f;  // in [0, 1]; 0 → a, 1 → b

  // Outputs (caller-owned; may alias a or b).
  std::span<Transform> output;
  std::span<float> morph_output;

  Status validate() const;  // sizes match, weight finite and in [0, 1]
  Status run() const;
};

// Shortest-path slerp of unit quaternions, nlerp when nearly parallel. Result is unit length.
glm::quat slerp_shortest(const glm::quat& a, const glm::quat& b, float u);

}  // namespace proxygi::anim
