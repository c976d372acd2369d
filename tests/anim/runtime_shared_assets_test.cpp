// Poses the shared sample characters (CesiumMan, Fox, RiggedSimple) at several times of every
// clip: results are finite and their bounds stay plausible next to the rest pose.
#include <cmath>
#include <filesystem>
#include <limits>
#include <string>

#include <gtest/gtest.h>

#include "anim/gltf_import.h"
#include "anim/posed_character.h"

namespace proxygi::anim {
namespace {

class SharedAssetPose : public ::testing::TestWithParam<const char*> {};

struct Box {
  glm::vec3 low{std::numeric_limits<float>::max()};
  glm::vec3 high{std::numeric_limits<float>::lowest()};
  float diagonal() const { return glm::length(high - low); }
};

Box pose_box(const Character& character, int clip, float time) {
  PoseBuffers pose;
  const Status status = evaluate_pose(character, clip, time, WrapMode::loop, pose);
  EXPECT_TRUE(status.ok()) << (status ? "" : status.message());
  Result<std::vector<PosedPrimitive>> meshes = pose_meshes(character, pose);
  EXPECT_TRUE(meshes.ok()) << (meshes ? "" : meshes.message());
  Box box;
  if (!meshes) return box;
  for (const PosedPrimitive& mesh : *meshes) {
    for (const glm::vec3& p : mesh.positions) {
      EXPECT_TRUE(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z));
      box.low = glm::min(box.low, p);
      box.high = glm::max(box.high, p);
    }
    for (const glm::vec3& n : mesh.normals) EXPECT_NEAR(glm::length(n), 1.0f, 1e-4f);
  }
  return box;
}

TEST_P(SharedAssetPose, FiniteAndPlausibleAtEveryClipAndTime) {
  const std::filesystem::path path = std::filesystem::path(PROXYGI_SHARED_ASSETS_DIR) / "gltf" / GetParam();
  if (!std::filesystem::exists(path)) GTEST_SKIP() << path << " not found";
  Result<Character> character = import_gltf(path);
  ASSERT_TRUE(character.ok()) << character.message();
  ASSERT_FALSE(character->clips.empty());
  const Box rest = pose_box(*character, -1, 0.0f);
  ASSERT_GT(rest.diagonal(), 0.0f);
  for (std::size_t c = 0; c < character->clips.size(); ++c) {
    const float duration = character->clips[c].duration;
    for (const float fraction : {0.0f, 0.13f, 0.5f, 0.77f, 1.0f}) {
      SCOPED_TRACE("clip " + std::to_string(c) + " at " + std::to_string(fraction * duration) + " s");
      const Box box = pose_box(*character, static_cast<int>(c), fraction * duration);
      // Animation bends limbs and moves the root a little; it does not explode or collapse.
      EXPECT_GT(box.diagonal(), 0.3f * rest.diagonal());
      EXPECT_LT(box.diagonal(), 3.0f * rest.diagonal());
      const glm::vec3 shift = 0.5f * (box.low + box.high) - 0.5f * (rest.low + rest.high);
      EXPECT_LT(glm::length(shift), 2.0f * rest.diagonal());
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Samples, SharedAssetPose, ::testing::Values("CesiumMan.glb", "Fox.glb", "RiggedSimple.glb"),
                         [](const ::testing::TestParamInfo<const char*>& param) {
                           std::string name = param.param;
                           return name.substr(0, name.find('.'));
                         });

}  // namespace
}  // namespace proxygi::anim
