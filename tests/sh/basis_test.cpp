// The generated basis against the Legendre definition, the notes' table, and orthonormality.
#include <cmath>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "sh/basis.h"
#include "sh/quadrature.h"

namespace proxygi::sh {
namespace {

glm::dvec3 direction_of(double theta, double phi) {
  return {std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
}

TEST(ShBasis, MatchesLegendreDefinitionForAllOrders) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<double> values(64);
  std::vector<float> values_float(64);
  for (int sample = 0; sample < 200; ++sample) {
    const double theta = std::acos(1.0 - 2.0 * unit(random));
    const double phi = 2.0 * kPi * unit(random);
    const glm::dvec3 dir = direction_of(theta, phi);
    for (int order = kMinOrder; order <= kMaxOrder; ++order) {
      evaluate_basis(order, dir, values);
      evaluate_basis(order, glm::vec3(dir), values_float);
      for (int l = 0; l < order; ++l)
        for (int m = -l; m <= l; ++m) {
          const double expected = basis_from_definition(l, m, theta, phi);
          EXPECT_NEAR(values[std::size_t(coefficient_index(l, m))], expected, 1e-12) << "l=" << l << " m=" << m;
          EXPECT_NEAR(values_float[std::size_t(coefficient_index(l, m))], expected, 2e-5) << "l=" << l << " m=" << m;
        }
    }
  }
}

TEST(ShBasis, MatchesTheNotesTable) {
  // sh-math.md section 1 polynomials, at one direction.
  const glm::dvec3 d = glm::normalize(glm::dvec3(0.3, -0.5, 0.8));
  const double x = d.x, y = d.y, z = d.z;
  const double expected[36] = {
      0.282094791773878, -0.488602511902920 * y, 0.488602511902920 * z, -0.488602511902920 * x,
      1.092548430592079 * x * y, -1.092548430592079 * y * z, 0.315391565252520 * (3 * z * z - 1),
      -1.092548430592079 * x * z, 0.546274215296040 * (x * x - y * y),
      -0.590043589926644 * y * (3 * x * x - y * y), 2.890611442640554 * x * y * z,
      -0.457045799464466 * y * (5 * z * z - 1), 0.373176332590115 * z * (5 * z * z - 3),
      -0.457045799464466 * x * (5 * z * z - 1), 1.445305721320277 * z * (x * x - y * y),
      -0.590043589926644 * x * (x * x - 3 * y * y), 2.503342941796705 * x * y * (x * x - y * y),
      -1.770130769779931 * y * z * (3 * x * x - y * y), 0.946174695757560 * x * y * (7 * z * z - 1),
      -0.669046543557289 * y * z * (7 * z * z - 3), 0.105785546915204 * (35 * z * z * z * z - 30 * z * z + 3),
      -0.669046543557289 * x * z * (7 * z * z - 3), 0.473087347878780 * (x * x - y * y) * (7 * z * z - 1),
      -1.770130769779931 * x * z * (x * x - 3 * y * y), 0.625835735449176 * (x * x * x * x - 6 * x * x * y * y + y * y * y * y),
      -0.656382056840170 * y * (5 * x * x * x * x - 10 * x * x * y * y + y * y * y * y),
      8.302649259524165 * x * y * z * (x * x - y * y), -0.489238299435250 * y * (3 * x * x - y * y) * (9 * z * z - 1),
      4.793536784973324 * x * y * z * (3 * z * z - 1), -0.452946651195697 * y * (21 * z * z * z * z - 14 * z * z + 1),
      0.116950322453424 * z * (63 * z * z * z * z - 70 * z * z + 15),
      -0.452946651195697 * x * (21 * z * z * z * z - 14 * z * z + 1),
      2.396768392486662 * z * (x * x - y * y) * (3 * z * z - 1),
      -0.489238299435250 * x * (x * x - 3 * y * y) * (9 * z * z - 1),
      2.075662314881041 * z * (x * x * x * x - 6 * x * x * y * y + y * y * y * y),
      -0.656382056840170 * x * (x * x * x * x - 10 * x * x * y * y + 5 * y * y * y * y)};
  std::vector<double> values(36);
  evaluate_basis(6, d, values);
  for (int i = 0; i < 36; ++i) EXPECT_NEAR(values[std::size_t(i)], expected[i], 1e-12) << "index " << i;
}

TEST(ShBasis, IsOrthonormalUnderQuadrature) {
  const int order = 8;
  const SphereQuadrature quadrature = make_sphere_quadrature(order + 1, 2 * order + 1);
  const int count = coefficient_count(order);
  std::vector<double> gram(static_cast<std::size_t>(count * count), 0.0), basis(static_cast<std::size_t>(count));
  for (std::size_t q = 0; q < quadrature.size(); ++q) {
    evaluate_basis(order, quadrature.directions[q], basis);
    for (int i = 0; i < count; ++i)
      for (int j = 0; j < count; ++j) gram[std::size_t(i * count + j)] += quadrature.weights[q] * basis[std::size_t(i)] * basis[std::size_t(j)];
  }
  for (int i = 0; i < count; ++i)
    for (int j = 0; j < count; ++j) EXPECT_NEAR(gram[std::size_t(i * count + j)], i == j ? 1.0 : 0.0, 1e-12) << i << "," << j;
}

TEST(ShBasis, BandOfIndex) {
  for (int l = 0; l < 8; ++l)
    for (int m = -l; m <= l; ++m) EXPECT_EQ(band_of_index(coefficient_index(l, m)), l);
}

TEST(ShQuadrature, GaussLegendreIntegratesPolynomialsExactly) {
  const GaussLegendreRule rule = gauss_legendre(5);  // exact to degree 9
  double integral = 0.0;
  for (std::size_t k = 0; k < rule.nodes.size(); ++k) integral += rule.weights[k] * std::pow(rule.nodes[k], 8);
  EXPECT_NEAR(integral, 2.0 / 9.0, 1e-14);
}

}  // namespace
}  // namespace proxygi::sh
