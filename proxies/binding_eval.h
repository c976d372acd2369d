#pragma once
// Which binding tracks the skinned surface better: rigid (each sphere follows its dominant bone)
// or blended (each sphere's center is linear-blend-skinned with its mean weights)?
//
// Poke-out of sphere i at frame t: how far the skinned region it stands for leaves it,
//   poke_i(t) = max(0, max_{s in samples(i)} |p_s(t) − c_i(t)| − r_i(t))
// where p_s(t) is surface sample s skinned at t (its triangle's corners skinned by their own
// weights, blended by the sample's barycentrics, which is exactly the skinned surface point) and
// (c_i(t), r_i(t)) the tracked sphere. It is 0 in the bind pose (spheres bound their samples).
// Frames: every clip sampled at k / fps for k = 0 .. ceil(duration × fps) (the last clamped to
// the duration); a character without clips is checked in its rest pose. Morph targets are
// ignored (the fit uses positions as stored).
#include "anim/character.h"
#include "base/result.h"
#include "proxies/fit.h"
#include "proxies/proxy_rig.h"

namespace proxygi::proxies {

struct BindingEvaluation {
  BindingError rigid;
  BindingError blended;
  int frames = 0;
  Binding better = Binding::rigid;  // lower worst poke-out; rigid on ties (it is cheaper)
};

Result<BindingEvaluation> evaluate_bindings(const anim::Character& character, const FitResult& fit, float fps = 30.0f);

}  // namespace proxygi::proxies
