// The AVX2 + FMA skinning kernel (anim/skinning_kernels.h). Compiled with per-function target
// attributes, not file-wide -mavx2, so no inline function of a shared header is emitted here with
// AVX2 code and the binary stays portable; SkinningJob::run calls it only when the CPU has both.
//
// Per vertex the blended matrix M's columns are held as two 8-float registers, [c0|c1] and
// [c2|c3], each influence adding w·S[j] with two FMAs (the portable kernel needs four multiplies
// and four adds); p' = c0·x + c1·y + c2·z + c3 is one multiply, one FMA and one 128-bit add of the
// halves; normals are normalized in the same loop. Results equal the portable kernel's up to
// rounding (FMA and summation order; tested within 1e-6 of the bounding-box diagonal).
#include "anim/skinning_kernels.h"

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>

#include <cstring>

#define PROXYGI_AVX2 __attribute__((target("avx2,fma")))

namespace proxygi::anim::detail {
namespace {

// Four floats from p[0..2] (lane 3 = p[3] when `kWide`, else 0). kWide reads one float past the
// vertex: only used when another vertex follows in the same array.
template <bool kWide>
PROXYGI_AVX2 inline __m128 load3(const float* p) {
  if constexpr (kWide) {
    return _mm_loadu_ps(p);
  } else {
    __m128 xy = _mm_castpd_ps(_mm_load_sd(reinterpret_cast<const double*>(p)));
    return _mm_movelh_ps(xy, _mm_load_ss(p + 2));
  }
}

// Writes x, y, z; kWide also writes lane 3 over the next vertex's x, which is written later.
template <bool kWide>
PROXYGI_AVX2 inline void store3(float* out, __m128 v) {
  if constexpr (kWide) {
    _mm_storeu_ps(out, v);
  } else {
    _mm_store_sd(reinterpret_cast<double*>(out), _mm_castps_pd(v));
    _mm_store_ss(out + 2, _mm_movehl_ps(v, v));
  }
}

// xyz / |xyz|, or zero for the zero vector (as the portable kernel). 1/sqrt by the hardware
// estimate and one Newton step (relative error about 1e-7, within the kernels' tolerance),
// cheaper than a square root and a divide per vertex.
PROXYGI_AVX2 inline __m128 normalize3(__m128 n) {
  const __m128 sq = _mm_mul_ps(n, n);
  const __m128 length2 = _mm_add_ps(_mm_add_ps(sq, _mm_shuffle_ps(sq, sq, _MM_SHUFFLE(3, 0, 2, 1))),
                                    _mm_shuffle_ps(sq, sq, _MM_SHUFFLE(3, 1, 0, 2)));
  const __m128 positive = _mm_cmpgt_ps(length2, _mm_setzero_ps());
  const __m128 estimate = _mm_rsqrt_ps(length2);
  const __m128 half_l2 = _mm_mul_ps(_mm_set1_ps(0.5f), length2);
  const __m128 scale =
      _mm_mul_ps(estimate, _mm_fnmadd_ps(half_l2, _mm_mul_ps(estimate, estimate), _mm_set1_ps(1.5f)));
  return _mm_mul_ps(n, _mm_and_ps(scale, positive));
}

PROXYGI_AVX2 inline __m256 halves(__m128 lo, __m128 hi) { return _mm256_insertf128_ps(_mm256_castps128_ps256(lo), hi, 1); }

PROXYGI_AVX2 inline __m128 sum_halves(__m256 v) {
  return _mm_add_ps(_mm256_castps256_ps128(v), _mm256_extractf128_ps(v, 1));
}

template <int kInfluences, bool kNormals, bool kNormalMatrices, bool kWide>
PROXYGI_AVX2 inline void skin_one(const SkinningJob& job, std::size_t influences, std::size_t v) {
  const float* const palette = reinterpret_cast<const float*>(job.skin_matrices.data());
  const float* const normal_palette = reinterpret_cast<const float*>(job.normal_matrices.data());
  const std::uint16_t* j = job.joints.data() + v * influences;
  const float* w = job.weights.data() + v * influences;
  __m256 c01, c23, n01;
  __m128 n2;
  {
    const float* m = palette + 16u * j[0];
    const __m256 wk = _mm256_broadcast_ss(w);
    c01 = _mm256_mul_ps(wk, _mm256_loadu_ps(m));
    c23 = _mm256_mul_ps(wk, _mm256_loadu_ps(m + 8));
    if constexpr (kNormalMatrices) {
      const float* nm = normal_palette + 16u * j[0];
      n01 = _mm256_mul_ps(wk, _mm256_loadu_ps(nm));
      n2 = _mm_mul_ps(_mm256_castps256_ps128(wk), _mm_loadu_ps(nm + 8));
    }
  }
  for (std::size_t k = 1; k < influences; ++k) {
    const float* m = palette + 16u * j[k];
    const __m256 wk = _mm256_broadcast_ss(w + k);
    c01 = _mm256_fmadd_ps(wk, _mm256_loadu_ps(m), c01);
    c23 = _mm256_fmadd_ps(wk, _mm256_loadu_ps(m + 8), c23);
    if constexpr (kNormalMatrices) {
      const float* nm = normal_palette + 16u * j[k];
      n01 = _mm256_fmadd_ps(wk, _mm256_loadu_ps(nm), n01);
      n2 = _mm_fmadd_ps(_mm256_castps256_ps128(wk), _mm_loadu_ps(nm + 8), n2);
    }
  }
  const float* p = reinterpret_cast<const float*>(job.positions.data()) + 3 * v;
  const __m128 p4 = load3<kWide>(p);
  const __m256 xy = halves(_mm_shuffle_ps(p4, p4, _MM_SHUFFLE(0, 0, 0, 0)), _mm_shuffle_ps(p4, p4, _MM_SHUFFLE(1, 1, 1, 1)));
  const __m256 z1 = halves(_mm_shuffle_ps(p4, p4, _MM_SHUFFLE(2, 2, 2, 2)), _mm_set1_ps(1.0f));
  const __m256 position = _mm256_fmadd_ps(c01, xy, _mm256_mul_ps(c23, z1));  // [c0 x + c2 z | c1 y + c3]
  store3<kWide>(reinterpret_cast<float*>(job.out_positions.data()) + 3 * v, sum_halves(position));
  if constexpr (kNormals) {
    const float* n = reinterpret_cast<const float*>(job.normals.data()) + 3 * v;
    const __m128 n4 = load3<kWide>(n);
    const __m256 nxy = halves(_mm_shuffle_ps(n4, n4, _MM_SHUFFLE(0, 0, 0, 0)), _mm_shuffle_ps(n4, n4, _MM_SHUFFLE(1, 1, 1, 1)));
    const __m128 nz = _mm_shuffle_ps(n4, n4, _MM_SHUFFLE(2, 2, 2, 2));
    __m128 normal;
    if constexpr (kNormalMatrices) {
      normal = _mm_fmadd_ps(n2, nz, sum_halves(_mm256_mul_ps(n01, nxy)));
    } else {
      normal = _mm_fmadd_ps(_mm256_castps256_ps128(c23), nz, sum_halves(_mm256_mul_ps(c01, nxy)));
    }
    store3<kWide>(reinterpret_cast<float*>(job.out_normals.data()) + 3 * v, normalize3(normal));
  }
}

template <int kInfluences, bool kNormals, bool kNormalMatrices>
PROXYGI_AVX2 void skin_vertices(const SkinningJob& job) {
  const std::size_t influences = static_cast<std::size_t>(kInfluences > 0 ? kInfluences : job.influences_per_vertex);
  const std::size_t count = job.positions.size();
  if (count == 0) return;
  for (std::size_t v = 0; v + 1 < count; ++v) skin_one<kInfluences, kNormals, kNormalMatrices, true>(job, influences, v);
  skin_one<kInfluences, kNormals, kNormalMatrices, false>(job, influences, count - 1);
}

template <int kInfluences>
void dispatch_normals(const SkinningJob& job) {
  if (job.normals.empty()) return skin_vertices<kInfluences, false, false>(job);
  if (job.normal_matrices.empty()) return skin_vertices<kInfluences, true, false>(job);
  skin_vertices<kInfluences, true, true>(job);
}

}  // namespace

// The largest joint index (SkinningJob::validate's range check), 16 lanes at a time.
PROXYGI_AVX2 std::uint16_t max_joint_avx2(std::span<const std::uint16_t> joints) {
  __m256i best = _mm256_setzero_si256();
  std::size_t i = 0;
  for (; i + 16 <= joints.size(); i += 16)
    best = _mm256_max_epu16(best, _mm256_loadu_si256(reinterpret_cast<const __m256i*>(joints.data() + i)));
  alignas(32) std::uint16_t lanes[16];
  _mm256_store_si256(reinterpret_cast<__m256i*>(lanes), best);
  std::uint16_t result = 0;
  for (std::uint16_t lane : lanes) result = lane > result ? lane : result;
  for (; i < joints.size(); ++i) result = joints[i] > result ? joints[i] : result;
  return result;
}

bool avx2_fma_supported() {
  static const bool supported = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
  return supported;
}

void skin_avx2_fma(const SkinningJob& job) {
  switch (job.influences_per_vertex) {
    case 1: dispatch_normals<1>(job); break;
    case 2: dispatch_normals<2>(job); break;
    case 4: dispatch_normals<4>(job); break;
    case 8: dispatch_normals<8>(job); break;
    default: dispatch_normals<0>(job); break;
  }
}

}  // namespace proxygi::anim::detail

#else  // not x86: no AVX2 kernel

namespace proxygi::anim::detail {
std::uint16_t max_joint_avx2(std::span<const std::uint16_t>) { return 0; }
bool avx2_fma_supported() { return false; }
void skin_avx2_fma(const SkinningJob&) {}
}  // namespace proxygi::anim::detail

#endif
