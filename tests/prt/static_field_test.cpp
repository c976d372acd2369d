// The run-time form of PRT (prt/static_field.h): the receiver lookup through the grid, the baked
// per-vertex records, and the pass's formula against prt/static_shading.h (the CPU reference
// checked against the path tracer in static_shading_test.cpp).
#include "prt/static_field.h"

#include <gtest/gtest.h>

#include <cmath>

#include "prt/static_shading.h"
#include "prt_scenes.h"
#include "sh/basis.h"
#include "sh/convolution.h"
#include "sh/product.h"

namespace proxygi::prt {
namespace {

constexpr int kOrder = 4;
constexpr std::size_t kN = 16;
constexpr float kSpacing = 0.25f;

struct Corner {
  StaticReceivers receivers = test::wall_corner(kSpacing);
  TransferSet transfer;
  std::shared_ptr<const StaticTransferField> field;
};

const Corner& corner() {
  static const Corner c = [] {
    Corner out;
    auto set = compute_transfer(out.receivers, {.order = kOrder, .directions = 256, .bounces = 2});
    EXPECT_TRUE(set.ok()) << set.message();
    out.transfer = std::move(*set);
    auto field = make_static_field(out.receivers, out.transfer, kSpacing);
    EXPECT_TRUE(field.ok()) << field.message();
    out.field = *field;
    return out;
  }();
  return c;
}

std::array<std::vector<float>, 3> light_floats(const sh::RgbSh& light) {
  return {test::to_float(light.channels[0]), test::to_float(light.channels[1]), test::to_float(light.channels[2])};
}

TEST(PrtStaticField, FindsEveryTriangleAtItsCentroidWithItsOwnWeights) {
  const StaticTransferField& f = *corner().field;
  ASSERT_GT(f.triangles.size(), 100u);
  ASSERT_GT(f.grid.size.x, 0u);
  for (std::size_t t = 0; t < f.triangles.size(); ++t) {
    const glm::uvec3 tri = f.triangles[t];
    const glm::vec3 centroid = (f.positions[tri.x] + f.positions[tri.y] + f.positions[tri.z]) / 3.0f;
    const auto hit = find_static_hit(f, centroid, f.triangle_normals[t]);
    ASSERT_TRUE(hit.has_value()) << "triangle " << t;
    EXPECT_EQ(hit->triangle, t);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(hit->weights[k], 1.0f / 3.0f, 1e-4f) << "triangle " << t;
  }
}

TEST(PrtStaticField, RejectsPointsOffTheSurfaceBackFacesAndOutsideTheGrid) {
  const StaticTransferField& f = *corner().field;
  const glm::vec3 up(0, 1, 0);
  const glm::vec3 on_floor(0.5f, 0.0f, 0.7f);
  ASSERT_TRUE(find_static_hit(f, on_floor, up).has_value());
  EXPECT_TRUE(find_static_hit(f, on_floor + glm::vec3(0, 0.004f, 0), up).has_value());   // within 5 mm
  EXPECT_FALSE(find_static_hit(f, on_floor + glm::vec3(0, 0.01f, 0), up).has_value());   // 1 cm above
  EXPECT_FALSE(find_static_hit(f, on_floor, -up).has_value());                            // the floor's back
  EXPECT_FALSE(find_static_hit(f, on_floor, glm::vec3(1, 0, 0)).has_value());             // side-facing
  EXPECT_FALSE(find_static_hit(f, glm::vec3(40, 0, 40), up).has_value());                 // outside
  // On the wall x = -1 facing +x: its own transfer, not the floor's at the seam.
  const auto wall = find_static_hit(f, glm::vec3(-1.0f, 0.6f, 0.5f), glm::vec3(1, 0, 0));
  ASSERT_TRUE(wall.has_value());
  EXPECT_NEAR(glm::dot(f.triangle_normals[wall->triangle], glm::vec3(1, 0, 0)), 1.0f, 1e-5f);
}

TEST(PrtStaticField, RecordsInterpolateToEachVertexAndHoldItsTransfer) {
  const Corner& c = corner();
  const StaticTransferField& f = *c.field;
  const sh::RgbSh light = test::test_lighting(kOrder);
  const auto l = light_floats(light);
  const std::vector<float> records = bake_static_records(f, light);
  const std::size_t stride = static_record_floats(kOrder);
  ASSERT_EQ(records.size(), f.positions.size() * stride);
  std::vector<float> product(kN);
  for (std::size_t v = 0; v < f.positions.size(); v += 37) {
    const float* r = records.data() + v * stride;
    const float* t = f.shadowed.data() + v * kN;
    const std::vector<double> h = sh::clamped_cosine_about(kOrder, glm::dvec3(f.normals[v]));
    for (std::size_t i = 0; i < kN; ++i) EXPECT_NEAR(r[3 * kN + i], float(h[i]) - t[i], 1e-6f);
    for (int ch = 0; ch < 3; ++ch) {
      sh::product(kOrder, l[std::size_t(ch)], std::span<const float>(t, kN), product);
      for (std::size_t i = 0; i < kN; ++i) EXPECT_FLOAT_EQ(r[std::size_t(ch) * kN + i], product[i]);
      float t_di_l = 0.0f, t_l = 0.0f;
      for (std::size_t i = 0; i < kN; ++i) {
        t_di_l += f.interreflected[(v * 3 + std::size_t(ch)) * kN + i] * l[std::size_t(ch)][i];
        t_l += t[i] * l[std::size_t(ch)][i];
      }
      EXPECT_NEAR(r[4 * kN + 3 + std::size_t(ch)], t_di_l, 1e-5f * std::abs(t_di_l) + 1e-6f);
      EXPECT_NEAR(r[4 * kN + std::size_t(ch)], t_di_l - t_l, 1e-5f * std::abs(t_di_l) + 1e-6f);
    }
  }
  // A hit exactly on a vertex (weight 1) returns that vertex's record.
  const glm::uvec3 tri = f.triangles[f.triangles.size() / 2];
  const StaticHit hit{std::uint32_t(f.triangles.size() / 2), glm::vec3(0, 1, 0)};
  const std::vector<float> at = interpolate_record(f, records, hit);
  for (std::size_t i = 0; i < stride; ++i) EXPECT_FLOAT_EQ(at[i], records[std::size_t(tri.y) * stride + i]);
}

// The pass's formula at the corner's vertices equals static_shading.h's L1 and ratio (the path
// tracer-checked reference) for a proxy-like visibility O_p, with LH = M_L H computed exactly.
TEST(PrtStaticField, ShadingEqualsTheCpuReferenceLevels) {
  const Corner& c = corner();
  const StaticTransferField& f = *c.field;
  const sh::RgbSh light = test::test_lighting(kOrder);
  const auto l = light_floats(light);
  const std::array<std::span<const float>, 3> lights = {l[0], l[1], l[2]};
  const std::vector<float> records = bake_static_records(f, light);
  const std::size_t stride = static_record_floats(kOrder);
  std::vector<float> o(kN, 0.0f);
  o[0] = 0.8f * float(sh::kSqrtFourPi), o[1] = -0.6f, o[2] = 0.3f, o[3] = 0.4f, o[6] = 0.2f;
  int compared = 0, blocked = 0;
  for (std::size_t v = 0; v < f.positions.size(); v += 5) {
    const std::vector<float> h = test::to_float(sh::clamped_cosine_about(kOrder, glm::dvec3(f.normals[v])));
    const std::span<const float> t(f.shadowed.data() + v * kN, kN);
    std::array<std::span<const float>, 3> t_di;
    for (std::size_t ch = 0; ch < 3; ++ch) t_di[ch] = {f.interreflected.data() + (v * 3 + ch) * kN, kN};
    const StaticReceiverSh receiver{h, t, t_di};
    std::array<std::vector<float>, 3> lh;
    for (std::size_t ch = 0; ch < 3; ++ch) {
      lh[ch].resize(kN);
      sh::product(kOrder, l[ch], h, lh[ch]);
    }
    const std::span<const float> record(records.data() + v * stride, stride);
    for (const StaticTransferLevel level : {StaticTransferLevel::l1, StaticTransferLevel::ratio}) {
      const glm::vec3 expected = shade_static_receiver(kOrder, level, receiver, lights, o);
      const glm::vec3 got = shade_static_direct(kOrder, level, record, o, lh);
      for (int ch = 0; ch < 3; ++ch)
        EXPECT_NEAR(got[ch], expected[ch], 2e-4f * std::abs(expected[ch]) + 1e-5f) << "vertex " << v << " channel " << ch;
    }
    ++compared;
    if (h[0] - t[0] > 0.05f * h[0]) ++blocked;
  }
  EXPECT_GT(compared, 100);
  EXPECT_GT(blocked, 10);  // receivers where static geometry matters were among them
}

}  // namespace
}  // namespace proxygi::prt
