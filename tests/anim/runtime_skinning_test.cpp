// Skinning against hand-computed values: blended matrices, > 4 influences, normal matrices
// (inverse-transpose), rigid meshes, morph targets, skin matrices, and job validity.
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "anim/skinning.h"

namespace proxygi::anim {
namespace {

glm::mat4 translation(float x, float y, float z) {
  glm::mat4 m(1.0f);
  m[3] = glm::vec4(x, y, z, 1.0f);
  return m;
}

// 90° about +Z with exact 0/1 entries: x → y, y → −x.
glm::mat4 quarter_turn_z() {
  glm::mat4 m(0.0f);
  m[0] = glm::vec4(0, 1, 0, 0);
  m[1] = glm::vec4(-1, 0, 0, 0);
  m[2] = glm::vec4(0, 0, 1, 0);
  m[3] = glm::vec4(0, 0, 0, 1);
  return m;
}

struct Skinned {
  std::vector<glm::vec3> positions, normals;
};

Skinned skin(int influences, std::vector<glm::mat4> palette, std::vector<std::uint16_t> joints,
             std::vector<float> weights, std::vector<glm::vec3> positions, std::vector<glm::vec3> normals,
             std::vector<glm::mat4> normal_palette = {}) {
  Skinned out;
  out.positions.resize(positions.size());
  out.normals.resize(normals.size());
  SkinningJob job;
  job.influences_per_vertex = influences;
  job.skin_matrices = palette;
  job.normal_matrices = normal_palette;
  job.joints = joints;
  job.weights = weights;
  job.positions = positions;
  job.normals = normals;
  job.out_positions = out.positions;
  job.out_normals = out.normals;
  const Status status = job.run();
  EXPECT_TRUE(status.ok()) << (status ? "" : status.message());
  return out;
}

TEST(Skinning, BlendsMatricesByWeight) {
  // M = 0.5 · T(1, 0, 0) + 0.5 · Rz(90°); p = (1, 0, 0): 0.5 · (2, 0, 0) + 0.5 · (0, 1, 0).
  const Skinned out = skin(4, {translation(1, 0, 0), quarter_turn_z()}, {0, 1, 0, 0}, {0.5f, 0.5f, 0.0f, 0.0f},
                           {{1, 0, 0}}, {{1, 0, 0}});
  EXPECT_EQ(out.positions[0], glm::vec3(1.0f, 0.5f, 0.0f));
  // Normal: (0.5 · I + 0.5 · Rz) · (1, 0, 0) = (0.5, 0.5, 0), normalized.
  EXPECT_NEAR(out.normals[0].x, std::sqrt(0.5f), 1e-7f);
  EXPECT_NEAR(out.normals[0].y, std::sqrt(0.5f), 1e-7f);
  EXPECT_EQ(out.normals[0].z, 0.0f);
}

TEST(Skinning, AnyInfluenceCountIncludingMoreThanFour) {
  std::vector<glm::mat4> palette = {translation(1, 0, 0), translation(0, 2, 0), translation(0, 0, 4),
                                    translation(8, 0, 0), translation(0, 16, 0), translation(0, 0, 32)};
  const std::vector<float> w = {0.5f, 0.25f, 0.125f, 0.0625f, 0.03125f, 0.03125f};
  const glm::vec3 expected(0.5f * 1 + 0.0625f * 8, 0.25f * 2 + 0.03125f * 16, 0.125f * 4 + 0.03125f * 32);
  for (const int influences : {6, 8}) {  // 8: two zero-weight slots pointing at joint 0
    std::vector<std::uint16_t> joints = {0, 1, 2, 3, 4, 5};
    std::vector<float> weights = w;
    joints.resize(static_cast<std::size_t>(influences), 0);
    weights.resize(static_cast<std::size_t>(influences), 0.0f);
    const Skinned out = skin(influences, palette, joints, weights, {{0, 0, 0}}, {});
    EXPECT_EQ(out.positions[0], expected) << influences << " influences";
  }
  // Three influences: generic path, two vertices.
  const Skinned three = skin(3, palette, {0, 1, 2, 5, 4, 3}, {0.5f, 0.25f, 0.25f, 0.5f, 0.25f, 0.25f},
                             {{1, 1, 1}, {0, 0, 0}}, {});
  EXPECT_EQ(three.positions[0], glm::vec3(1.5f, 1.5f, 2.0f));
  EXPECT_EQ(three.positions[1], glm::vec3(2.0f, 4.0f, 16.0f));
  // One influence.
  const Skinned one = skin(1, palette, {3}, {1.0f}, {{1, 2, 3}}, {});
  EXPECT_EQ(one.positions[0], glm::vec3(9, 2, 3));
}

TEST(Skinning, NormalMatrixIsTheInverseTranspose) {
  glm::mat4 stretch(1.0f);
  stretch[0][0] = 2.0f;  // scale x by 2
  const glm::mat4 n = normal_matrix(stretch * translation(3, 4, 5));
  EXPECT_EQ(n[0], glm::vec4(0.5f, 0, 0, 0));
  EXPECT_EQ(n[1], glm::vec4(0, 1, 0, 0));
  EXPECT_EQ(n[2], glm::vec4(0, 0, 1, 0));
  EXPECT_EQ(n[3], glm::vec4(0, 0, 0, 1));
  EXPECT_EQ(normal_matrix(quarter_turn_z()), quarter_turn_z());  // rotations are their own

  // A plane x + y = 0 has normal (1, 1, 0)/√2; stretched by 2 in x, its tangent (1, −1, 0)
  // becomes (2, −1, 0): the skinned normal must stay perpendicular to it: (1, 2, 0)/√5.
  const Skinned out = skin(4, {stretch}, {0, 0, 0, 0}, {1, 0, 0, 0}, {{1, -1, 0}},
                           {glm::normalize(glm::vec3(1, 1, 0))}, {normal_matrix(stretch)});
  EXPECT_NEAR(glm::dot(out.normals[0], glm::vec3(2, -1, 0)), 0.0f, 1e-6f);
  EXPECT_NEAR(out.normals[0].x, 1.0f / std::sqrt(5.0f), 1e-6f);
  EXPECT_NEAR(out.normals[0].y, 2.0f / std::sqrt(5.0f), 1e-6f);
  // Without normal matrices the fast path uses mat3(M): wrong under non-uniform scale, as documented.
  const Skinned fast = skin(4, {stretch}, {0, 0, 0, 0}, {1, 0, 0, 0}, {{1, -1, 0}}, {glm::normalize(glm::vec3(1, 1, 0))});
  EXPECT_GT(std::fabs(glm::dot(fast.normals[0], glm::vec3(2, -1, 0))), 0.1f);
}

TEST(Skinning, MirroredAndSingularMatricesKeepSensibleNormals) {
  glm::mat4 mirror(1.0f);
  mirror[0][0] = -1.0f;
  EXPECT_EQ(glm::mat3(normal_matrix(mirror)) * glm::vec3(1, 0, 0), glm::vec3(-1, 0, 0));
  glm::mat4 flat(1.0f);
  flat[2][2] = 0.0f;  // squashes z: the cofactor keeps the z normal direction
  const glm::vec3 n = glm::mat3(normal_matrix(flat)) * glm::vec3(0, 0, 1);
  EXPECT_GT(n.z, 0.0f);
  EXPECT_TRUE(std::isfinite(n.x) && std::isfinite(n.y));
}

TEST(Skinning, ZeroNormalStaysZeroInsteadOfNaN) {
  const Skinned out = skin(4, {glm::mat4(1.0f)}, {0, 0, 0, 0}, {1, 0, 0, 0}, {{0, 0, 0}}, {{0, 0, 0}});
  EXPECT_EQ(out.normals[0], glm::vec3(0.0f));
}

TEST(Skinning, SkinMatricesAreJointWorldTimesInverseBind) {
  Skin s;
  s.joints = {2, 0};
  s.inverse_bind_matrices = {translation(-1, 0, 0), translation(0, -5, 0)};
  const std::vector<glm::mat4> world = {quarter_turn_z(), glm::mat4(1.0f), translation(3, 0, 0)};
  std::vector<glm::mat4> skin_m(2), normal_m(2);
  ASSERT_TRUE((SkinMatricesJob{&s, world, skin_m, normal_m}.run().ok()));
  EXPECT_EQ(skin_m[0], translation(2, 0, 0));
  EXPECT_EQ(skin_m[1], quarter_turn_z() * translation(0, -5, 0));
  EXPECT_EQ(normal_m[1], quarter_turn_z());
  EXPECT_EQ(normal_m[0], glm::mat4(1.0f));
  // Validity: joint node out of range, wrong output size, IBM count mismatch.
  Skin bad = s;
  bad.joints[0] = 3;
  EXPECT_FALSE((SkinMatricesJob{&bad, world, skin_m, {}}.validate().ok()));
  std::vector<glm::mat4> one(1);
  EXPECT_FALSE((SkinMatricesJob{&s, world, one, {}}.validate().ok()));
  bad = s;
  bad.inverse_bind_matrices.pop_back();
  EXPECT_FALSE((SkinMatricesJob{&bad, world, skin_m, {}}.validate().ok()));
  EXPECT_FALSE((SkinMatricesJob{nullptr, world, skin_m, {}}.validate().ok()));
}

TEST(SkinningValidity, RejectsEveryBrokenInput) {
  const std::vector<glm::mat4> palette = {glm::mat4(1.0f), glm::mat4(1.0f)};
  std::vector<std::uint16_t> joints = {0, 1, 0, 0};
  std::vector<float> weights = {0.5f, 0.5f, 0, 0};
  const std::vector<glm::vec3> positions = {{0, 0, 0}}, normals = {{0, 0, 1}};
  std::vector<glm::vec3> out_p(1), out_n(1);
  SkinningJob job;
  job.influences_per_vertex = 4;
  job.skin_matrices = palette;
  job.joints = joints;
  job.weights = weights;
  job.positions = positions;
  job.normals = normals;
  job.out_positions = out_p;
  job.out_normals = out_n;
  EXPECT_TRUE(job.validate().ok());

  SkinningJob bad = job;
  bad.influences_per_vertex = 0;
  EXPECT_FALSE(bad.validate().ok());
  bad = job;
  bad.influences_per_vertex = 3;  // 4 joints for 1 vertex × 3
  EXPECT_FALSE(bad.validate().ok());
  std::vector<std::uint16_t> out_of_range = {0, 2, 0, 0};  // palette has 2 matrices
  bad = job;
  bad.joints = out_of_range;
  EXPECT_FALSE(bad.run().ok());
  bad = job;
  bad.out_positions = {};
  EXPECT_FALSE(bad.validate().ok());
  bad = job;
  bad.out_normals = {};
  EXPECT_FALSE(bad.validate().ok());
  bad = job;
  bad.skin_matrices = {};
  EXPECT_FALSE(bad.validate().ok());
  const std::vector<glm::mat4> one_normal = {glm::mat4(1.0f)};
  bad = job;
  bad.normal_matrices = one_normal;
  EXPECT_FALSE(bad.validate().ok());
}

TEST(RigidTransform, MovesPositionsAndNormalsWithTheNodeMatrix) {
  glm::mat4 world = translation(1, 2, 3) * quarter_turn_z();
  world[0] *= 2.0f;  // non-uniform: x column scaled
  const std::vector<glm::vec3> positions = {{1, 0, 0}, {0, 1, 0}};
  const std::vector<glm::vec3> normals = {{1, 0, 0}, {0, 1, 0}};
  std::vector<glm::vec3> out_p(2), out_n(2);
  ASSERT_TRUE((RigidTransformJob{world, positions, normals, out_p, out_n}.run().ok()));
  EXPECT_EQ(out_p[0], glm::vec3(1, 4, 3));
  EXPECT_EQ(out_p[1], glm::vec3(0, 2, 3));
  EXPECT_NEAR(out_n[0].y, 1.0f, 1e-7f);
  EXPECT_NEAR(out_n[1].x, -1.0f, 1e-7f);
  std::vector<glm::vec3> wrong(1);
  EXPECT_FALSE((RigidTransformJob{world, positions, normals, wrong, out_n}.validate().ok()));
}

TEST(Morph, AddsWeightedDeltasBeforeSkinning) {
  std::vector<MorphTarget> targets(2);
  targets[0].position_deltas = {{1, 0, 0}, {0, 0, 0}};
  targets[0].normal_deltas = {{0, 1, 0}, {0, 0, 0}};
  targets[1].position_deltas = {{0, 2, 0}, {0, 0, 4}};
  const std::vector<float> weights = {0.5f, 0.25f};
  const std::vector<glm::vec3> positions = {{1, 1, 1}, {2, 2, 2}}, normals = {{0, 0, 1}, {0, 0, 1}};
  std::vector<glm::vec3> out_p(2), out_n(2);
  ASSERT_TRUE((MorphJob{targets, weights, positions, normals, out_p, out_n}.run().ok()));
  EXPECT_EQ(out_p[0], glm::vec3(1.5f, 1.5f, 1.0f));
  EXPECT_EQ(out_p[1], glm::vec3(2.0f, 2.0f, 3.0f));
  EXPECT_EQ(out_n[0], glm::vec3(0.0f, 0.5f, 1.0f));
  EXPECT_EQ(out_n[1], glm::vec3(0.0f, 0.0f, 1.0f));
  const std::vector<float> one_weight = {1.0f};
  EXPECT_FALSE((MorphJob{targets, one_weight, positions, normals, out_p, out_n}.validate().ok()));
  targets[1].position_deltas.pop_back();
  EXPECT_FALSE((MorphJob{targets, weights, positions, normals, out_p, out_n}.validate().ok()));
}

}  // namespace
}  // namespace proxygi::anim
