// Lagrange bases: Kronecker property, exact interpolation of the element's space, gradients,
// partition of unity, conditioning, element map and Jacobians.
#include "semimesh/ho/basis.hpp"
#include "all_shapes.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <cmath>
#include <iostream>
#include <random>
#include <stdexcept>

namespace semimesh::ho {
namespace {

using testing::kAllShapes;
using testing::kSets;

std::string describe(Shape shape, int p, NodeSet set) {
  return to_string(shape) + " P=" + std::to_string(p) + (set == NodeSet::GLL ? " GLL" : " equispaced");
}

// Random points strictly inside the reference element, by rejection from its bounding box.
Eigen::MatrixX3d random_points(Shape shape, int count, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Eigen::MatrixX3d points(count, 3);
  for (int i = 0; i < count;) {
    Eigen::Vector3d x(u(rng), u(rng), u(rng));
    bool ok = false;
    switch (shape) {
      case Shape::Segment: x.y() = x.z() = 0; ok = true; break;
      case Shape::Quadrilateral: x.z() = 0; ok = true; break;
      case Shape::Hexahedron: ok = true; break;
      case Shape::Triangle: x = 0.5 * (x + Eigen::Vector3d::Ones()); x.z() = 0; ok = x.x() + x.y() < 1; break;
      case Shape::Tetrahedron: x = 0.5 * (x + Eigen::Vector3d::Ones()); ok = x.sum() < 1; break;
      case Shape::Prism: x.head<2>() = 0.5 * (x.head<2>() + Eigen::Vector2d::Ones()); ok = x.x() + x.y() < 1; break;
      case Shape::Pyramid:
        x.z() = 0.5 * (x.z() + 1.0);
        ok = std::abs(x.x()) < 1 - x.z() && std::abs(x.y()) < 1 - x.z();
        break;
    }
    if (ok) points.row(i++) = x.transpose();
  }
  return points;
}

// A random polynomial of the element's space, known in closed form: sum of c * x^a y^b z^c over the
// exponents the space contains (total degree <= P for simplices and pyramids, per-variable <= P for
// tensor shapes, (a+b <= P, c <= P) for prisms). The pyramid's space contains P_P (Bergot et al.).
struct Polynomial {
  std::vector<std::array<int, 3>> exponents;
  std::vector<double> coefficients;
  double operator()(const Eigen::Vector3d& x) const {
    double sum = 0.0;
    for (std::size_t i = 0; i < exponents.size(); ++i)
      sum += coefficients[i] * std::pow(x.x(), exponents[i][0]) * std::pow(x.y(), exponents[i][1]) *
             std::pow(x.z(), exponents[i][2]);
    return sum;
  }
};

Polynomial random_polynomial(Shape shape, int p, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> coefficient(-1.0, 1.0);
  const int dim = dimension(shape);
  Polynomial poly;
  for (int a = 0; a <= p; ++a)
    for (int b = 0; b <= (dim >= 2 ? p : 0); ++b)
      for (int c = 0; c <= (dim == 3 ? p : 0); ++c) {
        bool in_space = false;
        switch (shape) {
          case Shape::Segment:
          case Shape::Quadrilateral:
          case Shape::Hexahedron: in_space = true; break;
          case Shape::Triangle:
          case Shape::Tetrahedron:
          case Shape::Pyramid: in_space = a + b + c <= p; break;
          case Shape::Prism: in_space = a + b <= p; break;
        }
        if (in_space) {
          poly.exponents.push_back({a, b, c});
          poly.coefficients.push_back(coefficient(rng));
        }
      }
  return poly;
}

TEST(LagrangeBasis, KroneckerAtNodesAllShapesOrdersAndSets) {
  for (Shape shape : kAllShapes)
    for (NodeSet set : kSets)
      for (int p = 1; p <= kMaxOrder; ++p) {
        const LagrangeBasis basis(shape, p, set);
        ASSERT_EQ(basis.size(), num_nodes(shape, p));
        const Eigen::MatrixXd v = basis.values(basis.nodes());
        const double error = (v - Eigen::MatrixXd::Identity(basis.size(), basis.size())).cwiseAbs().maxCoeff();
        EXPECT_LT(error, 1e-9) << describe(shape, p, set);
      }
}

TEST(LagrangeBasis, InterpolatesItsSpaceExactlyAndSumsToOne) {
  for (Shape shape : kAllShapes)
    for (NodeSet set : kSets)
      for (int p : {1, 2, 3, 5, 8}) {
        const LagrangeBasis basis(shape, p, set);
        const Polynomial poly = random_polynomial(shape, p, 17u * p + 3u);
        Eigen::VectorXd at_nodes(basis.size());
        for (int i = 0; i < basis.size(); ++i) at_nodes[i] = poly(basis.nodes().row(i).transpose());
        const Eigen::MatrixX3d points = random_points(shape, 40, 5u * p + 1u);
        const Eigen::MatrixXd v = basis.values(points);
        for (Eigen::Index q = 0; q < points.rows(); ++q) {
          EXPECT_NEAR(v.row(q).dot(at_nodes), poly(points.row(q).transpose()), 1e-9) << describe(shape, p, set);
          EXPECT_NEAR(v.row(q).sum(), 1.0, 1e-11) << describe(shape, p, set);
        }
      }
}

// The product path of quadrilaterals, hexahedra and prisms (factors' values multiplied) against the
// modal reference, at every order and node set.
TEST(LagrangeBasis, ProductShapesAgreeWithTheModalReference) {
  for (Shape shape : {Shape::Quadrilateral, Shape::Hexahedron, Shape::Prism})
    for (NodeSet set : kSets)
      for (int p = 1; p <= kMaxOrder; ++p) {
        const LagrangeBasis basis(shape, p, set);
        const Eigen::MatrixX3d points = random_points(shape, 30, 7u * p + 2u);
        const Eigen::MatrixXd fast = basis.values(points), slow = basis.values_by_modes(points);
        // The modal path loses digits with equispaced nodes at high order (its Vandermonde matrix).
        EXPECT_LT((fast - slow).cwiseAbs().maxCoeff(), set == NodeSet::Equispaced && p > 6 ? 1e-7 : 1e-10)
            << describe(shape, p, set);
      }
}

// A polynomial of degree P+1 is not in the space: interpolation must then differ (the test above
// would pass with any basis that reproduces nodes if the test polynomial were trivial).
TEST(LagrangeBasis, DoesNotReproduceDegreeAboveP) {
  const LagrangeBasis basis(Shape::Triangle, 3);
  Eigen::VectorXd at_nodes(basis.size());
  for (int i = 0; i < basis.size(); ++i) at_nodes[i] = std::pow(basis.nodes()(i, 0), 4);
  const Eigen::MatrixX3d point = (Eigen::MatrixX3d(1, 3) << 0.3, 0.1, 0.0).finished();
  EXPECT_GT(std::abs(basis.values(point).row(0).dot(at_nodes) - std::pow(0.3, 4)), 1e-5);
}

TEST(LagrangeBasis, GradientsMatchFiniteDifferences) {
  const double h = 1e-6;
  for (Shape shape : kAllShapes)
    for (NodeSet set : kSets)
      for (int p : {1, 3, 6}) {
        const LagrangeBasis basis(shape, p, set);
        const Eigen::MatrixX3d points = random_points(shape, 6, 11u * p + 7u);
        const auto gradients = basis.gradients(points);
        for (int k = 0; k < 3; ++k) {
          Eigen::MatrixX3d plus = points, minus = points;
          plus.col(k).array() += h;
          minus.col(k).array() -= h;
          const Eigen::MatrixXd fd = (basis.values(plus) - basis.values(minus)) / (2 * h);  // 0 in unused directions
          EXPECT_LT((gradients[k] - fd).cwiseAbs().maxCoeff(), 1e-5)
              << describe(shape, p, set) << " d/dxi_" << k;
        }
        // The gradients of a partition of unity sum to zero.
        for (int k = 0; k < 3; ++k) EXPECT_LT(gradients[k].rowwise().sum().cwiseAbs().maxCoeff(), 1e-9);
      }
}

// Pyramid apex: values are exact limits (Kronecker there too, checked above); the gradient of the
// interpolant of a linear function is its exact gradient even at the apex.
TEST(LagrangeBasis, PyramidApexGradientOfLinearFunctionIsExact) {
  for (int p : {1, 2, 4, 7}) {
    const LagrangeBasis basis(Shape::Pyramid, p);
    Eigen::VectorXd at_nodes(basis.size());
    for (int i = 0; i < basis.size(); ++i) at_nodes[i] = basis.nodes().row(i).dot(Eigen::RowVector3d(2.0, -3.0, 0.5));
    const Eigen::MatrixX3d apex = (Eigen::MatrixX3d(1, 3) << 0.0, 0.0, 1.0).finished();
    const auto g = basis.gradients(apex);
    EXPECT_NEAR(g[0].row(0).dot(at_nodes), 2.0, 1e-9) << "P=" << p;
    EXPECT_NEAR(g[1].row(0).dot(at_nodes), -3.0, 1e-9) << "P=" << p;
    EXPECT_NEAR(g[2].row(0).dot(at_nodes), 0.5, 1e-9) << "P=" << p;
  }
}

TEST(LagrangeBasis, VandermondeConditioningAtOrderTen) {
  for (Shape shape : {Shape::Segment, Shape::Triangle, Shape::Quadrilateral, Shape::Tetrahedron, Shape::Prism}) {
    const double equispaced = vandermonde_condition_number(shape, kMaxOrder, NodeSet::Equispaced);
    const double gll = vandermonde_condition_number(shape, kMaxOrder, NodeSet::GLL);
    std::cout << "  Vandermonde condition, " << to_string(shape) << " P=10: equispaced " << equispaced << ", GLL "
              << gll << "\n";
    EXPECT_LT(gll, equispaced) << to_string(shape);
  }
  EXPECT_LT(vandermonde_condition_number(Shape::Triangle, kMaxOrder, NodeSet::GLL),
            0.5 * vandermonde_condition_number(Shape::Triangle, kMaxOrder, NodeSet::Equispaced));
}

TEST(LagrangeBasis, InterpolationMatrixBetweenOrdersAndSets) {
  for (Shape shape : kAllShapes) {
    const LagrangeBasis coarse(shape, 2), fine(shape, 5, NodeSet::GLL);
    const Eigen::MatrixXd up = interpolation_matrix(coarse, fine);
    ASSERT_EQ(up.rows(), fine.size());
    ASSERT_EQ(up.cols(), coarse.size());
    const Polynomial poly = random_polynomial(shape, 2, 99u);
    Eigen::VectorXd at_coarse(coarse.size());
    for (int i = 0; i < coarse.size(); ++i) at_coarse[i] = poly(coarse.nodes().row(i).transpose());
    const Eigen::VectorXd at_fine = up * at_coarse;
    for (int i = 0; i < fine.size(); ++i) EXPECT_NEAR(at_fine[i], poly(fine.nodes().row(i).transpose()), 1e-10);
  }
  EXPECT_THROW(interpolation_matrix(LagrangeBasis(Shape::Triangle, 2), LagrangeBasis(Shape::Quadrilateral, 2)),
               std::invalid_argument);
}

TEST(LagrangeBasis, AffineMapHasConstantJacobian) {
  Eigen::Matrix3d a;
  a << 2.0, 0.3, -0.1, 0.2, 1.5, 0.4, -0.3, 0.1, 0.8;
  const Eigen::Vector3d b(1.0, -2.0, 0.5);
  for (Shape shape : {Shape::Tetrahedron, Shape::Pyramid, Shape::Prism, Shape::Hexahedron})
    for (NodeSet set : kSets) {
      const LagrangeBasis basis(shape, 4, set);
      const Eigen::MatrixX3d element = (basis.nodes() * a.transpose()).rowwise() + b.transpose();
      const Eigen::MatrixX3d points = random_points(shape, 10, 3u);
      const std::vector<Eigen::Matrix3d> jac = jacobians(basis, element, points);
      const Eigen::MatrixX3d mapped = map_points(basis, element, points);
      for (Eigen::Index q = 0; q < points.rows(); ++q) {
        EXPECT_LT((jac[q] - a).cwiseAbs().maxCoeff(), 1e-10) << describe(shape, 4, set);
        EXPECT_LT((mapped.row(q).transpose() - (a * points.row(q).transpose() + b)).norm(), 1e-12);
      }
    }
  const LagrangeBasis tet(Shape::Tetrahedron, 2);
  EXPECT_THROW(map_points(tet, Eigen::MatrixX3d::Zero(4, 3), tet.nodes()), std::invalid_argument);
}

TEST(LagrangeBasis, QuadraticMapJacobian) {
  // chi(x, y, z) = (x + 0.1 y^2, y, z + 0.2 x z): exactly representable at P = 2 on a hex.
  const LagrangeBasis basis(Shape::Hexahedron, 2);
  Eigen::MatrixX3d element(basis.size(), 3);
  for (int i = 0; i < basis.size(); ++i) {
    const Eigen::Vector3d x = basis.nodes().row(i);
    element.row(i) << x.x() + 0.1 * x.y() * x.y(), x.y(), x.z() + 0.2 * x.x() * x.z();
  }
  const Eigen::MatrixX3d point = (Eigen::MatrixX3d(1, 3) << 0.3, -0.5, 0.7).finished();
  Eigen::Matrix3d expected;
  expected << 1.0, 0.2 * -0.5, 0.0, 0.0, 1.0, 0.0, 0.2 * 0.7, 0.0, 1.0 + 0.2 * 0.3;
  EXPECT_LT((jacobians(basis, element, point)[0] - expected).cwiseAbs().maxCoeff(), 1e-12);
}

TEST(LagrangeBasis, RejectsBadInput) {
  EXPECT_THROW(LagrangeBasis(Shape::Triangle, 0), std::invalid_argument);
  EXPECT_THROW(LagrangeBasis(Shape::Triangle, kMaxOrder + 1), std::invalid_argument);
  const LagrangeBasis basis(Shape::Triangle, 2);
  EXPECT_THROW(basis.values((Eigen::MatrixX3d(1, 3) << std::nan(""), 0.0, 0.0).finished()), std::invalid_argument);
}

}  // namespace
}  // namespace semimesh::ho
