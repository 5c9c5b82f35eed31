// det J's Bernstein coefficients by the chained scaled products (jacobian_determinant) against the
// polynomial formed as written from BernsteinPolynomial's operations (the reference).
#include "validity/jacobian_polynomial.hpp"

#include "mapped_nodes.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>
#include <string>

namespace semimesh::ho {
namespace {

TEST(JacobianDeterminant, ChainedProductsEqualTheReferenceOnEveryShapeOrderAndNodeSet) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> noise(-0.04, 0.04);
  for (Shape shape : {Shape::Tetrahedron, Shape::Pyramid, Shape::Prism, Shape::Hexahedron})
    for (NodeSet set : {NodeSet::Equispaced, NodeSet::GLL})
      for (int order = 1; order <= 6; ++order) {
        SCOPED_TRACE(to_string(shape) + " P" + std::to_string(order) + (set == NodeSet::GLL ? " GLL" : " equispaced"));
        // A curved, far-from-the-origin element with a node-by-node perturbation: every product term counts.
        Eigen::MatrixX3d nodes = testing::mapped_nodes(shape, order, set, [](const Eigen::Vector3d& r) -> Eigen::Vector3d {
          return {30.0 + 1.5 * r(0) + 0.2 * std::sin(2.0 * r(1)), -7.0 + r(1) + 0.1 * r(0) * r(2),
                  0.8 * r(2) + 0.15 * std::cos(r(0) + r(1))};
        });
        for (Eigen::Index i = 0; i < nodes.rows(); ++i)
          for (int c = 0; c < 3; ++c) nodes(i, c) += noise(rng);
        const BernsteinPolynomial fast = detail::jacobian_determinant(shape, order, set, nodes);
        const BernsteinPolynomial reference = detail::jacobian_determinant_by_products(shape, order, set, nodes);
        ASSERT_EQ(fast.layout_ptr(), reference.layout_ptr());
        const double scale = reference.coefficients().cwiseAbs().maxCoeff();
        ASSERT_GT(scale, 0.0);
        EXPECT_LT((fast.coefficients() - reference.coefficients()).cwiseAbs().maxCoeff(), 1e-12 * scale);
        // A second element on the same thread: the reused buffers carry nothing over.
        const Eigen::MatrixX3d moved = 2.0 * nodes;
        EXPECT_LT((detail::jacobian_determinant(shape, order, set, moved).coefficients() - 8.0 * fast.coefficients())
                      .cwiseAbs()
                      .maxCoeff(),
                  1e-11 * scale);
      }
}

// The trilinear fast path's det J: the vertex element's, elevated to degree 3P - 1 along each
// direction, is the element's own det J coefficient by coefficient.
TEST(JacobianDeterminant, ElevatedTrilinearDeterminantIsTheElementsOwn) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (NodeSet set : {NodeSet::Equispaced, NodeSet::GLL})
    for (int order = 2; order <= 6; ++order) {
      SCOPED_TRACE("P" + std::to_string(order) + (set == NodeSet::GLL ? " GLL" : " equispaced"));
      Eigen::Matrix<double, 8, 3> corners = reference_nodes(Shape::Hexahedron, 1);
      for (int v = 0; v < 8; ++v)
        for (int c = 0; c < 3; ++c) corners(v, c) = 10.0 * c + corners(v, c) * (c == 2 ? 0.1 : 1.0) + 0.05 * u(rng);
      const Eigen::MatrixX3d nodes = testing::mapped_nodes(Shape::Hexahedron, order, set, [&](const Eigen::Vector3d& r) -> Eigen::Vector3d {
        Eigen::Vector3d x = Eigen::Vector3d::Zero();
        for (int v = 0; v < 8; ++v) {
          const Eigen::Vector3d c = reference_nodes(Shape::Hexahedron, 1).row(v).transpose();
          x += corners.row(v).transpose() * (1 + c[0] * r[0]) * (1 + c[1] * r[1]) * (1 + c[2] * r[2]) / 8;
        }
        return x;
      });
      const BernsteinPolynomial element = detail::jacobian_determinant(Shape::Hexahedron, order, set, nodes);
      const BernsteinPolynomial elevated = detail::elevated_on_segments(
          detail::jacobian_determinant(Shape::Hexahedron, 1, set, corners), 3 * order - 1);
      ASSERT_EQ(elevated.layout_ptr(), element.layout_ptr());
      const double scale = element.coefficients().cwiseAbs().maxCoeff();
      // The element's own from its nodes carries the node-to-Bezier conversion's conditioning.
      EXPECT_LT((elevated.coefficients() - element.coefficients()).cwiseAbs().maxCoeff(), 1e-9 * scale);
    }
  EXPECT_THROW(detail::elevated_on_segments(BernsteinPolynomial({SimplexFactor{2, 2}, SimplexFactor{1, 2}}), 5),
               std::invalid_argument);
}

}  // namespace
}  // namespace semimesh::ho
