#pragma once
// Internal to anim/skinning*.cpp: the SIMD skinning kernels behind SkinningJob::run.
#include "anim/skinning.h"

namespace proxygi::anim::detail {

// True when this CPU runs AVX2 and FMA (checked once, __builtin_cpu_supports).
bool avx2_fma_supported();
// SkinningJob::run's work on an already validated job, AVX2 + FMA (skinning_avx2.cpp); only call
// when avx2_fma_supported().
void skin_avx2_fma(const SkinningJob& job);
// The largest of `joints` (0 when empty); only call when avx2_fma_supported().
std::uint16_t max_joint_avx2(std::span<const std::uint16_t> joints);

}  // namespace proxygi::anim::detail
