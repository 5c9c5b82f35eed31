// ho::follow_exposed_body: a far-field element standing on a curved body face, its far vertex a
// thin layer above the face (a pre-cut rim's node over a sharp trailing edge's bare triangles),
// folds once curving bends the face; following the face's bulge makes it valid again, leaves the
// body's nodes where curving put them, does nothing over a flat face and is not applied twice.
#include "semimesh/ho/curving/follow_exposed_body.hpp"

#include "semimesh/ho/validity.hpp"

#include <gtest/gtest.h>

namespace semimesh::ho {
namespace {

constexpr double kChord = 1.0;

// Height of the body face over the plane z = 0 at (x, y): zero at the tet's three body vertices
// (0,0) (1,0) (0,1), bulging by kappa / 8 at its edges' midpoints (a convex body, kappa 1).
double body_height(double x, double y, double kappa) { return 0.5 * kappa * (x * (kChord - x) + y * (kChord - y)); }

// One far-field tet of order P on the body face z = 0 (vertices 0 1 2) with its far vertex at `top`,
// as curve_mesh leaves it: the face's nodes on the body, the others straight; the face a "wing"
// boundary face.
mesh::Mesh tet_on_body(int order, const Eigen::Vector3d& top, double kappa) {
  mesh::Mesh m(order, NodeSet::GLL);
  const Eigen::MatrixX3d reference = reference_nodes(Shape::Tetrahedron, order, NodeSet::GLL);
  std::vector<mesh::NodeId> ids;
  for (Eigen::Index i = 0; i < reference.rows(); ++i) {
    const Eigen::Vector3d r = reference.row(i).transpose();
    Eigen::Vector3d x = Eigen::Vector3d(r.x(), r.y(), 0.0) + r.z() * top;
    mesh::CadAttachment on_body;
    if (r.z() == 0.0) {
      x.z() = body_height(x.x(), x.y(), kappa);
      on_body = {mesh::CadAttachment::Surface, 0, x.x(), x.y()};
    }
    ids.push_back(m.add_node(x, on_body));
  }
  m.add_element(Shape::Tetrahedron, ids, m.region_index("farfield"));
  const Eigen::MatrixX3d face = reference_nodes(Shape::Triangle, order, NodeSet::GLL);
  std::vector<mesh::NodeId> face_ids;
  for (Eigen::Index j = 0; j < face.rows(); ++j)
    for (Eigen::Index i = 0; i < reference.rows(); ++i)
      if (reference(i, 2) == 0.0 && (reference.row(i).head<2>() - face.row(j).head<2>()).norm() < 1e-12)
        face_ids.push_back(ids[i]);
  // Faces by the right-hand rule out of the element: the body face is seen 0 2 1 from the fluid.
  std::vector<mesh::NodeId> outward = face_ids;
  const Eigen::MatrixX3d swapped = [&] {
    Eigen::MatrixX3d s = face;
    s.col(0).swap(s.col(1));
    return s;
  }();
  for (Eigen::Index j = 0; j < face.rows(); ++j)
    for (Eigen::Index k = 0; k < face.rows(); ++k)
      if ((swapped.row(j) - face.row(k)).norm() < 1e-12) outward[j] = face_ids[k];
  m.add_boundary_face("wing", Shape::Triangle, outward);
  return m;
}

bool valid(const mesh::Mesh& m) {
  return certify_jacobian(Shape::Tetrahedron, m.order(), m.node_set(), m.element_coordinates(0)).valid;
}

TEST(FollowExposedBody, ATetOnACurvedBodyFaceWithItsTopInTheFirstLayerIsValidAgain) {
  // The top 0.05 over vertex 0; the face's edges leave vertices 1 and 2 tilted by kappa L / 2 = 0.5.
  for (int order : {2, 3, 4}) {
    mesh::Mesh m = tet_on_body(order, {0.0, 0.0, 0.05}, 1.0);
    ASSERT_FALSE(valid(m)) << "order " << order << ": the case must fold as curve_mesh leaves it";
    std::vector<Eigen::Vector3d> on_body;
    for (mesh::NodeId id = 0; id < m.num_nodes(); ++id)
      if (m.cad_attachment(id).kind != mesh::CadAttachment::None) on_body.push_back(m.node(id));
    const ExposedBodyStats stats = follow_exposed_body(m, "wing", "farfield");
    EXPECT_EQ(stats.faces, 1u);
    EXPECT_GT(stats.nodes, 0u);
    EXPECT_TRUE(valid(m)) << "order " << order;
    std::size_t k = 0;
    for (mesh::NodeId id = 0; id < m.num_nodes(); ++id) {
      if (m.cad_attachment(id).kind == mesh::CadAttachment::None) continue;
      EXPECT_EQ(m.node(id), on_body[k++]);
    }
  }
}

TEST(FollowExposedBody, AFlatBodyFaceMovesNothing) {
  mesh::Mesh m = tet_on_body(3, {0.2, 0.2, 0.05}, 0.0);
  const std::vector<Eigen::Vector3d> before = m.nodes();
  const ExposedBodyStats stats = follow_exposed_body(m, "wing", "farfield");
  EXPECT_EQ(stats.faces, 0u);
  EXPECT_EQ(m.nodes(), before);
}

TEST(FollowExposedBody, ASecondPassAfterTheFirstFindsTheStraightVerticesAgain) {
  // The top over the face's middle moves with the bulge there; the second pass must not move it on.
  mesh::Mesh m = tet_on_body(3, {0.3, 0.3, 0.2}, 1.0);
  const Eigen::Vector3d top = m.node(3);
  follow_exposed_body(m, "wing", "farfield");
  ASSERT_GT((m.node(3) - top).norm(), 1e-3);
  const std::vector<Eigen::Vector3d> once = m.nodes();
  follow_exposed_body(m, "wing", "farfield", /*moved_before=*/true);
  for (mesh::NodeId id = 0; id < m.num_nodes(); ++id) EXPECT_LT((m.node(id) - once[id]).norm(), 1e-12) << "node " << id;
}

TEST(FollowExposedBody, AFaceOnlyTheNearFieldStandsOnMovesNothing) {
  // The same tet as a wing-layer element: its body face is covered, not the far field's to follow.
  mesh::Mesh m = tet_on_body(2, {0.0, 0.0, 0.05}, 1.0);
  mesh::Mesh near(2, NodeSet::GLL);
  for (mesh::NodeId id = 0; id < m.num_nodes(); ++id) near.add_node(m.node(id), m.cad_attachment(id));
  near.region_index("farfield");
  near.add_element(Shape::Tetrahedron, m.element_nodes(0), near.region_index("wing_layer"));
  near.add_boundary_face("wing", Shape::Triangle, m.boundary_face_nodes(0));
  const std::vector<Eigen::Vector3d> before = near.nodes();
  EXPECT_EQ(follow_exposed_body(near, "wing", "farfield").nodes, 0u);
  EXPECT_EQ(near.nodes(), before);
}

}  // namespace
}  // namespace semimesh::ho
