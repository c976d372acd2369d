// The proxies' sender light, the lighting above a receiver's tangent plane (sh/sender_light.h):
// against the ground's horizon rule, the complementary half-space, rotations, an independent
// quadrature with the plane as a sharp cut, and a closed form for a uniform sky.
#include <cmath>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "sh/basis.h"
#include "sh/convolution.h"
#include "sh/ground_bounce.h"
#include "sh/quadrature.h"
#include "sh/rotation.h"
#include "sh/sender_light.h"

namespace proxygi::sh {
namespace {

std::vector<double> random_lighting(int order, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  std::vector<double> lighting(std::size_t(order * order));
  for (double& value : lighting) value = uniform(random);
  lighting[0] += 4.0;
  return lighting;
}

glm::dvec3 unit(double x, double y, double z) { return glm::normalize(glm::dvec3(x, y, z)); }

TEST(SenderLight, AboveTheGroundIsTheHorizonRuleWithABlackGround) {
  for (int order : {3, 4, 6}) {
    const std::vector<double> lighting = random_lighting(order, 7u + unsigned(order));
    const std::vector<double> horizon = replace_below_horizon(order, lighting, 0.0);
    const std::vector<double> above = project_above_plane(order, lighting, {0.0, 1.0, 0.0}, 3);
    ASSERT_EQ(above.size(), 9u);
    for (int i = 0; i < 9; ++i) EXPECT_NEAR(above[std::size_t(i)], horizon[std::size_t(i)], 1e-12) << order << " " << i;
  }
}

TEST(SenderLight, ThePlaneAndItsOppositeAddUpToTheWholeLighting) {
  const std::vector<double> lighting = random_lighting(5, 3u);
  for (const glm::dvec3& n : {unit(1, 2, 3), unit(-0.3, -1, 0.2), unit(0, 0, 1)})
    for (int out_order : {3, 5, 6}) {
      const std::vector<double> a = project_above_plane(5, lighting, n, out_order);
      const std::vector<double> b = project_above_plane(5, lighting, -n, out_order);
      for (int i = 0; i < out_order * out_order; ++i) {
        const double whole = i < 25 ? lighting[std::size_t(i)] : 0.0;
        EXPECT_NEAR(a[std::size_t(i)] + b[std::size_t(i)], whole, 1e-12) << i;
      }
      EXPECT_GT(std::abs(a[1] - b[1]), 0.01) << "the halves differ";
    }
}

TEST(SenderLight, TurningLightAndPlaneTogetherTurnsTheResult) {
  const int order = 4;
  const std::vector<double> lighting = random_lighting(order, 11u);
  const glm::dvec3 n = unit(0.4, 0.5, -0.7);
  const glm::dmat3 rotation = rotation_between(unit(0.1, 1, 0.3), unit(1, -0.2, 0.5));
  const Eigen::MatrixXd turn = rotation_matrix(order, rotation);
  const Eigen::VectorXd turned = turn * Eigen::Map<const Eigen::VectorXd>(lighting.data(), Eigen::Index(lighting.size()));
  const std::vector<double> turned_lighting(turned.data(), turned.data() + turned.size());
  const std::vector<double> before = project_above_plane(order, lighting, n, order);
  const std::vector<double> after = project_above_plane(order, turned_lighting, rotation * n, order);
  const Eigen::VectorXd expected = turn * Eigen::Map<const Eigen::VectorXd>(before.data(), Eigen::Index(before.size()));
  for (int i = 0; i < order * order; ++i) EXPECT_NEAR(after[std::size_t(i)], expected(i), 1e-10) << i;
}

TEST(SenderLight, MatchesAMidpointRuleThatCutsAtThePlane) {
  // Independent of the Gauss rule: cells in (θ, φ) about N with exact solid angles, the plane a
  // cell boundary (θ = π/2), N given its own frame.
  const int order = 4;
  const std::vector<double> lighting = random_lighting(order, 5u);
  const glm::dvec3 n = unit(-0.6, 0.3, 0.74);
  const glm::dvec3 t = glm::normalize(glm::cross(n, glm::dvec3(0, 1, 0))), b = glm::cross(n, t);
  constexpr int kRows = 512, kColumns = 1024;
  std::vector<double> expected(9, 0.0), basis(16);
  for (int row = 0; row < kRows; ++row) {
    const double top = 0.5 * kPi * row / kRows, bottom = 0.5 * kPi * (row + 1) / kRows, theta = 0.5 * (top + bottom);
    const double weight = (std::cos(top) - std::cos(bottom)) * 2.0 * kPi / kColumns;
    for (int column = 0; column < kColumns; ++column) {
      const double phi = 2.0 * kPi * (column + 0.5) / kColumns;
      const glm::dvec3 d = std::cos(theta) * n + std::sin(theta) * (std::cos(phi) * t + std::sin(phi) * b);
      evaluate_basis(order, d, basis);
      double radiance = 0.0;
      for (int i = 0; i < 16; ++i) radiance += lighting[std::size_t(i)] * basis[std::size_t(i)];
      for (int i = 0; i < 9; ++i) expected[std::size_t(i)] += weight * radiance * basis[std::size_t(i)];
    }
  }
  const std::vector<double> above = project_above_plane(order, lighting, n, 3);
  for (int i = 0; i < 9; ++i) EXPECT_NEAR(above[std::size_t(i)], expected[std::size_t(i)], 2e-5) << i;
}

TEST(SenderLight, AUniformSkyAboveAPlaneInClosedForm) {
  // L = c: (L U_N)_00 = c √(4π)/2 = c √π, and band 1 = c π y_1m(N) (∫_{s·N>0} s ds = π N),
  // so L̃_N(n) = c π (1 + (N · n))/2 at order 2 (A_0 = π, A_1 = 2π/3); band 2 is 0 (even).
  const double c = 0.7;
  std::vector<double> lighting(16, 0.0);
  lighting[0] = c * kSqrtFourPi;
  const glm::dvec3 n = unit(0.2, -0.9, 0.4);
  const std::vector<double> above = project_above_plane(4, lighting, n, 3);
  EXPECT_NEAR(above[0], c * std::sqrt(kPi), 1e-12);
  std::vector<double> direction(9);
  evaluate_basis(3, n, direction);
  // y_1m(s) = √(3/4π) s_a for its axis a, so ∫_{s·N>0} y_1m = √(3/4π) π N_a = π y_1m(N).
  for (int i = 1; i < 4; ++i) EXPECT_NEAR(above[std::size_t(i)], c * kPi * direction[std::size_t(i)], 1e-12) << i;
  for (int i = 4; i < 9; ++i) EXPECT_NEAR(above[std::size_t(i)], 0.0, 1e-12) << i;
  // The cube's texel: the irradiance of that light at normal m is c π (1 + N·m)/2.
  const LightingCubeMap cube = make_sender_light_cube(4, lighting, 4);
  const glm::dvec3 texel = cube_map_direction(2, 1, 3, 4);
  std::vector<double> stored(cube.values.begin() + std::ptrdiff_t(((2 * 4 + 3) * 4 + 1) * 9),
                             cube.values.begin() + std::ptrdiff_t(((2 * 4 + 3) * 4 + 1) * 9 + 9));
  for (const glm::dvec3& m : {unit(1, 0, 0), unit(0.3, 0.8, -0.2), -texel})
    EXPECT_NEAR(evaluate_expansion(3, stored, m), c * kPi * (1.0 + glm::dot(texel, m)) / 2.0, 2e-6) << m.x;
}

}  // namespace
}  // namespace proxygi::sh
