// Walk paths, clip time and the character world matrix.
#include <gtest/gtest.h>

#include <cmath>

#include <glm/gtc/constants.hpp>

#include "scene/character_motion.h"

namespace proxygi::scene {
namespace {

void expect_near(const glm::vec3& a, const glm::vec3& b) {
  EXPECT_NEAR(glm::length(a - b), 0.0f, 1e-5f) << a.x << "," << a.y << "," << a.z;
}

TEST(CharacterMotion, ClipTime) {
  Character c;
  c.speed = 1.5f;
  c.time_offset_s = 0.25f;
  EXPECT_DOUBLE_EQ(clip_time_s(c, 2.0), 3.25);
  EXPECT_DOUBLE_EQ(clip_time_s(c, 0.0), 0.25);
}

TEST(CharacterMotion, PathStopsLoopsOrPingPongs) {
  WalkPath path{glm::vec3(0, 0, 0), glm::vec3(4, 0, 0), 2.0f, WalkPath::Repeat::none};
  expect_near(walk_path_at(path, -1.0).position, glm::vec3(0, 0, 0));
  expect_near(walk_path_at(path, 0.5).position, glm::vec3(1, 0, 0));
  expect_near(walk_path_at(path, 5.0).position, glm::vec3(4, 0, 0));
  EXPECT_NEAR(walk_path_at(path, 0.5).heading_radians, glm::half_pi<float>(), 1e-6f);  // +Z turned to +X

  path.repeat = WalkPath::Repeat::loop;
  expect_near(walk_path_at(path, 2.5).position, glm::vec3(1, 0, 0));

  path.repeat = WalkPath::Repeat::ping_pong;
  expect_near(walk_path_at(path, 2.5).position, glm::vec3(3, 0, 0));  // 5 m: 4 out, 1 back
  EXPECT_NEAR(walk_path_at(path, 2.5).heading_radians, -glm::half_pi<float>(), 1e-6f);  // facing -X
  expect_near(walk_path_at(path, 4.5).position, glm::vec3(1, 0, 0));  // 9 m: second lap, outbound
  EXPECT_NEAR(walk_path_at(path, 4.5).heading_radians, glm::half_pi<float>(), 1e-6f);
}

TEST(CharacterMotion, WorldMatrixAppliesTheTransformInsideThePathFrame) {
  Character c;
  c.transform.translation = glm::vec3(0, 0.1f, 0);
  c.transform.scale = glm::vec3(2.0f);
  expect_near(character_root_position(c, 3.0), glm::vec3(0, 0.1f, 0));  // no path: fixed
  c.path = WalkPath{glm::vec3(1, 0, 1), glm::vec3(1, 0, -5), 1.0f, WalkPath::Repeat::none};
  const glm::mat4 m = character_world_matrix(c, 2.0);
  expect_near(glm::vec3(m[3]), glm::vec3(1, 0.1f, -1));
  // Model +Z (forward) points along the path (-Z), scaled by 2.
  expect_near(glm::vec3(m * glm::vec4(0, 0, 1, 0)), glm::vec3(0, 0, -2));
  expect_near(glm::vec3(m * glm::vec4(0, 1, 0, 0)), glm::vec3(0, 2, 0));
}

TEST(CharacterMotion, EulerRotationIsExtrinsicXYZ) {
  Rotation r;
  r.euler_degrees = glm::vec3(90.0f, 90.0f, 0.0f);
  // X first: +Y -> +Z; then Y: +Z -> +X.
  expect_near(r.to_quat() * glm::vec3(0, 1, 0), glm::vec3(1, 0, 0));
  r.euler_degrees = glm::vec3(0.0f, 0.0f, 90.0f);
  expect_near(r.to_quat() * glm::vec3(1, 0, 0), glm::vec3(0, 1, 0));
  Rotation q;
  q.form = Rotation::Form::quaternion;
  q.quaternion = glm::quat(2.0f, 0.0f, 0.0f, 0.0f);  // renormalized on use
  expect_near(q.to_quat() * glm::vec3(1, 2, 3), glm::vec3(1, 2, 3));
}

}  // namespace
}  // namespace proxygi::scene
