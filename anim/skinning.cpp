#include "anim/skinning.h"

#include "anim/skinning_kernels.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>

namespace proxygi::anim {
namespace {

// Four floats in one SSE2/NEON register (GCC/Clang vector extension, no ISA flags needed).
typedef float f4 __attribute__((vector_size(16)));

inline f4 load4(const float* p) {
  f4 v;
  std::memcpy(&v, p, sizeof v);
  return v;
}

inline f4 splat(float x) { return f4{x, x, x, x}; }

typedef float f2 __attribute__((vector_size(8)));

// Writes x, y, z as one 8-byte and one 4-byte store (no trip through the stack).
inline void store3(float* out, f4 v) {
  const f2 xy = {v[0], v[1]};
  std::memcpy(out, &xy, sizeof xy);
  out[2] = v[2];
}

inline f4 sqrt4(f4 x) {
#if defined(__SSE__)
  return __builtin_ia32_sqrtps(x);
#else
  return f4{std::sqrt(x[0]), std::sqrt(x[1]), std::sqrt(x[2]), std::sqrt(x[3])};
#endif
}

// Normalizes n[0..count) (xyz triples) in place, four at a time: one vector sqrt and divide per
// four normals. Zero vectors stay zero.
void normalize_all(float* n, std::size_t count) {
  const f4 zero = {0.0f, 0.0f, 0.0f, 0.0f};
  std::size_t v = 0;
  for (; v + 4 <= count; v += 4) {
    float* q = n + 3 * v;
    const f4 length2 = {q[0] * q[0] + q[1] * q[1] + q[2] * q[2], q[3] * q[3] + q[4] * q[4] + q[5] * q[5],
                        q[6] * q[6] + q[7] * q[7] + q[8] * q[8], q[9] * q[9] + q[10] * q[10] + q[11] * q[11]};
    const f4 scale = length2 > zero ? splat(1.0f) / sqrt4(length2) : zero;
    for (int i = 0; i < 12; ++i) q[i] *= scale[i / 3];
  }
  for (; v < count; ++v) {
    float* q = n + 3 * v;
    const float length2 = q[0] * q[0] + q[1] * q[1] + q[2] * q[2];
    const float scale = length2 > 0.0f ? 1.0f / std::sqrt(length2) : 0.0f;
    for (int i = 0; i < 3; ++i) q[i] *= scale;
  }
}

// The skinning loop, specialized on the influence count (0 = runtime count) and on which
// normal path runs. Columns of the blended matrix M are accumulated as four f4 registers; the
// first influence initializes them (0 + w·S == w·S, so this equals the documented sum).
// Normals are stored unnormalized, then normalized in a second pass over the cache-hot output.
template <int kInfluences, bool kNormals, bool kNormalMatrices>
void skin_vertices(const SkinningJob& job) {
  const std::size_t influences = static_cast<std::size_t>(kInfluences > 0 ? kInfluences : job.influences_per_vertex);
  const float* const palette = reinterpret_cast<const float*>(job.skin_matrices.data());
  const float* const normal_palette = reinterpret_cast<const float*>(job.normal_matrices.data());
  const std::uint16_t* const joints = job.joints.data();
  const float* const weights = job.weights.data();
  const float* const positions = reinterpret_cast<const float*>(job.positions.data());
  const float* const normals = reinterpret_cast<const float*>(job.normals.data());
  float* const out_positions = reinterpret_cast<float*>(job.out_positions.data());
  float* const out_normals = reinterpret_cast<float*>(job.out_normals.data());
  const std::size_t count = job.positions.size();

  for (std::size_t v = 0; v < count; ++v) {
    const std::uint16_t* j = joints + v * influences;
    const float* w = weights + v * influences;
    f4 c0, c1, c2, c3, n0, n1, n2;
    {
      const float* m = palette + 16u * j[0];
      const f4 wk = splat(w[0]);
      c0 = wk * load4(m);
      c1 = wk * load4(m + 4);
      c2 = wk * load4(m + 8);
      c3 = wk * load4(m + 12);
      if constexpr (kNormalMatrices) {
        const float* nm = normal_palette + 16u * j[0];
        n0 = wk * load4(nm);
        n1 = wk * load4(nm + 4);
        n2 = wk * load4(nm + 8);
      }
    }
    for (std::size_t k = 1; k < influences; ++k) {
      const float* m = palette + 16u * j[k];
      const f4 wk = splat(w[k]);
      c0 += wk * load4(m);
      c1 += wk * load4(m + 4);
      c2 += wk * load4(m + 8);
      c3 += wk * load4(m + 12);
      if constexpr (kNormalMatrices) {
        const float* nm = normal_palette + 16u * j[k];
        n0 += wk * load4(nm);
        n1 += wk * load4(nm + 4);
        n2 += wk * load4(nm + 8);
      }
    }
    const float* p = positions + 3 * v;
    store3(out_positions + 3 * v, c0 * splat(p[0]) + c1 * splat(p[1]) + c2 * splat(p[2]) + c3);
    if constexpr (kNormals) {
      const float* n = normals + 3 * v;
      if constexpr (kNormalMatrices) {
        store3(out_normals + 3 * v, n0 * splat(n[0]) + n1 * splat(n[1]) + n2 * splat(n[2]));
      } else {
        store3(out_normals + 3 * v, c0 * splat(n[0]) + c1 * splat(n[1]) + c2 * splat(n[2]));
      }
    }
  }
  if constexpr (kNormals) normalize_all(out_normals, count);
}

template <int kInfluences>
void skin_dispatch_normals(const SkinningJob& job) {
  if (job.normals.empty()) return skin_vertices<kInfluences, false, false>(job);
  if (job.normal_matrices.empty()) return skin_vertices<kInfluences, true, false>(job);
  skin_vertices<kInfluences, true, true>(job);
}

// `simd`: the AVX2 scan when the CPU has it (the portable kernel keeps the scalar scan, so
// `bench micro` times it as before).
std::uint16_t max_joint(std::span<const std::uint16_t> joints, bool simd) {
  if (simd && detail::avx2_fma_supported()) return detail::max_joint_avx2(joints);
  std::uint16_t result = 0;
  for (const std::uint16_t joint : joints) result = std::max(result, joint);
  return result;
}

}  // namespace

glm::mat4 normal_matrix(const glm::mat4& m) {
  const glm::mat3 linear(m);
  const float determinant = glm::determinant(linear);
  glm::mat3 normal;
  if (std::fabs(determinant) > 1e-20f) {
    normal = glm::transpose(glm::inverse(linear));
  } else {  // singular: cofactor matrix, columns = cross products of the other two columns
    normal = glm::mat3(glm::cross(linear[1], linear[2]), glm::cross(linear[2], linear[0]),
                       glm::cross(linear[0], linear[1]));
  }
  return glm::mat4(normal);  // upper 3×3 = normal, column 3 = (0, 0, 0, 1), row 3 zero
}

Status SkinMatricesJob::validate() const {
  if (skin == nullptr) return make_error("skin matrices: skin is required");
  const std::size_t count = skin->joints.size();
  if (skin->inverse_bind_matrices.size() != count) {
    return make_error("skin '" + skin->name + "': " + std::to_string(skin->inverse_bind_matrices.size()) +
                      " inverse bind matrices for " + std::to_string(count) + " joints");
  }
  if (skin_matrices.size() != count || (!normal_matrices.empty() && normal_matrices.size() != count)) {
    return make_error("skin '" + skin->name + "': output spans must hold " + std::to_string(count) + " matrices");
  }
  for (std::size_t j = 0; j < count; ++j) {
    if (skin->joints[j] < 0 || static_cast<std::size_t>(skin->joints[j]) >= world.size()) {
      return make_error("skin '" + skin->name + "': joint " + std::to_string(j) + " is node " +
                        std::to_string(skin->joints[j]) + ", out of range (" + std::to_string(world.size()) + " nodes)");
    }
  }
  return {};
}

Status SkinMatricesJob::run() const {
  if (Status status = validate(); !status) return status;
  for (std::size_t j = 0; j < skin->joints.size(); ++j) {
    skin_matrices[j] = world[static_cast<std::size_t>(skin->joints[j])] * skin->inverse_bind_matrices[j];
    if (!normal_matrices.empty()) normal_matrices[j] = normal_matrix(skin_matrices[j]);
  }
  return {};
}

bool skinning_kernel_available(SkinningKernel kernel) {
  return kernel != SkinningKernel::avx2_fma || detail::avx2_fma_supported();
}

Status SkinningJob::validate() const {
  if (!skinning_kernel_available(kernel)) return make_error("skinning: the AVX2 + FMA kernel does not run on this CPU");
  if (influences_per_vertex < 1) return make_error("skinning: influences_per_vertex must be >= 1");
  const std::size_t count = positions.size();
  const std::size_t slots = count * static_cast<std::size_t>(influences_per_vertex);
  if (joints.size() != slots || weights.size() != slots) {
    return make_error("skinning: " + std::to_string(count) + " vertices × " + std::to_string(influences_per_vertex) +
                      " influences need " + std::to_string(slots) + " joints and weights, got " +
                      std::to_string(joints.size()) + " and " + std::to_string(weights.size()));
  }
  if (out_positions.size() != count) return make_error("skinning: out_positions must hold every vertex");
  if (normals.size() != (normals.empty() ? 0 : count) || out_normals.size() != normals.size()) {
    return make_error("skinning: normals and out_normals must both be empty or hold every vertex");
  }
  if (skin_matrices.empty()) return make_error("skinning: empty skin matrix palette");
  if (!normal_matrices.empty() && normal_matrices.size() != skin_matrices.size()) {
    return make_error("skinning: normal_matrices must be empty or as long as skin_matrices");
  }
  const bool simd = kernel != SkinningKernel::portable;
  if (count > 0 && max_joint(joints, simd) >= skin_matrices.size()) {
    return make_error("skinning: joint index " + std::to_string(max_joint(joints, simd)) + " out of range (" +
                      std::to_string(skin_matrices.size()) + " skin matrices)");
  }
  return {};
}

Status SkinningJob::run() const {
  if (Status status = validate(); !status) return status;
  if (kernel == SkinningKernel::avx2_fma || (kernel == SkinningKernel::automatic && detail::avx2_fma_supported())) {
    detail::skin_avx2_fma(*this);
    return {};
  }
  switch (influences_per_vertex) {
    case 1: skin_dispatch_normals<1>(*this); break;
    case 2: skin_dispatch_normals<2>(*this); break;
    case 4: skin_dispatch_normals<4>(*this); break;
    case 8: skin_dispatch_normals<8>(*this); break;
    default: skin_dispatch_normals<0>(*this); break;
  }
  return {};
}

Status RigidTransformJob::validate() const {
  if (out_positions.size() != positions.size()) return make_error("rigid transform: out_positions size mismatch");
  if ((!normals.empty() && normals.size() != positions.size()) || out_normals.size() != normals.size()) {
    return make_error("rigid transform: normals and out_normals must both be empty or hold every vertex");
  }
  return {};
}

Status RigidTransformJob::run() const {
  if (Status status = validate(); !status) return status;
  for (std::size_t v = 0; v < positions.size(); ++v) out_positions[v] = glm::vec3(world * glm::vec4(positions[v], 1.0f));
  if (normals.empty()) return {};
  const glm::mat3 normal(normal_matrix(world));
  for (std::size_t v = 0; v < normals.size(); ++v) {
    const glm::vec3 n = normal * normals[v];
    const float length2 = glm::dot(n, n);
    out_normals[v] = length2 > 0.0f ? n / std::sqrt(length2) : glm::vec3(0.0f);
  }
  return {};
}

Status MorphJob::validate() const {
  const std::size_t count = positions.size();
  if (weights.size() != targets.size()) {
    return make_error("morph: " + std::to_string(weights.size()) + " weights for " + std::to_string(targets.size()) +
                      " targets");
  }
  if (out_positions.size() != count) return make_error("morph: out_positions size mismatch");
  if ((!normals.empty() && normals.size() != count) || out_normals.size() != normals.size()) {
    return make_error("morph: normals and out_normals must both be empty or hold every vertex");
  }
  for (std::size_t t = 0; t < targets.size(); ++t) {
    const MorphTarget& target = targets[t];
    if ((!target.position_deltas.empty() && target.position_deltas.size() != count) ||
        (!target.normal_deltas.empty() && target.normal_deltas.size() != count)) {
      return make_error("morph: target " + std::to_string(t) + " delta count differs from the vertex count " +
                        std::to_string(count));
    }
  }
  return {};
}

Status MorphJob::run() const {
  if (Status status = validate(); !status) return status;
  std::copy(positions.begin(), positions.end(), out_positions.begin());
  std::copy(normals.begin(), normals.end(), out_normals.begin());
  for (std::size_t t = 0; t < targets.size(); ++t) {
    const float w = weights[t];
    if (w == 0.0f) continue;
    const MorphTarget& target = targets[t];
    for (std::size_t v = 0; v < target.position_deltas.size(); ++v) out_positions[v] += w * target.position_deltas[v];
    if (out_normals.empty()) continue;
    for (std::size_t v = 0; v < target.normal_deltas.size(); ++v) out_normals[v] += w * target.normal_deltas[v];
  }
  return {};
}

}  // namespace proxygi::anim
