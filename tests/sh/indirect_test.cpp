// The averaged indirect operator D: closed form, polynomial fit and numerical integration; the
// exact operator's consistency; the error ordering of paper Figure 5.
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "sh/basis.h"
#include "sh/convolution.h"
#include "sh/indirect.h"
#include "sh/rotation.h"

namespace proxygi::sh {
namespace {

TEST(ShIndirect, ClosedFormMatchesNumericalIntegration) {
  for (double s : {0.05, 0.2, 0.5, 0.8, 0.95}) {
    const std::array<double, 3> closed = averaged_indirect_closed_form(s);
    const std::vector<double> numerical = averaged_indirect_zonal(3, s);
    for (int l = 0; l < 3; ++l) EXPECT_NEAR(closed[std::size_t(l)], numerical[std::size_t(l)], 1e-7) << "s=" << s << " l=" << l;
  }
}

TEST(ShIndirect, PolynomialFitMatchesTheClosedForm) {
  // The paper's fit has relative squared errors of 1.6e-6 (D1) and 6.4e-6 (D2): a few 1e-4.
  for (int k = 1; k < 20; ++k) {
    const double s = k / 20.0;
    const std::array<double, 3> closed = averaged_indirect_closed_form(s), fit = averaged_indirect_polynomial(s);
    EXPECT_NEAR(fit[0], closed[0], 1e-5);
    EXPECT_NEAR(fit[1], closed[1], 1.5e-3) << "s=" << s;
    EXPECT_NEAR(fit[2], closed[2], 1.5e-3) << "s=" << s;
  }
  // Small-angle limit: the visible hemisphere of the proxy weighted by its projected area:
  // D1 -> -y10 * 2/3, D2 -> y20 * 1/2.
  const std::array<double, 3> small = averaged_indirect_closed_form(1e-3);
  EXPECT_NEAR(small[1], -0.4886025119 * 2.0 / 3.0, 1e-3);
  EXPECT_NEAR(small[2], 0.6307831305 * 0.25, 1e-3);
}

TEST(ShIndirect, ExactOperatorOfConstantRadianceIsTheVisibility) {
  // Ltilde = constant c: the proxy shines c over its cap, so I = c V.
  for (double s : {0.2, 0.6}) {
    const Eigen::MatrixXd m = exact_indirect_operator(4, s);
    const std::vector<double> v = proxy_visibility_zonal(4, s);
    for (int l = 0; l < 4; ++l) EXPECT_NEAR(m(coefficient_index(l, 0), 0) * kSqrtFourPi, v[std::size_t(l)], 1e-9);
    for (int i = 0; i < 16; ++i) {
      if (i != coefficient_index(band_of_index(i), 0)) {
        EXPECT_NEAR(m(i, 0), 0.0, 1e-12);
      }
    }
  }
}

TEST(ShIndirect, ExactOperatorRotatesWithTheProxy) {
  // Eq. 17 for a proxy along +z is the canonical operator; along another direction it equals
  // the canonical result of the lighting rotated with it.
  const int order = 3;
  std::vector<double> lighting = {1.2, 0.3, -0.5, 0.2, 0.1, -0.2, 0.3, 0.05, -0.1};
  const std::vector<double> canonical = apply_exact_indirect(order, 0.5, {0, 0, 1}, lighting);
  const Eigen::VectorXd direct = exact_indirect_operator(order, 0.5) * Eigen::Map<const Eigen::VectorXd>(lighting.data(), 9);
  for (int i = 0; i < 9; ++i) EXPECT_NEAR(canonical[std::size_t(i)], direct(i), 1e-10);
  const glm::dvec3 dir = glm::normalize(glm::dvec3(0.3, -0.6, 0.5));
  const Eigen::MatrixXd r = rotation_matrix(order, rotation_between({0, 0, 1}, dir));
  const Eigen::VectorXd turned_lighting = r * Eigen::Map<const Eigen::VectorXd>(lighting.data(), 9);
  std::vector<double> turned(turned_lighting.data(), turned_lighting.data() + 9);
  const std::vector<double> rotated = apply_exact_indirect(order, 0.5, dir, turned);
  const Eigen::VectorXd expected = r * direct;
  for (int i = 0; i < 9; ++i) EXPECT_NEAR(rotated[std::size_t(i)], expected(i), 1e-9);
}

TEST(ShIndirect, AveragedBeatsPointSampledAsInFigure5) {
  for (double s : {0.1, 0.3, 0.5, 0.7, 0.9}) {
    const IndirectOperatorErrors errors = indirect_operator_errors(3, s);
    EXPECT_LT(errors.averaged, errors.point) << "s=" << s;
    EXPECT_NEAR(errors.averaged_polynomial, errors.averaged, 0.01);
  }
  // Both approximations become exact as the proxy shrinks (its disk radiance is ~ constant).
  EXPECT_LT(indirect_operator_errors(3, 0.02).averaged, indirect_operator_errors(3, 0.5).averaged);
}

TEST(ShIndirect, ExactTableRowsAreTheOperator) {
  const ExactIndirectTable table = make_exact_indirect_table(3, 11);
  ASSERT_EQ(table.values.size(), 11u * 81u);
  const Eigen::MatrixXd m = exact_indirect_operator(3, 0.5);  // row 5
  for (int j = 0; j < 9; ++j)
    for (int k = 0; k < 9; ++k) EXPECT_NEAR(table.values[std::size_t((5 * 9 + j) * 9 + k)], m(j, k), 1e-6);
}

TEST(ShIndirect, PointKernelEvaluatesTheLightingOppositeTheProxy) {
  const int order = 4;
  const glm::dvec3 dir = glm::normalize(glm::dvec3(0.1, 0.9, -0.3));
  std::vector<double> kernel(16), basis(16);
  rotate_zonal(order, point_indirect_zonal(order), dir, kernel);
  evaluate_basis(order, -dir, basis);
  for (int i = 0; i < 16; ++i) EXPECT_NEAR(kernel[std::size_t(i)], basis[std::size_t(i)], 1e-12);
}

}  // namespace
}  // namespace proxygi::sh
