// Culling, level of detail and sphere geometry.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "proxies/culling.h"
#include "proxies/sphere_mesh.h"
#include "proxies/test_shapes.h"

namespace proxygi::proxies {
namespace {

TEST(Culling, KeepsSpheresWhoseInfluenceTouchesTheFrustum) {
  const glm::mat4 view = glm::lookAt(glm::vec3(0, 1, 4), glm::vec3(0, 1, 0), glm::vec3(0, 1, 0));
  const glm::mat4 projection = glm::perspective(glm::radians(60.0f), 16.0f / 9.0f, 0.1f, 100.0f);
  const Frustum frustum = Frustum::from_view_projection(projection * view);
  const std::vector<WorldSphere> spheres = {
      {glm::vec3(0, 1, 0), 0.1f, glm::vec3(1), 0},     // in view
      {glm::vec3(0, 1, 8), 0.1f, glm::vec3(1), 0},     // behind the camera, influence 1.5 m: reaches the near plane? no (4 m behind)
      {glm::vec3(12, 1, 0), 0.1f, glm::vec3(1), 0},    // far to the side
      {glm::vec3(0, 1, 4.6f), 0.05f, glm::vec3(1), 0}, // just behind the eye, influence 0.75 m reaches the near plane
  };
  std::vector<std::uint32_t> kept(spheres.size());
  int count = -1;
  CullProxiesJob job{spheres, frustum, 15.0f, kept, &count};
  ASSERT_TRUE(job.run().ok());
  ASSERT_EQ(count, 2);
  EXPECT_EQ(kept[0], 0u);
  EXPECT_EQ(kept[1], 3u);
  // With eta = 1 the sphere just behind the eye no longer reaches.
  job.eta = 1.0f;
  ASSERT_TRUE(job.run().ok());
  EXPECT_EQ(count, 1);
}

TEST(LevelOfDetail, MergesChainsThatAreSmallOnScreen) {
  const anim::Character ch = testing::arm_character();
  ProxyRig rig;
  for (const char* bone : {"upper", "upper", "lower"}) {
    ProxySphere s;
    s.bone = bone;
    s.node = std::string(bone) == "upper" ? 1 : 2;
    rig.spheres.push_back(s);
  }
  const std::vector<int> groups = chain_groups(rig, ch);
  // upper -> lower -> tip is one unbranched chain rooted at "upper".
  EXPECT_EQ(groups, (std::vector<int>{1, 1, 1}));
  const std::vector<WorldSphere> spheres = {{glm::vec3(0, 0, 0), 0.1f, glm::vec3(1, 0, 0), 0},
                                            {glm::vec3(0.3f, 0, 0), 0.1f, glm::vec3(0, 1, 0), 0},
                                            {glm::vec3(0.6f, 0, 0), 0.1f, glm::vec3(0, 0, 1), 0}};
  std::vector<WorldSphere> out(3);
  int count = 0;
  MergeSmallProxiesJob job{spheres, groups, glm::vec3(0, 0, 5), 1000.0f, 2.0f, out, &count};
  ASSERT_TRUE(job.run().ok());
  EXPECT_EQ(count, 3);  // 0.4 m at 5 m: ~80 px, kept
  job.eye = glm::vec3(0, 0, 1000);
  ASSERT_TRUE(job.run().ok());
  ASSERT_EQ(count, 1);
  for (const WorldSphere& s : spheres) EXPECT_LE(glm::length(s.center - out[0].center) + s.radius, out[0].radius + 1e-5f);
  EXPECT_NEAR(out[0].albedo.r + out[0].albedo.g + out[0].albedo.b, 1.0f, 1e-5f);
}

TEST(SphereMesh, VerticesLieOnTheSpheresWithOutwardTriangles) {
  const std::vector<WorldSphere> spheres = {{glm::vec3(1, 2, 3), 0.5f, glm::vec3(0.2f), 0},
                                            {glm::vec3(-1, 0, 0), 0.25f, glm::vec3(0.8f), 0}};
  SphereGeometry g;
  append_sphere_geometry(spheres, 12, g);
  ASSERT_EQ(g.positions.size() % 2, 0u);
  const std::size_t per = g.positions.size() / 2;
  for (std::size_t v = 0; v < g.positions.size(); ++v) {
    const WorldSphere& s = spheres[v / per];
    EXPECT_NEAR(glm::length(g.positions[v] - s.center), s.radius, 1e-5f);
  }
  for (std::size_t t = 0; t < g.indices.size(); t += 3) {
    const glm::vec3 a = g.positions[g.indices[t]], b = g.positions[g.indices[t + 1]], c = g.positions[g.indices[t + 2]];
    const WorldSphere& s = spheres[g.indices[t] / per];
    const glm::vec3 n = glm::cross(b - a, c - a);
    EXPECT_GT(glm::dot(n, (a + b + c) / 3.0f - s.center), 0.0f);
  }
}

}  // namespace
}  // namespace proxygi::proxies
