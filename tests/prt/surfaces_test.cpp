// Static receivers from a scene (prt/surfaces.h) and the outer ground of the precompute.
#include "prt/surfaces.h"

#include <gtest/gtest.h>

#include <cmath>

#include "prt/transfer.h"
#include "prt_scenes.h"
#include "scene/scene_parse.h"

namespace proxygi::prt {
namespace {

TEST(PrtSurfaces, WallCornerSceneGivesItsBoxesAndAGroundPatch) {
  auto scene = scene::load_scene(std::filesystem::path(PROXYGI_SOURCE_DIR) / "assets/scenes/wall_corner.json");
  ASSERT_TRUE(scene.ok()) << scene.message();
  auto world = world::World::load(
      *scene, {.assets_dir = std::filesystem::path(PROXYGI_SOURCE_DIR) / "assets", .load_rigs = false});
  ASSERT_TRUE(world.ok()) << world.message();
  auto r = static_receivers(**world, 0.1f, 2.0f);
  ASSERT_TRUE(r.ok()) << r.message();
  ASSERT_EQ(r->surfaces.size(), 6u);  // 2 walls, 3 steps, the ground patch
  EXPECT_EQ(r->surfaces.back().name, "ground");
  EXPECT_NE(r->surfaces[0].name.find("static_meshes[0]:"), std::string::npos) << r->surfaces[0].name;
  EXPECT_EQ(r->surfaces[0].albedo, glm::vec3(0.75f, 0.7f, 0.62f));  // the wall material's factor
  // The model spans x, z in [-1.1, 2] × [-1.1, 1.9]; the patch adds 2 m all round.
  EXPECT_FLOAT_EQ(r->outer_ground.patch_min.x, -3.1f);
  EXPECT_FLOAT_EQ(r->outer_ground.patch_max.y, 3.9f);
  EXPECT_TRUE(r->outer_ground.enabled);
  // Mesh edges meet the spacing; the ground grid's cells do (their diagonals are √2 longer).
  for (const StaticSurface& s : r->surfaces) {
    const float limit = (s.name == "ground" ? std::sqrt(2.0f) : 1.0f) * 0.1f + 1e-5f;
    for (std::size_t t = 0; t < s.indices.size(); t += 3)
      for (int e = 0; e < 3; ++e)
        ASSERT_LE(glm::length(s.positions[s.indices[t + std::size_t(e)]] -
                              s.positions[s.indices[t + std::size_t((e + 1) % 3)]]),
                  limit)
            << s.name << " triangle " << t / 3;
  }
}

TEST(PrtSurfaces, OuterGroundBlocksAndLitLikeAMeshedGround) {
  // A wall standing on a meshed floor, and the same wall on the analytic outer ground only.
  const auto wall = test::quad("wall", {-1, 0, -1}, {0, 2, 0}, {0, 0, 2}, glm::vec3(0.7f), 0.25f);
  StaticReceivers meshed, outer;
  meshed.surfaces = {wall, test::quad("floor", {-10, 0, -10}, {0, 0, 20}, {20, 0, 0}, glm::vec3(0.5f), 2.0f)};
  outer.surfaces = {wall};
  outer.outer_ground = {true, 10.0f, glm::vec2(0.0f), glm::vec2(0.0f), glm::vec3(0.5f)};
  const TransferSettings settings{.order = 3, .directions = 512, .bounces = 1};
  auto a = compute_transfer(meshed, settings), b = compute_transfer(outer, settings);
  ASSERT_TRUE(a.ok() && b.ok());
  const std::size_t nn = 9;
  for (std::size_t v = 0; v < wall.positions.size(); ++v) {
    // The ground blocks the lower half of the wall's hemisphere the same way (same directions).
    for (std::size_t i = 0; i < nn; ++i)
      ASSERT_NEAR(a->surfaces[0].shadowed[v * nn + i], b->surfaces[0].shadowed[v * nn + i], 2e-3) << "vertex " << v;
    // One bounce off the floor: the outer ground is taken as unshadowed (T = H(+Y)), the meshed
    // floor knows the wall's shadow: never darker, and equal where the floor is far from the wall.
    const float bounce_a = a->surfaces[0].interreflected[3 * v * nn] - a->surfaces[0].shadowed[v * nn];
    const float bounce_b = b->surfaces[0].interreflected[3 * v * nn] - b->surfaces[0].shadowed[v * nn];
    EXPECT_GT(bounce_a, 0.0f) << "vertex " << v;
    EXPECT_GE(bounce_b, bounce_a - 1e-4f) << "vertex " << v;
    EXPECT_LT(bounce_b, 1.6f * bounce_a) << "vertex " << v;
  }
}

}  // namespace
}  // namespace proxygi::prt
