// The generated sparse triple product against direct quadrature of the product of functions.
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "sh/basis.h"
#include "sh/product.h"
#include "sh/quadrature.h"

namespace proxygi::sh {
namespace {

std::vector<double> random_vector(int order, std::mt19937& random) {
  std::normal_distribution<double> normal(0.0, 1.0);
  std::vector<double> v(std::size_t(order * order));
  for (double& x : v) x = normal(random);
  return v;
}

TEST(ShProduct, SparsityMatchesTheNotes) {
  EXPECT_EQ(ordered_triple_product_count(3), 83);
  EXPECT_EQ(ordered_triple_product_count(4), 353);
  EXPECT_EQ(ordered_triple_product_count(5), 1158);
  EXPECT_EQ(ordered_triple_product_count(6), 2907);
  EXPECT_EQ(triple_product_entries(4).size(), 77u);
}

TEST(ShProduct, MatchesQuadratureOfTheFunctionProduct) {
  std::mt19937 random(3);
  for (int order = kMinProductOrder; order <= kMaxProductOrder; ++order) {
    const std::vector<double> a = random_vector(order, random), b = random_vector(order, random);
    // Project f_a(s) f_b(s) (degree 2(n-1)) back to order n: exact with this rule.
    const SphereQuadrature quadrature = make_sphere_quadrature(2 * order, 4 * order);
    const std::vector<double> expected = project_function(order, quadrature, [&](const glm::dvec3& d) {
      return evaluate_expansion(order, a, d) * evaluate_expansion(order, b, d);
    });
    std::vector<double> got(a.size());
    product(order, a, b, got);
    std::vector<float> af(a.begin(), a.end()), bf(b.begin(), b.end()), fast(a.size()), squared(a.size()), fast_aa(a.size());
    product(order, af, bf, fast);
    square(order, af, squared);
    product(order, af, af, fast_aa);
    for (std::size_t i = 0; i < a.size(); ++i) {
      EXPECT_NEAR(got[i], expected[i], 1e-10) << "order " << order << " index " << i;
      EXPECT_NEAR(fast[i], expected[i], 1e-4 * (1.0 + std::abs(expected[i]))) << "order " << order << " index " << i;
      EXPECT_NEAR(squared[i], fast_aa[i], 1e-4 * (1.0 + std::abs(fast_aa[i])));
    }
  }
}

TEST(ShProduct, ConstantOneIsTheIdentityAndMatrixIsSymmetric) {
  std::mt19937 random(5);
  for (int order = kMinProductOrder; order <= kMaxProductOrder; ++order) {
    std::vector<double> one(std::size_t(order * order), 0.0);
    one[0] = kSqrtFourPi;
    const Eigen::MatrixXd identity = product_matrix(order, one);
    EXPECT_LT((identity - Eigen::MatrixXd::Identity(order * order, order * order)).norm(), 1e-10);
    const Eigen::MatrixXd m = product_matrix(order, random_vector(order, random));
    EXPECT_LT((m - m.transpose()).norm(), 1e-12);
  }
}

}  // namespace
}  // namespace proxygi::sh
