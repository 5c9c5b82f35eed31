// Bernstein machinery checked against direct evaluation (values, finite differences, restriction to
// sub-simplices), never against its own coefficients.
#include "semimesh/ho/bernstein.hpp"
#include "semimesh/ho/element_type.hpp"

#include <gtest/gtest.h>

#include <random>
#include <vector>

namespace semimesh::ho {
namespace {

const std::vector<std::vector<SimplexFactor>>& spaces() {
  static const std::vector<std::vector<SimplexFactor>> all{
      {{3, 4}}, {{2, 3}, {1, 2}}, {{1, 2}, {1, 3}, {1, 1}}, {{1, 5}}, {{3, 0}}};
  return all;
}

BernsteinPolynomial random_polynomial(const std::vector<SimplexFactor>& factors, std::mt19937& rng) {
  std::uniform_real_distribution<double> coefficient(-1.0, 1.0);
  BernsteinPolynomial p(factors);
  for (int i = 0; i < p.size(); ++i) p.coefficients()[i] = coefficient(rng);
  return p;
}

/// A random point of the product domain: per factor a point of its unit simplex.
Eigen::Vector3d random_point(const BernsteinLayout& layout, std::mt19937& rng) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  for (int v = 0; v < layout.num_vars; ++v) {
    double used = 0.0;
    for (int w = 0; w < v; ++w)
      if (layout.var_factor[w] == layout.var_factor[v]) used += point[w];
    point[v] = (1.0 - used) * unit(rng) * 0.7;
  }
  return point;
}

TEST(Bernstein, BasisIsNonNegativePartitionOfUnity) {
  std::mt19937 rng(1);
  for (const auto& factors : spaces()) {
    const auto layout = BernsteinLayout::get(factors);
    for (int trial = 0; trial < 20; ++trial) {
      const Eigen::VectorXd values = BernsteinPolynomial::basis_values(*layout, random_point(*layout, rng));
      EXPECT_NEAR(values.sum(), 1.0, 1e-13);
      EXPECT_GE(values.minCoeff(), 0.0);
    }
  }
}

TEST(Bernstein, SizesMatchPolynomialSpaceDimensions) {
  EXPECT_EQ(BernsteinLayout::get({{3, 4}})->size(), 35);            // C(7, 3)
  EXPECT_EQ(BernsteinLayout::get({{2, 3}, {1, 2}})->size(), 10 * 3);
  EXPECT_EQ(BernsteinLayout::get({{1, 2}, {1, 3}, {1, 1}})->size(), 3 * 4 * 2);
  EXPECT_EQ(BernsteinLayout::get({{3, 4}})->corners.size(), 4u);
  EXPECT_EQ(BernsteinLayout::get({{2, 3}, {1, 2}})->corners.size(), 6u);
  EXPECT_EQ(BernsteinLayout::get({{1, 2}, {1, 3}, {1, 1}})->corners.size(), 8u);
  EXPECT_THROW(BernsteinLayout::get({{3, 1}, {1, 1}}), std::invalid_argument);
}

TEST(Bernstein, CornerCoefficientsAreValues) {
  std::mt19937 rng(2);
  const BernsteinPolynomial p = random_polynomial({{2, 3}, {1, 2}}, rng);
  // Corner (triangle vertex 1, segment end t = 1): free components (3, 0, 2).
  EXPECT_NEAR(p.evaluate({1.0, 0.0, 1.0}), p.coefficients()[p.layout().id_of({3, 0, 2})], 1e-14);
  EXPECT_NEAR(p.evaluate({0.0, 0.0, 0.0}), p.coefficients()[p.layout().id_of({0, 0, 0})], 1e-14);
}

TEST(Bernstein, ProductEvaluatesToProductOfValues) {
  std::mt19937 rng(3);
  const std::vector<std::vector<SimplexFactor>> second{
      {{3, 2}}, {{2, 1}, {1, 3}}, {{1, 1}, {1, 0}, {1, 2}}, {{1, 3}}, {{3, 2}}};
  for (std::size_t s = 0; s < spaces().size(); ++s) {
    const BernsteinPolynomial p = random_polynomial(spaces()[s], rng);
    const BernsteinPolynomial q = random_polynomial(second[s], rng);
    const BernsteinPolynomial pq = p * q;
    for (std::size_t f = 0; f < spaces()[s].size(); ++f)
      EXPECT_EQ(pq.layout().factors[f].degree, spaces()[s][f].degree + second[s][f].degree);
    for (int trial = 0; trial < 10; ++trial) {
      const Eigen::Vector3d x = random_point(p.layout(), rng);
      EXPECT_NEAR(pq.evaluate(x), p.evaluate(x) * q.evaluate(x), 1e-12);
    }
  }
}

/// The factor structures of det J's products for every shape and order (a column's degrees times
/// another's, and the 2 x 2 minor's times the third column's), with every other coefficient of the
/// first operand zero (the skipped terms).
TEST(Bernstein, ProductMatchesPairwiseReferenceBitForBit) {
  std::mt19937 rng(11);
  auto check = [&](const std::vector<SimplexFactor>& fa, const std::vector<SimplexFactor>& fb) {
    BernsteinPolynomial a = random_polynomial(fa, rng);
    for (int i = 0; i < a.size(); i += 2) a.coefficients()[i] = 0.0;
    const BernsteinPolynomial b = random_polynomial(fb, rng);
    const BernsteinPolynomial fast = a * b, reference = multiply_pairwise(a, b);
    ASSERT_EQ(fast.layout_ptr(), reference.layout_ptr());
    for (int k = 0; k < fast.size(); ++k) ASSERT_EQ(fast.coefficients()[k], reference.coefficients()[k]) << k;
  };
  for (int p = 1; p <= kMaxOrder; ++p) {
    check({{3, p - 1}}, {{3, p - 1}});
    check({{3, 2 * p - 2}}, {{3, p - 1}});
    check({{2, p - 1}, {1, p}}, {{2, p}, {1, p - 1}});
    check({{2, 2 * p - 1}, {1, 2 * p - 1}}, {{2, p - 1}, {1, p}});
    check({{1, p - 1}, {1, p}, {1, p}}, {{1, p}, {1, p - 1}, {1, p}});
    check({{1, 2 * p - 1}, {1, 2 * p - 1}, {1, 2 * p}}, {{1, p}, {1, p}, {1, p - 1}});
  }
  for (const auto& factors : spaces()) check(factors, factors);
}

TEST(Bernstein, DerivativeMatchesFiniteDifference) {
  std::mt19937 rng(4);
  for (const auto& factors : spaces()) {
    const BernsteinPolynomial p = random_polynomial(factors, rng);
    for (int var = 0; var < p.layout().num_vars; ++var) {
      const BernsteinPolynomial dp = p.derivative(var);
      for (int trial = 0; trial < 5; ++trial) {
        const Eigen::Vector3d x = random_point(p.layout(), rng);
        const double h = 1e-6;
        Eigen::Vector3d plus = x, minus = x;
        plus[var] += h;
        minus[var] -= h;
        EXPECT_NEAR(dp.evaluate(x), (p.evaluate(plus) - p.evaluate(minus)) / (2 * h), 1e-6);
      }
    }
  }
}

TEST(Bernstein, DivisionByOneMinusUndoesMultiplication) {
  std::mt19937 rng(5);
  const BernsteinPolynomial q = random_polynomial({{1, 2}, {1, 1}, {1, 3}}, rng);
  BernsteinPolynomial one_minus_t({{1, 0}, {1, 0}, {1, 1}});
  one_minus_t.coefficients() << 1.0, 0.0;  // B^1_0(t) = 1 - t
  const BernsteinPolynomial back = (q * one_minus_t).divide_by_one_minus(2);
  ASSERT_EQ(back.size(), q.size());
  EXPECT_LT((back.coefficients() - q.coefficients()).cwiseAbs().maxCoeff(), 1e-13);
}

TEST(Bernstein, BisectionPiecesReproduceTheParent) {
  std::mt19937 rng(6);
  const BernsteinPolynomial p = random_polynomial({{3, 4}}, rng);
  // Tetrahedron vertices in lambda_1..3 coordinates; split edge (1, 3).
  const std::array<Eigen::Vector3d, 4> vertex{Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 0, 0),
                                              Eigen::Vector3d(0, 1, 0), Eigen::Vector3d(0, 0, 1)};
  const Eigen::Vector3d midpoint = 0.5 * (vertex[1] + vertex[3]);
  BernsteinPolynomial first(p.layout_ptr()), second(p.layout_ptr());
  p.bisect(0, 1, 3, first, second);
  for (int trial = 0; trial < 10; ++trial) {
    const Eigen::Vector3d mu = random_point(p.layout(), rng);
    const double mu0 = 1.0 - mu.sum();
    // first: vertex 3 replaced by the midpoint; second: vertex 1 replaced by the midpoint.
    const Eigen::Vector3d in_first = mu0 * vertex[0] + mu[0] * vertex[1] + mu[1] * vertex[2] + mu[2] * midpoint;
    const Eigen::Vector3d in_second = mu0 * vertex[0] + mu[0] * midpoint + mu[1] * vertex[2] + mu[2] * vertex[3];
    EXPECT_NEAR(first.evaluate(mu), p.evaluate(in_first), 1e-12);
    EXPECT_NEAR(second.evaluate(mu), p.evaluate(in_second), 1e-12);
  }
  // Edge through the implicit vertex 0 of a segment factor: halves [0, 1/2] and [1/2, 1].
  const BernsteinPolynomial s = random_polynomial({{2, 2}, {1, 3}}, rng);
  BernsteinPolynomial low(s.layout_ptr()), high(s.layout_ptr());
  s.bisect(1, 0, 1, low, high);
  for (double t : {0.0, 0.3, 1.0}) {
    EXPECT_NEAR(low.evaluate({0.2, 0.3, t}), s.evaluate({0.2, 0.3, 0.5 * t}), 1e-12);
    EXPECT_NEAR(high.evaluate({0.2, 0.3, t}), s.evaluate({0.2, 0.3, 0.5 + 0.5 * t}), 1e-12);
  }
}

TEST(Bernstein, ElevationKeepsTheFunction) {
  const Eigen::MatrixXd e = bernstein_elevation_1d(2, 5);
  const auto low = BernsteinLayout::get({{1, 2}});
  const auto high = BernsteinLayout::get({{1, 5}});
  for (double t : {0.0, 0.25, 0.8, 1.0}) {
    const Eigen::VectorXd b_low = BernsteinPolynomial::basis_values(*low, {t, 0, 0});
    const Eigen::VectorXd b_high = BernsteinPolynomial::basis_values(*high, {t, 0, 0});
    for (int i = 0; i <= 2; ++i) EXPECT_NEAR(b_low[i], b_high.dot(e.col(i)), 1e-14);
  }
}

}  // namespace
}  // namespace semimesh::ho
