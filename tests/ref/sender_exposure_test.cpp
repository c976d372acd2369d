// ref::SenderExposureJob (ref/sender_exposure.h), the VSGL senders' exposure: a triangle buried
// inside a closed box gets 0, the box's own (open) vertices 1, a floor vertex at a
// wall's foot half; with the exposures applied, VSGL with one light per VPL equals brute-force
// gathering of the VPLs that are not buried (and not of all of them).
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "ref/sender_exposure.h"
#include "sh/vsgl.h"
#include "tests/sh/vsgl_lobe_bound.h"

namespace proxygi::ref {
namespace {

// A closed axis-aligned box, each face its own four vertices with the outward face normal.
anim::PosedPrimitive box(const glm::vec3& low, const glm::vec3& high) {
  anim::PosedPrimitive out;
  out.name = "box";
  for (int axis = 0; axis < 3; ++axis)
    for (int side = 0; side < 2; ++side) {
      glm::vec3 n(0.0f);
      n[axis] = side ? 1.0f : -1.0f;
      const int u = (axis + 1) % 3, v = (axis + 2) % 3;
      const std::uint32_t base = std::uint32_t(out.positions.size());
      for (int corner = 0; corner < 4; ++corner) {
        glm::vec3 p;
        p[axis] = side ? high[axis] : low[axis];
        p[u] = (corner == 1 || corner == 2) ? high[u] : low[u];
        p[v] = corner >= 2 ? high[v] : low[v];
        out.positions.push_back(p);
        out.normals.push_back(n);
      }
      // Wound counter-clockwise about n (the winding does not matter to the rays).
      if (side) out.indices.insert(out.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
      else out.indices.insert(out.indices.end(), {base, base + 2, base + 1, base, base + 3, base + 2});
    }
  return out;
}

anim::PosedPrimitive triangle(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c, const glm::vec3& normal) {
  anim::PosedPrimitive out;
  out.name = "triangle";
  out.positions = {a, b, c};
  out.normals = {normal, normal, normal};
  out.indices = {0, 1, 2};
  return out;
}

std::vector<std::vector<float>> run(std::span<const anim::PosedPrimitive> primitives, int directions = 256) {
  std::vector<std::vector<float>> exposure;
  SenderExposureJob job;
  job.primitives = primitives;
  job.directions = directions;
  job.exposure = &exposure;
  const Status s = job.run();
  EXPECT_TRUE(s.ok()) << (s.ok() ? "" : s.message());
  return exposure;
}

TEST(SenderExposure, BuriedTriangleGetsZeroOpenSurfacesOne) {
  const std::vector<anim::PosedPrimitive> parts = {
      box({-0.5f, 0.0f, -0.5f}, {0.5f, 1.0f, 0.5f}),
      // inside the box, facing up: every ray meets the box's inside
      triangle({-0.2f, 0.5f, -0.2f}, {0.2f, 0.5f, -0.2f}, {0.0f, 0.5f, 0.2f}, {0, 1, 0})};
  const auto exposure = run(parts);
  ASSERT_EQ(exposure.size(), 2u);
  ASSERT_EQ(exposure[0].size(), 24u);
  for (float e : exposure[0]) EXPECT_EQ(e, 1.0f);  // a convex closed mesh: each hemisphere is open
  for (float e : exposure[1]) EXPECT_EQ(e, 0.0f);
  // Deterministic: the same exposures again.
  EXPECT_EQ(run(parts), exposure);
}

TEST(SenderExposure, FloorVertexAtAWallsFootIsHalfOpen) {
  // The wall (x = 0, 2 m high and wide) blocks the half of the floor vertex's hemisphere toward −x:
  // cosine-weighted, exactly half by symmetry, less the thin sliver over its top and sides.
  anim::PosedPrimitive wall;
  wall.name = "wall";
  wall.positions = {{0, 0, -1}, {0, 0, 1}, {0, 2, 1}, {0, 2, -1}};
  wall.normals = std::vector<glm::vec3>(4, glm::vec3(1, 0, 0));
  wall.indices = {0, 1, 2, 0, 2, 3};
  const std::vector<anim::PosedPrimitive> parts = {
      wall, triangle({0.002f, 0.0f, 0.0f}, {1.0f, 0.0f, 0.0f}, {1.0f, 0.0f, 0.5f}, {0, 1, 0})};
  const auto exposure = run(parts, 1024);
  ASSERT_EQ(exposure.size(), 2u);
  // The sliver: directions over the 2 m wall from 2 mm away miss it; about (1/π)·(solid angle
  // near the horizon) — under 2 % here, and the 1024 stratified directions add under 1 %.
  EXPECT_NEAR(exposure[1][0], 0.5f, 0.03f);
  EXPECT_GT(exposure[1][0], 0.45f);
  // 1 m away the wall covers less of the sky (elevations below atan(2) toward −x only).
  EXPECT_GT(exposure[1][1], 0.6f);
  EXPECT_LT(exposure[1][1], 0.95f);
}

TEST(SenderExposure, ValidatesItsInputs) {
  std::vector<std::vector<float>> exposure;
  anim::PosedPrimitive bad = triangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1});
  bad.indices[2] = 7;
  const std::vector<anim::PosedPrimitive> parts = {bad};
  SenderExposureJob job;
  job.primitives = parts;
  job.exposure = &exposure;
  const Status out_of_range = job.validate();
  ASSERT_FALSE(out_of_range.ok());
  EXPECT_NE(out_of_range.message().find("primitive 0 (triangle): index 2 out of range (3 vertices)"), std::string::npos)
      << out_of_range.message();
  bad.indices[2] = 2;
  const std::vector<anim::PosedPrimitive> good = {bad};
  job.primitives = good;
  job.directions = 0;
  EXPECT_FALSE(job.validate().ok());
  job.directions = 16;
  job.exposure = nullptr;
  EXPECT_FALSE(job.validate().ok());
  job.exposure = &exposure;
  EXPECT_TRUE(job.validate().ok());
}

// One VPL per triangle as vsgl_lights.comp forms it (sh::triangle_light) under a constant L̃.
std::vector<sh::VirtualPointLight> vpls(std::span<const anim::PosedPrimitive> parts, std::span<const double> albedo,
                                        const std::vector<std::vector<float>>& exposure, bool weighted) {
  std::array<std::array<float, 9>, 3> irradiance{};
  for (auto& channel : irradiance) channel[0] = float(std::numbers::pi * 2.0 * std::sqrt(std::numbers::pi));  // E = π
  std::vector<sh::VirtualPointLight> out;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    const anim::PosedPrimitive& p = parts[i];
    for (std::size_t t = 0; t < p.indices.size(); t += 3) {
      glm::dvec3 x[3], n[3], e;
      for (int k = 0; k < 3; ++k) {
        x[k] = glm::dvec3(p.positions[p.indices[t + std::size_t(k)]]);
        n[k] = glm::dvec3(p.normals[p.indices[t + std::size_t(k)]]);
        e[k] = weighted ? exposure[i][p.indices[t + std::size_t(k)]] : 1.0;
      }
      out.push_back(sh::triangle_light(x, n, albedo[i] * glm::dvec3(1.0, 0.6, 0.3), irradiance, e));
    }
  }
  return out;
}

TEST(SenderExposure, VsglOfExposedVplsEqualsBruteForceGatheringOfTheVisibleOnes) {
  // A dark box and a bright triangle buried inside it facing +x (its light would matter there);
  // receivers on the +x side: on the ground, above, and on a wall facing the box.
  const std::vector<anim::PosedPrimitive> parts = {
      box({-0.5f, 0.0f, -0.5f}, {0.5f, 1.0f, 0.5f}),
      triangle({0.3f, 0.05f, -0.45f}, {0.3f, 0.95f, 0.0f}, {0.3f, 0.05f, 0.45f}, {1, 0, 0})};
  const double albedo[] = {0.02, 0.9};  // the bound grows with the visible VPLs' flux
  const auto exposure = run(parts);
  ASSERT_EQ(exposure.size(), 2u);
  for (float e : exposure[1]) EXPECT_EQ(e, 0.0f);
  const auto weighted = vpls(parts, albedo, exposure, true);
  const auto all = vpls(parts, albedo, exposure, false);
  std::vector<sh::VirtualPointLight> visible(all.begin(), all.begin() + 12);  // the box's, not the buried one
  ASSERT_EQ(weighted.size(), 13u);
  EXPECT_EQ(weighted[12].flux, glm::dvec3(0.0));
  std::vector<sh::Vsgl> lights;  // K = number of VPLs (sh::fit_vsgl skips the zero one)
  for (const sh::VirtualPointLight& v : weighted) {
    sh::VsglSums sums;
    sh::add_light(sums, v, v.position);
    if (auto light = sh::fit_vsgl(sums, v.position)) lights.push_back(*light);
  }
  EXPECT_EQ(lights.size(), 12u);
  const double pair_bound = sh::testing::diffuse_lobe_pair_bound();
  int checked = 0, distinguished = 0;
  const std::pair<glm::dvec3, glm::dvec3> receivers[] = {{{1.5, 0.0, 0.2}, {0, 1, 0}},  {{1.2, 0.0, -0.9}, {0, 1, 0}},
                                                        {{2.0, 0.0, 1.0}, {0, 1, 0}},  {{1.0, 2.0, 0.0}, {0, -1, 0}},
                                                        {{1.6, 0.5, 0.0}, {-1, 0, 0}}};
  for (const auto& [p, n] : receivers) {
    const glm::dvec3 brute = sh::gather_vpl_irradiance(visible, p, n);
    const glm::dvec3 every = sh::gather_vpl_irradiance(all, p, n);
    glm::dvec3 summed(0.0), bound(0.0);
    for (const sh::Vsgl& light : lights) summed += sh::vsgl_irradiance(light, p, n);
    for (const sh::VirtualPointLight& v : visible) {
      const glm::dvec3 offset = v.position - p;
      bound += std::numbers::pi * v.flux / glm::dot(offset, offset) * pair_bound;
    }
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(summed[c], brute[c], bound[c] + 1e-5 * brute[c]) << "receiver " << checked << " channel " << c;
      // The test can tell: gathering the buried VPL too is further off than the bound.
      if (std::abs(every[c] - summed[c]) > bound[c] + 1e-5 * brute[c]) ++distinguished;
    }
    ++checked;
  }
  EXPECT_EQ(checked, 5);
  EXPECT_EQ(distinguished, 15);  // every receiver, every channel
}

}  // namespace
}  // namespace proxygi::ref
