// PRT precompute: analytic cases (notes/prt-vsgl.md §2 tests) and determinism.
#include "prt/transfer.h"

#include <gtest/gtest.h>

#include <cmath>

#include "prt_scenes.h"
#include "ref/sampling.h"
#include "sh/convolution.h"
#include "sh/rotation.h"

namespace proxygi::prt {
namespace {

using test::nearest_vertex;
using test::wall_corner;

constexpr double kPi = 3.14159265358979323846;

TransferSet compute(const StaticReceivers& r, const TransferSettings& s, int threads = 0) {
  auto t = compute_transfer(r, s, {}, threads);
  EXPECT_TRUE(t.ok()) << (t.ok() ? "" : t.message());
  return std::move(*t);
}

// Cosine-weighted unoccluded fraction from T_DS: (T · 1) / π = √4π T_0 / π.
double ambient_occlusion(const TransferSet& t, std::size_t surface, std::size_t vertex) {
  const std::size_t nn = std::size_t(t.order * t.order);
  return std::sqrt(4.0 * kPi) * double(t.surfaces[surface].shadowed[vertex * nn]) / kPi;
}

TEST(PrtTransfer, UnoccludedPlaneGivesClampedCosine) {
  // A tilted square alone: nothing blocks any vertex, so T_DS = H(N) and no light bounces.
  StaticReceivers r;
  r.surfaces.push_back(test::quad("tilted", {0, 0, 0}, {2, 1, 0}, {0, 0, 2}, glm::vec3(0.8f), 0.5f));
  const TransferSet t = compute(r, {.order = 4, .directions = 256, .bounces = 1});
  const StaticSurface& s = r.surfaces[0];
  ASSERT_GT(s.positions.size(), 16u);
  for (std::size_t v = 0; v < s.positions.size(); ++v) {
    const std::vector<double> h = sh::clamped_cosine_about(4, glm::dvec3(s.normals[v]));
    for (std::size_t i = 0; i < 16; ++i) {
      ASSERT_NEAR(t.surfaces[0].shadowed[v * 16 + i], h[i], 1e-3) << "vertex " << v << " coefficient " << i;
      for (int c = 0; c < 3; ++c)
        ASSERT_EQ(t.surfaces[0].interreflected[(3 * v + std::size_t(c)) * 16 + i], t.surfaces[0].shadowed[v * 16 + i]);
    }
  }
}

TEST(PrtTransfer, HemisphereSumMatchesMonteCarloAmbientOcclusion) {
  // T · 1 / π against an independent estimate: the path tracer's Embree scene and sampler.
  const StaticReceivers r = wall_corner(0.25f);
  const int k = 2048;
  const TransferSet t = compute(r, {.order = 4, .directions = k, .bounces = 0});
  auto scene = ref::EmbreeScene::build(test::tracer_meshes(r));
  ASSERT_TRUE(scene.ok()) << scene.message();
  const int samples = 20000;
  for (const glm::vec3 p : {glm::vec3(-0.75f, 0, -0.75f), glm::vec3(-0.5f, 0, 0.5f), glm::vec3(0.5f, 0, 0.5f),
                            glm::vec3(1.5f, 0, -0.5f), glm::vec3(-0.25f, 0, 1.5f)}) {
    const std::size_t v = nearest_vertex(r.surfaces[0], p);
    const glm::vec3 x = r.surfaces[0].positions[v] + glm::vec3(0, 1e-4f, 0);
    int open = 0;
    for (int s = 0; s < samples; ++s) {
      ref::SampleStream random(7, std::uint32_t(v), std::uint32_t(s), ref::Sampler::random);
      const glm::vec3 d = ref::sample_cosine_hemisphere(glm::vec3(0, 1, 0), random.next_2d());
      open += scene->occluded(x, d) ? 0 : 1;
    }
    const double mc = double(open) / samples;
    const double prt = ambient_occlusion(t, 0, v);
    // Binomial standard errors of both estimates (the stratified PRT set is at most this noisy).
    const double sigma = std::sqrt(mc * (1 - mc) / samples + mc * (1 - mc) / k);
    EXPECT_NEAR(prt, mc, 4 * sigma + 1e-4) << "floor vertex at " << x.x << ", " << x.z;
  }
}

TEST(PrtTransfer, CornerDarkensTowardTheCorner) {
  const StaticReceivers r = wall_corner(0.1f);
  const TransferSet t = compute(r, {.order = 4, .directions = 1024, .bounces = 1});
  double previous = 1.0;
  for (const float d : {1.9f, 1.2f, 0.8f, 0.5f, 0.3f, 0.2f, 0.1f, 0.0f}) {  // distance from each wall
    const std::size_t v = nearest_vertex(r.surfaces[0], glm::vec3(-1.0f + d, 0, -1.0f + d));
    const double ao = ambient_occlusion(t, 0, v);
    EXPECT_LT(ao, previous) << "at " << d << " m from both walls";
    previous = ao;
  }
  // In the corner itself only the quadrant in front of both walls is open: a quarter of the
  // cosine-weighted hemisphere (the walls, 2 m × 3 m, cover their half-spaces as seen from 1 mm).
  EXPECT_NEAR(previous, 0.25, 0.02);
  // Interreflection only adds light, and the reddish walls tint the floor's bounce red.
  const std::size_t v = nearest_vertex(r.surfaces[0], glm::vec3(-0.8f, 0, -0.8f));
  const SurfaceTransfer& f = t.surfaces[0];
  const float red = f.interreflected[(3 * v + 0) * 16] - f.shadowed[v * 16];
  const float blue = f.interreflected[(3 * v + 2) * 16] - f.shadowed[v * 16];
  EXPECT_GT(blue, 0.0f);
  EXPECT_GT(red, 1.5f * blue);
}

TEST(PrtTransfer, RotatingSceneAndLightingTogetherChangesNothing) {
  const StaticReceivers r = wall_corner(0.25f);
  const glm::dmat3 rotation = sh::rotation_between(glm::dvec3(0, 1, 0), glm::normalize(glm::dvec3(0.3, 0.5, -0.8)));
  StaticReceivers turned = r;
  for (StaticSurface& s : turned.surfaces)
    for (std::size_t i = 0; i < s.positions.size(); ++i) {
      s.positions[i] = glm::vec3(rotation * glm::dvec3(s.positions[i]));
      s.normals[i] = glm::normalize(glm::vec3(rotation * glm::dvec3(s.normals[i])));
    }
  const TransferSettings settings{.order = 4, .directions = 1024, .bounces = 2};
  const TransferSet a = compute(r, settings), b = compute(turned, settings);
  const sh::RgbSh light = test::test_lighting(4);
  const Eigen::MatrixXd rot = sh::rotation_matrix(4, rotation);
  // E = T_DI · L in the original frame, and T'_DI · (R L) in the turned one, per vertex.
  double sum = 0, sum_diff = 0, max_rel = 0;
  for (std::size_t s = 0; s < r.surfaces.size(); ++s)
    for (std::size_t v = 0; v < r.surfaces[s].positions.size(); ++v)
      for (int c = 0; c < 3; ++c) {
        Eigen::VectorXd l = Eigen::Map<const Eigen::VectorXd>(light.channels[std::size_t(c)].data(), 16);
        const Eigen::VectorXd l_turned = rot * l;
        double e = 0, e_turned = 0;
        for (int i = 0; i < 16; ++i) {
          e += a.surfaces[s].interreflected[(3 * v + std::size_t(c)) * 16 + std::size_t(i)] * l[i];
          e_turned += b.surfaces[s].interreflected[(3 * v + std::size_t(c)) * 16 + std::size_t(i)] * l_turned[i];
        }
        sum += e;
        sum_diff += e_turned - e;
        max_rel = std::max(max_rel, std::abs(e_turned - e) / e);
      }
  // Only the per-vertex direction sets differ between the frames: ~1/√K noise per vertex on the
  // blocked part (≤ 3 % of E), and its mean over ~1000 vertex channels is near 0.
  EXPECT_LT(std::abs(sum_diff) / sum, 2e-3);
  EXPECT_LT(max_rel, 0.05);
}

TEST(PrtTransfer, ResultsDoNotDependOnTheThreadCount) {
  const StaticReceivers r = wall_corner(0.3f);
  const TransferSettings settings{.order = 3, .directions = 128, .bounces = 2, .seed = 5};
  const TransferSet one = compute(r, settings, 1), three = compute(r, settings, 3);
  for (std::size_t s = 0; s < r.surfaces.size(); ++s) {
    EXPECT_EQ(one.surfaces[s].shadowed, three.surfaces[s].shadowed);
    EXPECT_EQ(one.surfaces[s].interreflected, three.surfaces[s].interreflected);
  }
  EXPECT_EQ(one.rays, three.rays);
  EXPECT_EQ(one.rays, std::uint64_t(3 * 128) * (r.surfaces[0].positions.size() + r.surfaces[1].positions.size() +
                                                r.surfaces[2].positions.size()));
}

TEST(PrtTransfer, ProgressReachesEveryVertexInEachPass) {
  const StaticReceivers r = wall_corner(0.5f);
  std::size_t total = 0, last_done = 0;
  std::vector<std::string> stages;
  auto t = compute_transfer(r, {.order = 3, .directions = 16, .bounces = 1},
                            [&](std::string_view stage, std::size_t done, std::size_t n) {
                              if (stages.empty() || stages.back() != stage) stages.emplace_back(stage);
                              last_done = done;
                              total = n;
                            });
  ASSERT_TRUE(t.ok());
  EXPECT_EQ(stages, (std::vector<std::string>{"shadow", "bounce 1"}));
  EXPECT_EQ(last_done, total);
}

TEST(PrtTransfer, BadInputIsNamed) {
  StaticReceivers r = wall_corner(0.5f);
  auto bad_order = compute_transfer(r, {.order = 9});
  ASSERT_FALSE(bad_order.ok());
  EXPECT_NE(bad_order.message().find("prt.order 9"), std::string::npos) << bad_order.message();
  r.surfaces[1].indices[4] = 100000;
  auto bad_index = compute_transfer(r, {});
  ASSERT_FALSE(bad_index.ok());
  EXPECT_NE(bad_index.message().find("wall x: index 4 = 100000 out of range"), std::string::npos)
      << bad_index.message();
}

TEST(PrtSurfaces, SubdivisionKeepsAreaAndMeetsTheSpacing) {
  const StaticSurface s = test::quad("q", {0, 0, 0}, {1, 0, 0}, {0, 0, 0.5f}, glm::vec3(1), 0.1f);
  double area = 0, longest = 0;
  for (std::size_t i = 0; i < s.indices.size(); i += 3) {
    const glm::vec3 a = s.positions[s.indices[i]], b = s.positions[s.indices[i + 1]], c = s.positions[s.indices[i + 2]];
    area += 0.5 * glm::length(glm::cross(b - a, c - a));
    longest = std::max({longest, double(glm::length(b - a)), double(glm::length(c - b)), double(glm::length(a - c))});
  }
  EXPECT_NEAR(area, 0.5, 1e-5);
  EXPECT_LE(longest, 0.1 + 1e-6);
  // The diagonal edge shared by the two triangles is welded: a 12×12 grid minus nothing duplicated.
  EXPECT_EQ(s.positions.size(), 13u * 13u);
}

}  // namespace
}  // namespace proxygi::prt
