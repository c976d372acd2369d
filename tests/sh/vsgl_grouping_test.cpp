// render.vsgl_grouping on a synthetic two-limb character against brute-force VPL gathering
// (sh::gather_vpl_irradiance): K VSGLs per character by index range or by bone group
// (anim/bone_groups.h). The limbs are two cylinders, one up-left and one down-right of a
// root joint, three joints each; the vertices are listed ring by ring alternating between the
// limbs (as a mirrored mesh export can order them), so an index range holds both limbs.
// Receivers: a grid on the ground below and points beside each limb. Measured error: relative
// RMS over the receivers of the irradiance.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "anim/bone_groups.h"
#include "sh/vsgl.h"

namespace proxygi::sh {
namespace {

constexpr double kPi = std::numbers::pi;

struct Character {
  std::vector<VirtualPointLight> vpls;
  std::vector<int> joint;   // dominant joint per VPL
  std::vector<int> parents = {-1, 0, 1, 2, 0, 4, 5};  // root, limb A (1–3), limb B (4–6)
};

// Limb a: from (−0.1, 1.2, 0) towards (−0.8, 1.8, 0); limb b: from (0.1, 1.0, 0) to (0.9, 0.4, 0.3).
Character two_limbs(int rings, int segments) {
  const glm::dvec3 start[2] = {{-0.1, 1.2, 0.0}, {0.1, 1.0, 0.0}};
  const glm::dvec3 end[2] = {{-0.8, 1.8, 0.0}, {0.9, 0.4, 0.3}};
  const double radius = 0.06;
  Character out;
  for (int r = 0; r < rings; ++r)
    for (int limb = 0; limb < 2; ++limb) {
      const glm::dvec3 axis = glm::normalize(end[limb] - start[limb]);
      const glm::dvec3 u = glm::normalize(glm::cross(axis, glm::dvec3(0.0, 0.0, 1.0)));
      const glm::dvec3 v = glm::cross(axis, u);
      const double t = (double(r) + 0.5) / double(rings);
      const glm::dvec3 center = glm::mix(start[limb], end[limb], t);
      const double patch = 2.0 * kPi * radius / double(segments) * glm::length(end[limb] - start[limb]) / double(rings);
      for (int s = 0; s < segments; ++s) {
        const double phi = 2.0 * kPi * double(s) / double(segments);
        VirtualPointLight vpl;
        vpl.normal = std::cos(phi) * u + std::sin(phi) * v;
        vpl.position = center + radius * vpl.normal;
        const double sky = 1.0 + 0.6 * vpl.normal.y;  // unshadowed irradiance, > 0
        const glm::dvec3 albedo = limb == 0 ? glm::dvec3(0.9, 0.2, 0.1) : glm::dvec3(0.1, 0.7, 0.3);
        vpl.flux = albedo * sky * patch;
        out.vpls.push_back(vpl);
        out.joint.push_back(1 + 3 * limb + std::min(2, int(3.0 * t)));
      }
    }
  return out;
}

struct Receiver {
  glm::dvec3 position, normal;
};
std::vector<Receiver> receivers() {
  std::vector<Receiver> out;
  for (int i = 0; i <= 12; ++i)
    for (int j = 0; j <= 8; ++j)
      out.push_back({{-1.5 + 0.25 * i, 0.0, -1.0 + 0.25 * j}, {0.0, 1.0, 0.0}});
  // Beside the limbs, facing them: 0.3 m from limb a's middle and from limb b's tip.
  out.push_back({{-0.45, 1.2, 0.3}, glm::normalize(glm::dvec3(0.0, 0.3, -1.0))});
  out.push_back({{0.9, 0.4, 0.6}, {0.0, 0.0, -1.0}});
  out.push_back({{-0.8, 2.1, 0.0}, {0.0, -1.0, 0.0}});
  return out;
}

// Relative RMS error of K VSGLs (VPL i in light group[i]) against brute force.
double relative_rms(const Character& c, const std::vector<int>& group, int k) {
  std::vector<VsglSums> sums(static_cast<std::size_t>(k));
  std::vector<glm::dvec3> origin(static_cast<std::size_t>(k));
  std::vector<bool> started(static_cast<std::size_t>(k), false);
  for (std::size_t i = 0; i < c.vpls.size(); ++i) {
    const std::size_t g = std::size_t(group[i]);
    if (!started[g]) origin[g] = c.vpls[i].position, started[g] = true;
    add_light(sums[g], c.vpls[i], origin[g]);
  }
  double error2 = 0.0, reference2 = 0.0;
  for (const Receiver& r : receivers()) {
    glm::dvec3 approximate(0.0);
    for (std::size_t g = 0; g < sums.size(); ++g)
      if (auto light = fit_vsgl(sums[g], origin[g])) approximate += vsgl_irradiance(*light, r.position, r.normal);
    const glm::dvec3 exact = gather_vpl_irradiance(c.vpls, r.position, r.normal);
    error2 += glm::dot(approximate - exact, approximate - exact);
    reference2 += glm::dot(exact, exact);
  }
  return std::sqrt(error2 / reference2);
}

TEST(VsglGrouping, BoneGroupsBeatIndexRangesOnTwoLimbs) {
  const Character c = two_limbs(24, 12);
  std::vector<std::size_t> counts(c.parents.size(), 0);
  for (int j : c.joint) ++counts[std::size_t(j)];
  for (int k : {2, 4}) {
    SCOPED_TRACE("K = " + std::to_string(k));
    const std::vector<int> node_group = anim::split_joint_tree(c.parents, counts, k);
    std::vector<int> by_bone, by_range;
    for (std::size_t i = 0; i < c.vpls.size(); ++i) {
      by_bone.push_back(node_group[std::size_t(c.joint[i])]);
      by_range.push_back(int(i * std::size_t(k) / c.vpls.size()));
    }
    const double bone = relative_rms(c, by_bone, k), range = relative_rms(c, by_range, k);
    const double one = relative_rms(c, std::vector<int>(c.vpls.size(), 0), 1);
    std::printf("K = %d: relative RMS error vs brute force: bone groups %.4f, index ranges %.4f (K = 1: %.4f)\n", k,
                bone, range, one);
    EXPECT_LT(bone, range);
    EXPECT_LT(bone, one);
  }
}

}  // namespace
}  // namespace proxygi::sh
