// Bone groups (anim/bone_groups.h) of the shared sample characters: for K = 1, 2, 4, 8 the groups
// are connected and cover every vertex exactly once (skipped when ../shared/assets is absent).
#include <filesystem>

#include <gtest/gtest.h>

#include "anim/gltf_import.h"
#include "bone_groups_check.h"

namespace proxygi::anim {
namespace {

class BoneGroupsSharedAssets : public ::testing::TestWithParam<const char*> {};

TEST_P(BoneGroupsSharedAssets, GroupsCoverEveryVertexExactlyOnce) {
  const std::filesystem::path path = std::filesystem::path(PROXYGI_SHARED_ASSETS_DIR) / "gltf" / GetParam();
  if (!std::filesystem::exists(path)) GTEST_SKIP() << path << " not found";
  auto character = import_gltf(path);
  ASSERT_TRUE(character.ok()) << character.message();
  testing::expect_groups_cover_every_vertex(*character);
}

INSTANTIATE_TEST_SUITE_P(Characters, BoneGroupsSharedAssets,
                         ::testing::Values("CesiumMan.glb", "Fox.glb", "RiggedSimple.glb"));

}  // namespace
}  // namespace proxygi::anim
