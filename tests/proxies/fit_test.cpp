// Fitting on synthetic shapes: geometry queries, rigid meshes, skinned arms, odd rigs.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "proxies/box_lattice.h"
#include "proxies/fit.h"
#include "proxies/mesh_index.h"
#include "proxies/point_sampling.h"
#include "proxies/quality.h"
#include "proxies/test_shapes.h"

namespace proxygi::proxies {
namespace {

using testing::arm_character;
using testing::box_character;
using testing::box_primitive;

using testing::box_sdf;

TriangleSoup soup_of(const anim::Primitive& prim) {
  TriangleSoup soup;
  testing::add_to_soup(soup, prim);
  return soup;
}

TEST(MeshIndex, ClosestPointOnTriangleBeatsEverySampledPoint) {
  const glm::vec3 a(0, 0, 0), b(1, 0, 0), c(0.2f, 1, 0.3f);
  Random random(3);
  for (int i = 0; i < 200; ++i) {
    const glm::vec3 p = glm::vec3(random.uniform(), random.uniform(), random.uniform()) * 3.0f - 1.0f;
    const float d = glm::length(p - closest_point_on_triangle(p, a, b, c));
    for (int k = 0; k < 200; ++k) {
      float u = random.uniform(), v = random.uniform();
      if (u + v > 1) u = 1 - u, v = 1 - v;
      EXPECT_LE(d, glm::length(p - (a + u * (b - a) + v * (c - a))) + 1e-5f);
    }
  }
}

TEST(MeshIndex, WindingAndDistanceMatchABox) {
  const glm::vec3 lo(-0.5f, -0.2f, -0.3f), hi(0.5f, 0.4f, 0.3f);
  const TriangleSoup soup = soup_of(box_primitive(lo, hi));
  WindingIndex winding;
  winding.build(soup, 16);
  ClosestTriangleGrid closest;
  closest.build(soup, 0.1f);
  Random random(5);
  for (int i = 0; i < 2000; ++i) {
    const glm::vec3 p = glm::vec3(random.uniform(), random.uniform(), random.uniform()) * 2.0f - 1.0f;
    const float exact = box_sdf(p, lo, hi);
    if (std::abs(exact) < 1e-4f) continue;
    EXPECT_EQ(winding.inside(p), exact < 0.0f) << p.x << " " << p.y << " " << p.z;
    EXPECT_NEAR(closest.distance(p, 10.0f), std::abs(exact), 1e-5f);
  }
  const float cell = 0.05f, band = 0.2f;
  const DistanceGrid grid = build_distance_grid(soup, winding, Box{lo, hi}, cell, band);
  for (int i = 0; i < 2000; ++i) {
    const glm::vec3 p = glm::vec3(random.uniform(), random.uniform(), random.uniform()) * 1.6f - 0.8f;
    const float exact = std::clamp(box_sdf(p, lo, hi), -band, band);
    // Trilinear interpolation of a distance field is off by at most about half a cell.
    EXPECT_NEAR(grid.sample(p), exact, 0.5f * cell);
  }
}

TEST(Fit, UnskinnedBoxIsOneRigidSetOnItsNode) {
  const glm::vec3 lo(-0.3f, 0.0f, -0.2f), hi(0.3f, 1.0f, 0.2f), offset(2.0f, 0.0f, 1.0f);
  const anim::Character ch = box_character(lo, hi, offset);
  FitResult fit;
  FitProxiesJob job;
  job.character = &ch;
  job.result = &fit;
  ASSERT_TRUE(job.run().ok());
  ASSERT_FALSE(fit.rig.spheres.empty());
  for (std::size_t i = 0; i < fit.rig.spheres.size(); ++i) {
    const ProxySphere& s = fit.rig.spheres[i];
    EXPECT_EQ(s.node, 0);
    EXPECT_EQ(s.bone, "box");
    // Bone space is the box node's local frame: the bind-space center minus the node offset.
    EXPECT_NEAR(glm::length(s.center + offset - fit.fitted[i].center), 0.0f, 1e-5f);
    EXPECT_GT(s.radius, 0.0f);
    EXPECT_LE(fit.fitted[i].protrusion, fit.tolerance_m);
  }
  const FitQuality q = measure_fit_quality(ch, fit);
  EXPECT_GE(q.coverage, 0.999f);
  // Exact protrusion (boundary points outside the box) is within the grid's accuracy of the
  // fitted one. Union boundary inside the box (seams where spheres that fall short of their
  // points by the slack meet) is not protrusion, so the exact box distance is used here rather
  // than the quality's distance to the surface, which counts those seams too.
  const std::vector<glm::vec3> directions = fibonacci_directions(256);
  float protrusion = 0.0f;
  for (const FittedSphere& s : fit.fitted)
    for (const glm::vec3& d : directions) protrusion = std::max(protrusion, box_sdf(s.center + s.radius * d, lo + offset, hi + offset));
  EXPECT_LE(protrusion, fit.tolerance_m + 0.5f * fit.diagonal / 100.0f);
  EXPECT_GT(q.outside_volume_ratio, 0.0f);
  EXPECT_LT(q.outside_volume_ratio, 1.0f);
}

TEST(Fit, TighterToleranceNeedsMoreSpheresAndErrsLess) {
  // A bar thin enough that every tolerance below is reachable (a sphere over its square cross
  // section protrudes by (sqrt(2) - 1) × half-width = 0.02 m at least). The error is two-sided
  // (spheres may fall short of the surface by the slack, which scales with the tolerance): the
  // larger of the two Hausdorff distances.
  const anim::Character ch = box_character(glm::vec3(-1.0f, -0.05f, -0.05f), glm::vec3(1.0f, 0.05f, 0.05f));
  std::size_t previous = 0;
  float previous_error = 1e9f;
  for (float tolerance : {0.08f, 0.04f, 0.02f}) {
    FitResult fit;
    FitProxiesJob job;
    job.character = &ch;
    job.result = &fit;
    job.options.tolerance = tolerance;
    ASSERT_TRUE(job.run().ok());
    float worst_protrusion = 0.0f;
    for (const FittedSphere& f : fit.fitted) worst_protrusion = std::max(worst_protrusion, f.protrusion);
    EXPECT_LE(worst_protrusion, fit.tolerance_m);
    const FitQuality q = measure_fit_quality(ch, fit);
    const float worst = std::max(q.hausdorff_spheres_to_surface, q.hausdorff_surface_to_spheres);
    EXPECT_GT(fit.rig.spheres.size(), previous);
    EXPECT_LT(worst, previous_error);
    previous = fit.rig.spheres.size();
    previous_error = worst;
  }
}

TEST(Fit, MaxSpheresCapsTheCount) {
  const anim::Character ch = box_character(glm::vec3(-1.0f, -0.1f, -0.1f), glm::vec3(1.0f, 0.1f, 0.1f));
  FitResult fit;
  FitProxiesJob job;
  job.character = &ch;
  job.result = &fit;
  job.options.tolerance = 0.005f;
  job.options.max_spheres = 3;
  ASSERT_TRUE(job.run().ok());
  EXPECT_EQ(fit.rig.spheres.size(), 3u);
}

TEST(Fit, SkinnedArmGetsSpheresOnWeightedBonesOnly) {
  const anim::Character ch = arm_character();
  FitResult fit;
  FitProxiesJob job;
  job.character = &ch;
  job.result = &fit;
  ASSERT_TRUE(job.run().ok());
  int upper = 0, lower = 0;
  for (const ProxySphere& s : fit.rig.spheres) {
    EXPECT_NE(s.bone, "tip") << "a bone with no vertices must get no sphere";
    EXPECT_NE(s.bone, "skin_mesh");
    upper += s.bone == "upper" ? 1 : 0;
    lower += s.bone == "lower" ? 1 : 0;
  }
  EXPECT_GE(upper, 1);
  EXPECT_GE(lower, 1);
  // Bone space: a "lower" sphere's center is its bind center minus the joint offset (0.5, 0, 0).
  for (std::size_t i = 0; i < fit.rig.spheres.size(); ++i) {
    const glm::vec3 expected = fit.fitted[i].center - (fit.rig.spheres[i].bone == "lower" ? glm::vec3(0.5f, 0, 0) : glm::vec3(0.0f));
    EXPECT_NEAR(glm::length(fit.rig.spheres[i].center - expected), 0.0f, 1e-5f);
    // Mean weights are normalized and led by the sphere's own bone or its neighbour.
    float sum = 0.0f;
    for (float w : fit.rig.spheres[i].weights) sum += w;
    EXPECT_NEAR(sum, 1.0f, 1e-5f);
  }
}

TEST(Fit, FlatPlateWarnsNamingTheBone) {
  const anim::Character ch = box_character(glm::vec3(-0.5f, 0.0f, -0.5f), glm::vec3(0.5f, 0.01f, 0.5f));
  FitResult fit;
  FitProxiesJob job;
  job.character = &ch;
  job.result = &fit;
  ASSERT_TRUE(job.run().ok());
  const bool named = std::any_of(fit.rig.warnings.begin(), fit.rig.warnings.end(),
                                 [](const std::string& w) { return w.find("bone 'box'") != std::string::npos; });
  EXPECT_TRUE(named);
}

TEST(Fit, AlbedoIsTheLinearBaseColorOfTheSurface) {
  anim::Character ch = box_character(glm::vec3(-0.2f), glm::vec3(0.2f));
  anim::Material material;
  material.base_color_factor = glm::vec4(0.5f, 0.25f, 1.0f, 1.0f);
  anim::Image image;  // 1x1 sRGB texel 188 ≈ linear 0.5
  image.width = image.height = 1;
  image.rgba = {188, 188, 188, 255};
  material.base_color_image = 0;
  ch.materials.push_back(material);
  ch.images.push_back(image);
  ch.meshes[0].primitives[0].material = 0;
  ch.meshes[0].primitives[0].uvs.assign(ch.meshes[0].primitives[0].positions.size(), glm::vec2(0.5f));
  FitResult fit;
  FitProxiesJob job;
  job.character = &ch;
  job.result = &fit;
  ASSERT_TRUE(job.run().ok());
  const float texel = std::pow((188.0f / 255.0f + 0.055f) / 1.055f, 2.4f);
  for (const ProxySphere& s : fit.rig.spheres) {
    EXPECT_NEAR(s.albedo.r, 0.5f * texel, 1e-4f);
    EXPECT_NEAR(s.albedo.g, 0.25f * texel, 1e-4f);
    EXPECT_NEAR(s.albedo.b, 1.0f * texel, 1e-4f);
  }
}

TEST(Fit, RejectsBadOptionsAndEmptyCharacters) {
  anim::Character empty;
  empty.source = "empty";
  FitResult fit;
  FitProxiesJob job;
  job.character = &empty;
  job.result = &fit;
  const Status no_triangles = job.run();
  ASSERT_FALSE(no_triangles.ok());
  EXPECT_NE(no_triangles.message().find("no triangles"), std::string::npos);
  job.options.tolerance = -1.0f;
  EXPECT_FALSE(job.validate().ok());
  job.options.tolerance = 0.05f;
  job.options.max_spheres = 0;
  EXPECT_FALSE(job.validate().ok());
  job.result = nullptr;
  job.options.max_spheres = 4;
  EXPECT_FALSE(job.validate().ok());
}

}  // namespace
}  // namespace proxygi::proxies
