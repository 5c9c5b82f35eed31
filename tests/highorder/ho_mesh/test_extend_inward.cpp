// ho::extend_inward (the extension curve_mesh gives faces and volumes off the CAD, for stages that
// move boundary nodes later): from the boundary nodes of an affinely mapped element it gives back
// the inner nodes exactly; the boundary rows are kept. A quadrilateral or a prism takes a bulge of
// its bottom linearly across to its straight top (a thin layer's first sub-layer keeps it).
#include "semimesh/ho/curving/extend_inward.hpp"

#include "semimesh/mesh/node_layout.hpp"

#include <gtest/gtest.h>

namespace semimesh::ho {
namespace {

TEST(ExtendInward, GivesBackTheInnerNodesOfAnAffineMapKeepingTheBoundary) {
  Eigen::Matrix3d a;
  a << 2.0, 0.3, -0.1, 0.2, 1.5, 0.4, -0.3, 0.1, 0.7;
  const Eigen::RowVector3d b(0.5, -1.0, 2.0);
  for (Shape shape : {Shape::Triangle, Shape::Quadrilateral, Shape::Tetrahedron, Shape::Pyramid, Shape::Prism,
                      Shape::Hexahedron})
    for (int order : {2, 3, 4}) {
      const Eigen::MatrixXd mapped = (reference_nodes(shape, order, NodeSet::GLL) * a.transpose()).rowwise() + b;
      const mesh::NodeLayout& layout = mesh::node_layout(shape, order);
      const auto inside = dimension(shape) == 3 ? mesh::NodeSlot::Interior : mesh::NodeSlot::Face;
      Eigen::MatrixXd x = mapped;
      int inner = 0;
      for (int i = 0; i < x.rows(); ++i)
        if (layout.slots[i].kind == inside) x.row(i).setConstant(1e3), ++inner;
      extend_inward(shape, order, NodeSet::GLL, x);
      EXPECT_LT((x - mapped).cwiseAbs().maxCoeff(), 1e-9) << to_string(shape) << " order " << order;
      if (order >= 4) {  // braces: EXPECT_* expand to an if-else (-Wdangling-else)
        EXPECT_GT(inner, 0) << to_string(shape);
      }
    }
}

// A layer prism 0.1 thick under a base bulging by up to 0.2 (its base on a curved wall, its top
// straight), its side faces and vertical edges carrying the bulge linearly to the top, as a
// quadrilateral does from its bottom edge: every inner node keeps the bulge times (1 - s), s its
// height's fraction. The harmonic extension took it out about three times faster near the base (the
// wall layer's first sub-layer folded on the re-seamed B-spline fuselage at order 4).
TEST(ExtendInward, ALayerPrismCarriesItsBasesBulgeLinearlyToItsTop) {
  for (Shape shape : {Shape::Quadrilateral, Shape::Prism})
    for (int order : {3, 4, 5}) {
      const Eigen::MatrixX3d ref = reference_nodes(shape, order, NodeSet::GLL);
      const int up = shape == Shape::Prism ? 2 : 1;  // the layer's direction
      const mesh::NodeLayout& layout = mesh::node_layout(shape, order);
      const auto inside = dimension(shape) == 3 ? mesh::NodeSlot::Interior : mesh::NodeSlot::Face;
      Eigen::MatrixXd x(ref.rows(), 3), expected(ref.rows(), 3);
      for (int i = 0; i < ref.rows(); ++i) {
        const double s = 0.5 * (ref(i, up) + 1.0);
        const double u = ref(i, 0), v = ref(i, 1);
        const double bulge = shape == Shape::Prism ? 0.2 * (u * u + v * v) + 2.7 * u * v * (1.0 - u - v) : 0.1 * (1.0 - u * u);
        expected.row(i) << u, shape == Shape::Prism ? v : 0.0, 0.1 * s + bulge * (1.0 - s);
        if (layout.slots[i].kind == inside)
          x.row(i).setConstant(1e3);
        else
          x.row(i) = expected.row(i);
      }
      extend_inward(shape, order, NodeSet::GLL, x);
      EXPECT_LT((x - expected).cwiseAbs().maxCoeff(), 1e-9) << to_string(shape) << " order " << order;
    }
}

}  // namespace
}  // namespace semimesh::ho
