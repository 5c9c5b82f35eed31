// ho::extend_inward (the harmonic extension curve_mesh gives faces and volumes off the CAD, for
// stages that move boundary nodes later): an affine map is harmonic, so from the boundary nodes of
// an affinely mapped element it gives back the inner nodes exactly; the boundary rows are kept.
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

}  // namespace
}  // namespace semimesh::ho
