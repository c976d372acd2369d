// The AVX2 + FMA skinning kernel against the portable one on the mannequin's vertices: every
// influence count the dispatch specializes (and two it does not), with and without normals and
// normal matrices. They may differ only by rounding (FMA, summation order): positions within
// 1e-6 of the skinned bounding box's diagonal, unit normals within 1e-6.
#include <algorithm>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "anim/mannequin.h"
#include "anim/posed_character.h"
#include "anim/skinning.h"

namespace proxygi::anim {
namespace {

struct Case {
  std::vector<glm::vec3> positions, normals;
  std::vector<std::uint16_t> joints;
  std::vector<float> weights;
  std::vector<glm::mat4> palette, normal_palette;
};

// The mannequin's bind vertices with `influences` random joints and weights (summing to 1) per
// vertex, skinned by a walk pose whose matrices also carry a non-uniform scale (so normal
// matrices differ from mat3 of the skin matrices).
Case make_case(int influences, unsigned seed) {
  const Character character = build_mannequin();
  Case c;
  for (const Primitive& p : character.meshes[0].primitives) {
    c.positions.insert(c.positions.end(), p.positions.begin(), p.positions.end());
    c.normals.insert(c.normals.end(), p.normals.begin(), p.normals.end());
  }
  PoseBuffers pose;
  EXPECT_TRUE(evaluate_pose(character, 0, 0.37f, WrapMode::loop, pose).ok());
  c.palette = pose.skin_matrices[0];
  std::mt19937 random(seed);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  for (glm::mat4& m : c.palette) m = m * glm::mat4(glm::vec4(1.0f + 0.3f * unit(random), 0, 0, 0),
                                                   glm::vec4(0, 1.0f, 0, 0), glm::vec4(0, 0, 0.8f, 0),
                                                   glm::vec4(0, 0, 0, 1));
  for (const glm::mat4& m : c.palette) c.normal_palette.push_back(normal_matrix(m));
  std::uniform_int_distribution<int> joint(0, int(c.palette.size()) - 1);
  for (std::size_t v = 0; v < c.positions.size(); ++v) {
    float sum = 0.0f;
    const std::size_t first = c.weights.size();
    for (int k = 0; k < influences; ++k) {
      c.joints.push_back(std::uint16_t(joint(random)));
      c.weights.push_back(k == 0 || unit(random) < 0.7f ? unit(random) : 0.0f);  // some zero weights
      sum += c.weights.back();
    }
    for (std::size_t k = first; k < c.weights.size(); ++k) c.weights[k] = sum > 0.0f ? c.weights[k] / sum : 1.0f;
  }
  c.normals[5] = glm::vec3(0.0f);  // a zero normal stays zero in both kernels
  return c;
}

struct Output {
  std::vector<glm::vec3> positions, normals;
};

Output run(const Case& c, int influences, SkinningKernel kernel, int mode) {
  Output out;
  out.positions.resize(c.positions.size());
  SkinningJob job;
  job.kernel = kernel;
  job.influences_per_vertex = influences;
  job.skin_matrices = c.palette;
  job.joints = c.joints;
  job.weights = c.weights;
  job.positions = c.positions;
  job.out_positions = out.positions;
  if (mode > 0) {
    out.normals.resize(c.normals.size());
    job.normals = c.normals;
    job.out_normals = out.normals;
  }
  if (mode == 2) job.normal_matrices = c.normal_palette;
  EXPECT_TRUE(job.run().ok());
  return out;
}

TEST(SkinningKernels, Avx2EqualsPortableWithinRounding) {
  if (!skinning_kernel_available(SkinningKernel::avx2_fma)) GTEST_SKIP() << "no AVX2 + FMA on this CPU";
  for (int influences : {1, 2, 3, 4, 5, 8}) {
    const Case c = make_case(influences, 17u + unsigned(influences));
    for (int mode : {0, 1, 2}) {
      SCOPED_TRACE("influences " + std::to_string(influences) + ", mode " + std::to_string(mode));
      const Output portable = run(c, influences, SkinningKernel::portable, mode);
      const Output avx2 = run(c, influences, SkinningKernel::avx2_fma, mode);
      glm::vec3 low(1e30f), high(-1e30f);
      for (const glm::vec3& p : portable.positions) low = glm::min(low, p), high = glm::max(high, p);
      const float tolerance = 1e-6f * glm::length(high - low);
      float position_error = 0.0f, normal_error = 0.0f;
      for (std::size_t v = 0; v < c.positions.size(); ++v)
        position_error = std::max(position_error, glm::length(portable.positions[v] - avx2.positions[v]));
      for (std::size_t v = 0; v < portable.normals.size(); ++v)
        normal_error = std::max(normal_error, glm::length(portable.normals[v] - avx2.normals[v]));
      EXPECT_LE(position_error, tolerance);
      EXPECT_LE(normal_error, 1e-6f);
      if (mode > 0) {
        EXPECT_EQ(avx2.normals[5], glm::vec3(0.0f));
      }
    }
  }
}

// The range check scans the joints 16 at a time with AVX2: an index out of range anywhere (in a
// full block or the tail) is still found, by every kernel.
TEST(SkinningKernels, JointRangeCheckSeesEveryIndex) {
  Case c = make_case(4, 5u);
  for (std::size_t at : {std::size_t(0), std::size_t(17), c.joints.size() / 2, c.joints.size() - 1}) {
    Case broken = c;
    broken.joints[at] = std::uint16_t(broken.palette.size());
    for (SkinningKernel kernel : {SkinningKernel::automatic, SkinningKernel::portable}) {
      std::vector<glm::vec3> out(broken.positions.size());
      SkinningJob job;
      job.kernel = kernel;
      job.skin_matrices = broken.palette;
      job.joints = broken.joints;
      job.weights = broken.weights;
      job.positions = broken.positions;
      job.out_positions = out;
      EXPECT_FALSE(job.validate().ok()) << "joint slot " << at;
    }
  }
}

TEST(SkinningKernels, AutomaticPicksAnAvailableKernel) {
  EXPECT_TRUE(skinning_kernel_available(SkinningKernel::automatic));
  EXPECT_TRUE(skinning_kernel_available(SkinningKernel::portable));
}

}  // namespace
}  // namespace proxygi::anim
