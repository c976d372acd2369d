#pragma once
// Clip sampling: the local (node-space) pose of a character at one time of one clip.
//
//   std::vector<Transform> locals(character.nodes.size());
//   std::vector<float> weights(morph_weight_count(character));
//   SampleClipJob job;
//   job.character = &character; job.clip = &character.clips[0];
//   job.time = 0.5f; job.wrap = WrapMode::loop;
//   job.locals = locals; job.morph_weights = weights;
//   if (Status s = job.run(); !s) { ... s.message() ... }
//
// Rules (glTF 2.0 §3.11, notes/gltf-conformance.md rows 9–14):
// - Every node starts from its rest TRS and every morph weight from its default (node weights,
//   else mesh weights, else 0); channels then overwrite what they animate, so un-animated
//   properties keep rest values.
// - Playback starts at t = 0 whatever the first key time is. Clip time: clamp → [0, duration];
//   loop → t mod duration in [0, duration) (so t = duration samples the clip's start).
// - Per channel, t before the first key or after the last key clamps to that key's value; an
//   exact key time returns that key's value unchanged; one-key channels hold their value.
// - STEP: value of the key at or before t. LINEAR: lerp for T/S/weights, shortest-path slerp
//   for rotations (nlerp when nearly parallel, see blending.h). CUBICSPLINE: Hermite with both tangents scaled
//   by t_d = t[k+1] − t[k]; rotations normalized afterwards.
// - Channels targeting a node that has a fixed matrix are sampled but have no effect (the
//   matrix wins in local_to_model).
#include <span>

#include "anim/character.h"
#include "base/result.h"

namespace proxygi::anim {

enum class WrapMode { clamp, loop };

// Maps clip time to sampling time: clamp to [0, duration] or wrap into [0, duration).
// duration <= 0 gives 0.
float wrap_time(float time, float duration, WrapMode wrap);

// Morph weights of a whole character live in one flat array: node i owns
// morph_weight_count(node i) consecutive floats starting at morph_weight_offset(character, i),
// in node order. A node owns weights when its mesh has morph targets.
int morph_target_count(const Character& character, int node);
int morph_weight_offset(const Character& character, int node);
int morph_weight_count(const Character& character);

// Default morph weights (node weights, else mesh weights, else 0) in the flat layout above.
// `weights` must hold morph_weight_count(character) floats.
void default_morph_weights(const Character& character, std::span<float> weights);

// Rest pose: every node's rest TRS. `locals` must hold one Transform per node.
void rest_pose(const Character& character, std::span<Transform> locals);

// Samples one clip at one time. No allocation in run().
struct SampleClipJob {
  // Inputs.
  const Character* character = nullptr;  // rest TRS, default weights, node count
  const Clip* clip = nullptr;            // usually one of character->clips
  float time = 0.0f;                     // seconds of clip time (wrapped by `wrap`)
  WrapMode wrap = WrapMode::clamp;

  // Outputs (caller-owned).
  std::span<Transform> locals;  // one per node, node-local space (parent space), meters
  // Flat morph weights (layout above). May be empty: weights channels are then skipped. Else it
  // must hold exactly morph_weight_count(*character) floats.
  std::span<float> morph_weights;

  // Checks pointers, span sizes, and every channel: node index in range, components matching
  // the path (3 for T/S, 4 for R, the node's target count for weights), at least one key, and
  // values.size() == keys * components (× 3 for CUBICSPLINE). Key-time monotonicity is the
  // importer's job (it rejects files that break it).
  Status validate() const;
  Status run() const;  // validate(), then sample
};

// Samples one channel at `time` (already wrapped; seconds) into `out` (channel.components
// floats; rotations as x, y, z, w). No validation: callers use SampleClipJob.
void sample_channel(const Channel& channel, float time, std::span<float> out);

}  // namespace proxygi::anim
