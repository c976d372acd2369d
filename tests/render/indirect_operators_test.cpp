// CPU twins of the three indirect operators (render::accumulate_indirect, render/exact_indirect.h)
// against the double-precision operators of sh/indirect.h, which use no table and Eigen's SH
// rotation matrices.
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "render/exact_indirect.h"
#include "render/frame_tables.h"
#include "render/shading.h"
#include "sh/basis.h"
#include "sh/convolution.h"
#include "sh/environment.h"
#include "sh/indirect.h"
#include "sh/rotation.h"
#include "sh/sender_light.h"

namespace proxygi::render {
namespace {

constexpr double kPi = 3.14159265358979323846;

// H(N): the clamped cosine rotated to N (order 3).
std::vector<double> cosine_lobe(const glm::dvec3& normal) {
  const double cosine[3] = {0.886226925452758, 1.023326707946489, 0.495415912200751};
  std::vector<double> h(9);
  sh::evaluate_basis(3, normal, h);
  for (int l = 0; l < 3; ++l)
    for (int m = -l; m <= l; ++m) h[std::size_t(l * (l + 1) + m)] *= std::sqrt(4.0 * kPi / (2 * l + 1)) * cosine[l];
  return h;
}

double norm(const std::vector<double>& v) {
  double sum = 0.0;
  for (double x : v) sum += x * x;
  return std::sqrt(sum);
}

glm::dvec3 unit(double x, double y, double z) { return glm::normalize(glm::dvec3(x, y, z)); }

const std::vector<double> kLighting = {2.1, 0.45, -0.7, 0.3, 0.25, -0.35, 0.2, 0.12, -0.18};

TEST(RenderExactIndirect, RotationTakesTheDirectionToZ) {
  for (const glm::dvec3& d : {unit(0, 0, 1), unit(0, 0, -1), unit(1, 2, 3), unit(-0.3, 0.1, -0.9), unit(1, 0, 0)}) {
    const auto rows = rotation_to_z(glm::vec3(d));
    EXPECT_NEAR(glm::dot(rows[0], rows[1]), 0.0f, 1e-6f);
    EXPECT_NEAR(glm::length(rows[0]), 1.0f, 1e-6f);
    EXPECT_NEAR(glm::length(rows[1]), 1.0f, 1e-6f);
    EXPECT_LE(glm::length(glm::cross(rows[0], rows[1]) - rows[2]), 1e-6f) << "right-handed, det +1";
  }
}

// The twin's W · L̃ against H(N) · apply_exact_indirect (double, no table). The twin differs by
// the table's linear interpolation in s and by float rounding, so the allowed error is bounded by
// Cauchy–Schwarz (SH rotations are orthogonal): |ΔE| ≤ ‖H‖ ‖ΔM‖_F ‖L̃‖, with ΔM the Frobenius
// distance between M(s) and the rows' linear interpolation (computed here in double at the very
// rows the table holds), plus a float allowance of 1e-5 ‖M(s)‖_F.
TEST(RenderExactIndirect, TwinMatchesTheDoubleOperatorWithinTheTableInterpolationError) {
  const int rows = 256;
  const sh::ExactIndirectTable table = sh::make_exact_indirect_table(3, rows);
  const glm::dvec3 directions[] = {unit(0, 0, 1), unit(0.2, -0.1, -1), unit(1, 2, 3), unit(-0.6, 0.7, 0.2),
                                   unit(0.3, -0.9, 0.1)};
  const glm::dvec3 normals[] = {unit(0, 1, 0), unit(0.5, 0.5, 0.7), unit(-0.2, 0.1, 0.97)};
  int compared = 0;
  double worst_interpolation = 0.0, worst_used = 0.0;
  for (double s : {0.15, 0.3137, 0.5, 0.7001, 0.85, 0.95, 0.99}) {
    const int row = int(s * (rows - 1));
    const double s0 = double(row) / (rows - 1), s1 = double(row + 1) / (rows - 1), t = s * (rows - 1) - row;
    const Eigen::MatrixXd exact = sh::exact_indirect_operator(3, s);
    const Eigen::MatrixXd lerp = (1 - t) * sh::exact_indirect_operator(3, s0) + t * sh::exact_indirect_operator(3, s1);
    const double interpolation = (lerp - exact).norm();
    if (s <= 0.95) worst_interpolation = std::max(worst_interpolation, interpolation / exact.norm());
    for (const glm::dvec3& d : directions)
      for (const glm::dvec3& n : normals) {
        const std::vector<double> h = cosine_lobe(n);
        const std::vector<double> radiance = sh::apply_exact_indirect(3, s, d, kLighting);
        double expected = 0.0;
        for (int i = 0; i < 9; ++i) expected += h[std::size_t(i)] * radiance[std::size_t(i)];
        const std::array<float, 9> w = exact_indirect_weights(table, float(s), glm::vec3(d), glm::vec3(n));
        double twin = 0.0;
        for (int i = 0; i < 9; ++i) twin += double(w[std::size_t(i)]) * kLighting[std::size_t(i)];
        const double bound = norm(h) * norm(kLighting) * (interpolation + 1e-5 * exact.norm());
        EXPECT_LE(std::abs(twin - expected), bound) << "s=" << s << " d=" << d.x << "," << d.y << "," << d.z;
        worst_used = std::max(worst_used, std::abs(twin - expected) / bound);
        ++compared;
      }
  }
  EXPECT_EQ(compared, 105);
  // The table resolution: at 256 rows linear interpolation moves M by < 2e-4 of ‖M‖_F for
  // 0.15 ≤ s ≤ 0.95 (measured 1.6e-4, at s = 0.15; M steepens again towards s = 1).
  EXPECT_LT(worst_interpolation, 2e-4);
  std::printf("exact twin: M interpolation error <= %.1e of |M| for s <= 0.95; worst error %.2f of its bound\n",
              worst_interpolation, worst_used);
}

TEST(RenderExactIndirect, TableIsZeroOutsideTheEqualMEntries) {
  // Why the twin and the shader read only kExactIndirectEntries.
  const sh::ExactIndirectTable table = sh::make_exact_indirect_table(3, 256);
  bool used[81] = {};
  for (int entry : kExactIndirectEntries) used[entry] = true;
  for (int row = 0; row < table.rows; ++row) {
    float largest = 0.0f, skipped = 0.0f;
    for (int e = 0; e < 81; ++e) {
      const float value = std::abs(table.values[std::size_t(row) * 81 + std::size_t(e)]);
      float& bucket = used[e] ? largest : skipped;
      bucket = std::max(bucket, value);
    }
    EXPECT_LE(skipped, 1e-6f * largest) << "row " << row;
  }
}

TEST(RenderExactIndirect, WrongRotationWouldFail) {
  // The test above can fail: the canonical (unrotated) operator differs from the rotated one by
  // far more than the interpolation bound for a tilted proxy.
  const sh::ExactIndirectTable table = sh::make_exact_indirect_table(3, 256);
  const glm::dvec3 d = unit(1, 2, 3), n = unit(0, 1, 0);
  const std::vector<double> h = cosine_lobe(n);
  const std::vector<double> rotated = sh::apply_exact_indirect(3, 0.5, d, kLighting);
  const std::vector<double> canonical = sh::apply_exact_indirect(3, 0.5, {0, 0, 1}, kLighting);
  double a = 0.0, b = 0.0;
  for (int i = 0; i < 9; ++i) {
    a += h[std::size_t(i)] * rotated[std::size_t(i)];
    b += h[std::size_t(i)] * canonical[std::size_t(i)];
  }
  EXPECT_GT(std::abs(a - b), 0.05 * std::abs(a));
}

// A receiver at the origin with normal +y and one proxy fully above its horizon (no tangent-plane
// adjustment): the twins' unnormalized sums (occlusion_dc = 0 makes ξ_p clamp to 1) against the
// double operators R⁻¹ X(s) R L̃ dotted with H(N).
struct SingleProxy {
  glm::dvec3 center;
  double radius;
};

TEST(RenderIndirectTwin, EachOperatorMatchesItsDoubleOperatorForOneProxy) {
  settings::RenderSettings settings;
  settings.sh_order = 3;
  settings.sh_window = false;
  // The paper's sender light (L̃ for every receiver): the tolerances below are the operators'
  // relative errors on a well-lit proxy; the masked light leaves the proxy overhead too dim for them.
  settings.mask_sender_light = false;
  sh::RgbSh sky;
  sky.order = 3;
  // L̃ = L * clamped cosine: pick L so that L̃ = kLighting (times a per-channel factor).
  const double convolution[3] = {kPi, 2.0 * kPi / 3.0, kPi / 4.0};
  for (int c = 0; c < 3; ++c) {
    sky.channels[std::size_t(c)].resize(9);
    for (int i = 0; i < 9; ++i)
      sky.channels[std::size_t(c)][std::size_t(i)] = (1.0 + 0.2 * c) * kLighting[std::size_t(i)] / convolution[sh::band_of_index(i)];
  }
  const FrameTables tables = make_frame_tables(sky, settings);
  const glm::dvec3 normal(0, 1, 0);
  const std::vector<double> h = cosine_lobe(normal);
  const glm::vec3 albedo(0.5f, 0.6f, 0.7f);
  for (const SingleProxy& proxy : {SingleProxy{{0.3, 1.5, -0.2}, 0.6}, SingleProxy{{-1.0, 0.9, 0.5}, 0.3},
                                   SingleProxy{{0.1, 3.0, 0.2}, 1.2}}) {
    const double distance = glm::length(proxy.center);
    const double s = proxy.radius / distance;
    const glm::dvec3 d = proxy.center / distance;
    const Sphere sphere{glm::vec3(proxy.center), float(proxy.radius), albedo};
    const Eigen::MatrixXd rotation = sh::rotation_matrix(3, sh::rotation_between(d, {0.0, 0.0, 1.0}));
    struct Case {
      settings::IndirectOperator op;
      Eigen::MatrixXd canonical;
      double tolerance;  // relative
    };
    // point: V table interpolation and float rounding only; exact: also M's interpolation
    // (< 1e-3 at 256 rows, see above); averaged: the paper's polynomial fit of D (< 1.5e-3
    // absolute per band, sh indirect_test) against numerically integrated D.
    const Case cases[] = {{settings::IndirectOperator::point, sh::point_indirect_operator(3, s), 1e-4},
                          {settings::IndirectOperator::exact, sh::exact_indirect_operator(3, s), 1e-3},
                          {settings::IndirectOperator::averaged, sh::averaged_indirect_operator(3, s), 5e-3}};
    const auto light = sender_light(tables, glm::vec3(normal));
    for (const Case& test : cases) {
      const IndirectResult twin = accumulate_indirect(tables, glm::vec3(0.0f), glm::vec3(normal), std::span<const Sphere>(&sphere, 1), 0.0f, test.op);
      for (int c = 0; c < 3; ++c) {
        Eigen::VectorXd lighting(9);
        for (int i = 0; i < 9; ++i) lighting(i) = light[std::size_t(c)][std::size_t(i)];
        const Eigen::VectorXd radiance = rotation.transpose() * (test.canonical * (rotation * lighting));
        double shade = 0.0;
        for (int i = 0; i < 9; ++i) shade += h[std::size_t(i)] * radiance(i);
        const double expected = albedo[c] / kPi * std::max(shade, 0.0);
        ASSERT_GT(expected, 1e-3) << "the sample must be lit";
        EXPECT_NEAR(twin.irradiance[c], expected, test.tolerance * expected)
            << settings::name_of(test.op) << " s=" << s << " channel " << c;
      }
    }
  }
}

TEST(RenderIndirectTwin, AllOperatorsAgreeUnderConstantRadiance) {
  // Constant L̃: the proxy shines the same over its whole cap, so point, averaged and exact give
  // the same I = L̃_0 y_0 V (up to the D_0 fit, 1.7e-5 relative, and table rounding). The sender
  // light is unmasked: above a receiver's plane a constant sky is no longer constant.
  settings::RenderSettings settings;
  settings.sh_order = 3;
  settings.mask_sender_light = false;
  sh::RgbSh sky;
  sky.order = 3;
  for (auto& channel : sky.channels) channel.assign(9, 0.0);
  for (int c = 0; c < 3; ++c) sky.channels[std::size_t(c)][0] = 3.5449077 * (1.0 + c);
  const FrameTables tables = make_frame_tables(sky, settings);
  const std::vector<Sphere> spheres = {{{0.0f, 0.8f, 0.0f}, 0.5f, {0.9f, 0.1f, 0.1f}},
                                       {{0.7f, 0.3f, 0.4f}, 0.3f, {0.1f, 0.2f, 0.9f}}};
  int lit = 0;
  for (float x = -2.0f; x <= 2.0f; x += 0.25f)
    for (float z = -2.0f; z <= 2.0f; z += 0.5f) {
      const glm::vec3 p(x, 0.0f, z), n(0.0f, 1.0f, 0.0f);
      const IndirectResult averaged = accumulate_indirect(tables, p, n, spheres, 1.0f, settings::IndirectOperator::averaged);
      for (settings::IndirectOperator op : {settings::IndirectOperator::point, settings::IndirectOperator::exact}) {
        const IndirectResult other = accumulate_indirect(tables, p, n, spheres, 1.0f, op);
        EXPECT_NEAR(other.summed_solid_angle, averaged.summed_solid_angle, 1e-6f);
        for (int c = 0; c < 3; ++c)
          EXPECT_NEAR(other.irradiance[c], averaged.irradiance[c], 1e-4f * averaged.irradiance[c] + 1e-7f)
              << settings::name_of(op) << " at " << x << "," << z;
      }
      if (averaged.irradiance.r > 1e-3f) ++lit;
    }
  EXPECT_GE(lit, 10);
}

// The sender light the indirect twin reads (render::sender_light, FrameTables::sender_light_cube):
// at a texel centre the cube holds L̃_N = A_l (L U_N) of the frame's (windowed) lighting; between
// texels it interpolates within 1 % of the exact value; off (render.mask_sender_light false), it is
// L̃ exactly at any normal, the paper's sender.
TEST(RenderIndirectTwin, SenderLightIsTheLightingAboveTheReceiversPlane) {
  settings::RenderSettings settings;
  sh::RgbSh sky;
  sky.order = 4;
  for (int c = 0; c < 3; ++c) {
    sky.channels[std::size_t(c)].assign(16, 0.0);
    sky.channels[std::size_t(c)][0] = 3.5 + c;
    sky.channels[std::size_t(c)][2] = 1.5;   // brighter above
    sky.channels[std::size_t(c)][3] = -0.8;  // and to one side
    sky.channels[std::size_t(c)][6] = 0.4;
  }
  const FrameTables tables = make_frame_tables(sky, settings);
  const std::vector<double> cosine = sh::clamped_cosine_zonal(3);
  auto exact = [&](int c, const glm::dvec3& n) {
    std::vector<double> light = sh::project_above_plane(4, tables.lighting.channels[std::size_t(c)], n, 3);
    sh::convolve_zonal(3, cosine, light);
    return light;
  };
  const int size = tables.sender_light_cube[0].face_size;
  const glm::dvec3 centre = sh::cube_map_direction(4, 3, 5, size);
  const auto at_centre = sender_light(tables, glm::vec3(centre));
  for (int c = 0; c < 3; ++c) {
    const std::vector<double> expected = exact(c, centre);
    for (int i = 0; i < 9; ++i)
      EXPECT_NEAR(at_centre[std::size_t(c)][std::size_t(i)], expected[std::size_t(i)], 1e-5 * std::abs(expected[0])) << c << " " << i;
  }
  for (const glm::dvec3& n : {glm::normalize(glm::dvec3(0.3, 0.9, -0.2)), glm::normalize(glm::dvec3(-1, 0.1, 0.45)),
                              glm::normalize(glm::dvec3(0.2, -1, 0.7))}) {
    const auto between = sender_light(tables, glm::vec3(n));
    for (int c = 0; c < 3; ++c) {
      const std::vector<double> expected = exact(c, n);
      for (int i = 0; i < 9; ++i)
        EXPECT_NEAR(between[std::size_t(c)][std::size_t(i)], expected[std::size_t(i)], 0.01 * std::abs(expected[0])) << c << " " << i;
    }
    // The masked light differs from L̃ by far more than the interpolation.
    EXPECT_GT(std::abs(between[0][0] - tables.irradiance_order3[0][0]), 0.1 * std::abs(tables.irradiance_order3[0][0]));
  }
  settings.mask_sender_light = false;
  const FrameTables paper = make_frame_tables(sky, settings);
  for (const glm::vec3& n : {glm::vec3(0, 1, 0), glm::normalize(glm::vec3(0.3f, -0.4f, 0.8f))})
    EXPECT_EQ(sender_light(paper, n), paper.irradiance_order3);
}

}  // namespace
}  // namespace proxygi::render
