// Reference node sets: counts, distinctness, vertices first, edge/face layout, GLL positions.
#include "semimesh/ho/element_type.hpp"
#include "all_shapes.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace semimesh::ho {
namespace {

using testing::kAllShapes;
using testing::kSets;

const char* name(NodeSet set) { return set == NodeSet::GLL ? "GLL" : "equispaced"; }

// Inside the closed reference element (with tolerance).
bool inside(Shape shape, const Eigen::Vector3d& x, double tol = 1e-12) {
  const auto in = [tol](double v, double lo, double hi) { return v >= lo - tol && v <= hi + tol; };
  switch (shape) {
    case Shape::Segment: return in(x.x(), -1, 1) && x.y() == 0 && x.z() == 0;
    case Shape::Quadrilateral: return in(x.x(), -1, 1) && in(x.y(), -1, 1) && x.z() == 0;
    case Shape::Hexahedron: return in(x.x(), -1, 1) && in(x.y(), -1, 1) && in(x.z(), -1, 1);
    case Shape::Triangle: return x.x() >= -tol && x.y() >= -tol && x.x() + x.y() <= 1 + tol && x.z() == 0;
    case Shape::Tetrahedron: return x.minCoeff() >= -tol && x.sum() <= 1 + tol;
    case Shape::Prism: return x.x() >= -tol && x.y() >= -tol && x.x() + x.y() <= 1 + tol && in(x.z(), -1, 1);
    case Shape::Pyramid:
      return in(x.z(), 0, 1) && std::abs(x.x()) <= 1 - x.z() + tol && std::abs(x.y()) <= 1 - x.z() + tol;
  }
  return false;
}

TEST(ReferenceNodes, CountsVerticesFirstDistinctInside) {
  for (Shape shape : kAllShapes)
    for (NodeSet set : kSets)
      for (int p = 1; p <= kMaxOrder; ++p) {
        const Eigen::MatrixX3d nodes = reference_nodes(shape, p, set);
        const std::string where = to_string(shape) + " P=" + std::to_string(p) + " " + name(set);
        ASSERT_EQ(nodes.rows(), num_nodes(shape, p)) << where;
        const Eigen::MatrixX3d vertices = reference_vertices(shape);
        EXPECT_LT((nodes.topRows(vertices.rows()) - vertices).cwiseAbs().maxCoeff(), 1e-15) << where;
        double closest = 1e300;
        for (Eigen::Index i = 0; i < nodes.rows(); ++i) {
          EXPECT_TRUE(inside(shape, nodes.row(i).transpose())) << where << " node " << i;
          for (Eigen::Index j = i + 1; j < nodes.rows(); ++j)
            closest = std::min(closest, (nodes.row(i) - nodes.row(j)).norm());
        }
        EXPECT_GT(closest, 0.2 / (p * p)) << where;  // distinct, and not nearly coincident
      }
}

TEST(ReferenceNodes, RejectsBadOrders) {
  EXPECT_THROW(reference_nodes(Shape::Tetrahedron, 0), std::invalid_argument);
  EXPECT_THROW(reference_nodes(Shape::Tetrahedron, kMaxOrder + 1), std::invalid_argument);
}

// Edge nodes follow Gmsh's edge table, in edge direction; in the GLL set they sit at the
// Gauss-Lobatto points of the edge (P = 4: 0 and +-sqrt(3/7), the roots of P_4').
TEST(ReferenceNodes, EdgeNodesInEdgeOrderAndDirection) {
  const double gll4[] = {-std::sqrt(3.0 / 7.0), 0.0, std::sqrt(3.0 / 7.0)};
  for (Shape shape : kAllShapes)
    for (NodeSet set : kSets) {
      const int p = 4;
      const Eigen::MatrixX3d nodes = reference_nodes(shape, p, set);
      const Eigen::MatrixX3d v = reference_vertices(shape);
      int next = num_vertices(shape);
      for (const auto& edge : edges(shape)) {
        const Eigen::RowVector3d a = v.row(edge[0]), b = v.row(edge[1]);
        for (int i = 1; i < p; ++i, ++next) {
          const double s = set == NodeSet::GLL ? 0.5 * (1.0 + gll4[i - 1]) : double(i) / p;
          EXPECT_LT((nodes.row(next) - (a + s * (b - a))).norm(), 1e-14)
              << to_string(shape) << " " << name(set) << " edge " << edge[0] << "-" << edge[1] << " node " << i;
        }
      }
    }
}

// The interior nodes of each face of a 3D element are those of the 2D element of the same order and
// node set, mapped by the face's vertex list, in the same order: what makes neighbours conforming.
TEST(ReferenceNodes, FaceNodesAreThe2DElementsInteriorNodes) {
  for (Shape shape : {Shape::Tetrahedron, Shape::Pyramid, Shape::Prism, Shape::Hexahedron})
    for (NodeSet set : kSets)
      for (int p = 1; p <= kMaxOrder; ++p) {
        const Eigen::MatrixX3d nodes = reference_nodes(shape, p, set);
        const Eigen::MatrixX3d v = reference_vertices(shape);
        int next = num_vertices(shape) + static_cast<int>(edges(shape).size()) * (p - 1);
        for (const auto& face : faces(shape)) {
          const bool triangle = face.size() == 3;
          const Shape face_shape = triangle ? Shape::Triangle : Shape::Quadrilateral;
          const Eigen::MatrixX3d face_nodes = reference_nodes(face_shape, p, set);
          const int boundary = triangle ? 3 * p : 4 * p;
          for (Eigen::Index i = boundary; i < face_nodes.rows(); ++i, ++next) {
            const double x = face_nodes(i, 0), y = face_nodes(i, 1);
            Eigen::RowVector3d expected;
            if (triangle) {
              expected = v.row(face[0]) + x * (v.row(face[1]) - v.row(face[0])) + y * (v.row(face[2]) - v.row(face[0]));
            } else {
              expected = 0.25 * ((1 - x) * (1 - y) * v.row(face[0]) + (1 + x) * (1 - y) * v.row(face[1]) +
                                 (1 + x) * (1 + y) * v.row(face[2]) + (1 - x) * (1 + y) * v.row(face[3]));
            }
            ASSERT_LT((nodes.row(next) - expected).norm(), 1e-13)
                << to_string(shape) << " P=" << p << " " << name(set) << " face node " << next;
          }
        }
      }
}

// Warp & blend moves interior nodes of simplices away from the equispaced lattice (towards the
// boundary, like GLL), keeps the node count and leaves vertices fixed.
TEST(ReferenceNodes, GllDiffersFromEquispacedFromOrderThree) {
  for (Shape shape : kAllShapes) {
    const Eigen::MatrixX3d eq = reference_nodes(shape, 2, NodeSet::Equispaced);
    const Eigen::MatrixX3d gll = reference_nodes(shape, 2, NodeSet::GLL);
    EXPECT_LT((eq - gll).cwiseAbs().maxCoeff(), 1e-15) << to_string(shape);  // GLL of order 2 = equispaced
    const Eigen::MatrixX3d eq6 = reference_nodes(shape, 6, NodeSet::Equispaced);
    const Eigen::MatrixX3d gll6 = reference_nodes(shape, 6, NodeSet::GLL);
    EXPECT_GT((eq6 - gll6).cwiseAbs().maxCoeff(), 1e-3) << to_string(shape);
  }
}

}  // namespace
}  // namespace semimesh::ho
