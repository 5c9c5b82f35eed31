// The split's map along lattice lines (splitting/lattice_lines.hpp) against the full Lagrange basis
// (map_points), and its linear weights against the order-1 basis.
#include "splitting/lattice_lines.hpp"

#include "semimesh/ho/basis.hpp"

#include <gtest/gtest.h>

#include <array>
#include <random>
#include <string>
#include <vector>

namespace semimesh::ho {
namespace {

struct Case {
  Shape shape;
  std::array<int, 2> directions;
};

const std::vector<Case>& cases() {
  static const std::vector<Case> all = {
      {Shape::Prism, {2, -1}},      {Shape::Hexahedron, {0, -1}}, {Shape::Hexahedron, {1, -1}},
      {Shape::Hexahedron, {2, -1}}, {Shape::Hexahedron, {0, 1}},  {Shape::Hexahedron, {2, 0}},
      {Shape::Hexahedron, {1, 2}}};
  return all;
}

// Curved element nodes: the reference nodes moved by a smooth non-polynomial field plus noise, so
// every basis function carries weight.
Eigen::MatrixX3d curved_nodes(Shape shape, int order, NodeSet set, std::mt19937& random) {
  std::uniform_real_distribution<double> noise(-0.05, 0.05);
  const Eigen::MatrixX3d r = reference_nodes(shape, order, set);
  Eigen::MatrixX3d x(r.rows(), 3);
  for (Eigen::Index i = 0; i < r.rows(); ++i) {
    x(i, 0) = 2.0 * r(i, 0) + 0.3 * std::sin(r(i, 1) + r(i, 2)) + noise(random);
    x(i, 1) = r(i, 1) + 0.2 * r(i, 0) * r(i, 2) + noise(random);
    x(i, 2) = 0.5 * r(i, 2) + 0.1 * std::exp(r(i, 0)) + noise(random);
  }
  return x;
}

TEST(LatticeLines, MapAlongLinesIsTheFullBasisOnEveryShapeDirectionOrderAndNodeSet) {
  std::mt19937 random(11);
  std::uniform_real_distribution<double> along(-1.0, 1.0);
  for (const Case& c : cases())
    for (NodeSet set : {NodeSet::Equispaced, NodeSet::GLL})
      for (int order = 1; order <= kMaxOrder; ++order) {
        // The highest orders' reference basis is slow: every order up to 6, the top one on two cases.
        if (order > 6 && order < kMaxOrder) continue;
        if (order == kMaxOrder && c.directions != std::array<int, 2>{2, -1} && c.directions != std::array<int, 2>{0, 1})
          continue;
        SCOPED_TRACE(to_string(c.shape) + " directions " + std::to_string(c.directions[0]) + "," +
                     std::to_string(c.directions[1]) + " order " + std::to_string(order) +
                     (set == NodeSet::GLL ? " GLL" : " equispaced"));
        const detail::LatticeLines lines = detail::lattice_lines(c.shape, order, set, c.directions);
        const Eigen::MatrixX3d X = curved_nodes(c.shape, order, set, random);
        const Eigen::MatrixX3d r = reference_nodes(c.shape, order, set);
        // Three points per node: each node's own coordinates but along the lines' directions.
        Eigen::MatrixX3d q(3 * r.rows(), 3);
        for (Eigen::Index k = 0; k < q.rows(); ++k) {
          q.row(k) = r.row(k % r.rows());
          for (int s = 0; s < 2; ++s)
            if (c.directions[s] >= 0) q(k, c.directions[s]) = along(random);
        }
        const Eigen::MatrixX3d fast = detail::map_along_lines(lines, X, q);
        const Eigen::MatrixX3d reference = map_points(LagrangeBasis(c.shape, order, set), X, q);
        ASSERT_EQ(fast.rows(), reference.rows());
        EXPECT_LT((fast - reference).cwiseAbs().maxCoeff(), 1e-11 * (1.0 + reference.cwiseAbs().maxCoeff()));
        // At a node's own place the map gives the node.
        for (Eigen::Index i = 0; i < r.rows(); ++i) {
          const std::array<double, 2> own{r(i, c.directions[0]), c.directions[1] >= 0 ? r(i, c.directions[1]) : 0.0};
          EXPECT_LT((detail::map_along_line(lines, X, static_cast<int>(i), own) - X.row(i).transpose()).norm(), 1e-12);
        }
      }
}

TEST(LatticeLines, LinearWeightsAreTheOrderOneBasis) {
  std::mt19937 random(5);
  std::uniform_real_distribution<double> coordinate(-1.0, 1.0), unit(0.0, 1.0);
  for (Shape shape : {Shape::Prism, Shape::Hexahedron}) {
    const LagrangeBasis linear(shape, 1);
    for (int k = 0; k < 50; ++k) {
      Eigen::RowVector3d r(coordinate(random), coordinate(random), coordinate(random));
      if (shape == Shape::Prism) r(0) = unit(random), r(1) = (1.0 - r(0)) * unit(random);
      const std::array<double, 8> w = detail::linear_weights(shape, r);
      const Eigen::MatrixXd reference = linear.values(Eigen::MatrixX3d(r));
      for (int v = 0; v < 8; ++v)
        EXPECT_NEAR(w[v], v < reference.cols() ? reference(0, v) : 0.0, 1e-14) << to_string(shape) << " vertex " << v;
    }
  }
}

TEST(LatticeLines, RefusesShapesAndDirectionsWithoutTensorLines) {
  EXPECT_THROW(detail::lattice_lines(Shape::Tetrahedron, 2, NodeSet::Equispaced, {0, -1}), std::invalid_argument);
  EXPECT_THROW(detail::lattice_lines(Shape::Prism, 2, NodeSet::Equispaced, {0, -1}), std::invalid_argument);
  EXPECT_THROW(detail::lattice_lines(Shape::Prism, 2, NodeSet::Equispaced, {2, 0}), std::invalid_argument);
  EXPECT_THROW(detail::lattice_lines(Shape::Hexahedron, 2, NodeSet::Equispaced, {1, 1}), std::invalid_argument);
  EXPECT_THROW(detail::lattice_lines(Shape::Hexahedron, 2, NodeSet::Equispaced, {3, -1}), std::invalid_argument);
  EXPECT_THROW(detail::linear_weights(Shape::Pyramid, Eigen::RowVector3d::Zero()), std::invalid_argument);
}

}  // namespace
}  // namespace semimesh::ho
