// Repair of invalid curved elements: a pushed interior node, a pushed free face node, and an element
// folded by its own CAD boundary face (reported, not moved).
#include "repair_in_place.hpp"

#include "semimesh/ho/basis.hpp"
#include "semimesh/ho/validity.hpp"
#include "semimesh/mock_cad/naca.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <memory>

namespace semimesh::ho {
namespace {

const cad::Model& model() {
  static const std::unique_ptr<cad::Model> m = mock_cad::make_naca_wing({});
  return *m;
}

int wall() { return *model().find_surface("wall"); }

// A column of `count` unit hexes of order 2 stacked in z, nodes shared by position; the nodes of the
// bottom face z = 0 are attached to the wall surface at (x, y).
mesh::Mesh hex_column(int count) {
  mesh::Mesh m(2, NodeSet::GLL);
  const Eigen::MatrixX3d r = reference_nodes(Shape::Hexahedron, 2, NodeSet::GLL);
  std::map<std::array<long, 3>, mesh::NodeId> ids;
  for (int k = 0; k < count; ++k) {
    std::vector<mesh::NodeId> nodes;
    for (int i = 0; i < r.rows(); ++i) {
      const Eigen::Vector3d x(0.5 * (r(i, 0) + 1.0), 0.5 * (r(i, 1) + 1.0), 0.5 * (r(i, 2) + 1.0) + k);
      const std::array<long, 3> key{std::lround(2 * x.x()), std::lround(2 * x.y()), std::lround(2 * x.z())};
      auto it = ids.find(key);
      if (it == ids.end()) {
        mesh::CadAttachment a;
        if (key[2] == 0) a = {mesh::CadAttachment::Surface, wall(), x.x(), x.y()};
        it = ids.emplace(key, m.add_node(x, a)).first;
      }
      nodes.push_back(it->second);
    }
    m.add_element(Shape::Hexahedron, nodes);
  }
  return m;
}

bool valid(const mesh::Mesh& m, std::size_t e) {
  return certify_jacobian(Shape::Hexahedron, 2, NodeSet::GLL, m.element_coordinates(e)).valid;
}

// Canonical index of the node of a P = 2 hex at reference point r (components -1, 0, 1).
int node_at(const Eigen::Vector3d& r) {
  const Eigen::MatrixX3d ref = reference_nodes(Shape::Hexahedron, 2, NodeSet::GLL);
  for (int i = 0; i < ref.rows(); ++i)
    if ((ref.row(i).transpose() - r).norm() < 1e-12) return i;
  return -1;
}

TEST(RepairInvalid, PushedInteriorNodeIsRelaxed) {
  mesh::Mesh m = hex_column(1);
  const mesh::NodeId centre = m.element_nodes(0)[node_at({0, 0, 0})];
  m.place_node(centre, Eigen::Vector3d(0.5, 0.5, 2.0));  // far above the top face
  ASSERT_FALSE(valid(m, 0));
  const RepairStats stats = repair_in_place(m, model(), {0});
  EXPECT_EQ(stats.checked, 1);
  EXPECT_EQ(stats.repaired_interior, 1);
  EXPECT_TRUE(stats.failures.empty());
  EXPECT_TRUE(valid(m, 0));
  // Moved on the straight line back toward (0.5, 0.5, 0.5), strictly below the top face.
  EXPECT_NEAR(m.node(centre).x(), 0.5, 1e-12);
  EXPECT_LT(m.node(centre).z(), 1.0);
  EXPECT_GT(m.node(centre).z(), 0.5);
  EXPECT_GT(stats.min_blend, 0.0);
  EXPECT_LT(stats.min_blend, 1.0);
}

TEST(RepairInvalid, PushedFreeFaceNodeIsRelaxedKeepingTheNeighbourValid) {
  mesh::Mesh m = hex_column(2);
  // The centre of the face shared by the two hexes (z = 1), pushed through the top hex's lid.
  const mesh::NodeId shared = m.element_nodes(0)[node_at({0, 0, 1})];
  m.place_node(shared, Eigen::Vector3d(0.5, 0.5, 2.5));
  ASSERT_FALSE(valid(m, 1));
  const RepairStats stats = repair_in_place(m, model(), {0, 1});
  EXPECT_EQ(stats.repaired_free_nodes + stats.already_valid, 2);
  EXPECT_TRUE(stats.failures.empty());
  EXPECT_TRUE(valid(m, 0));
  EXPECT_TRUE(valid(m, 1));
  EXPECT_LT(m.node(shared).z(), 2.0);
}

TEST(RepairInvalid, ElementFoldedByItsCadFaceIsReported) {
  mesh::Mesh m = hex_column(1);
  // The bottom face's centre, on the wall CAD surface, pushed above the top face.
  const mesh::NodeId on_cad = m.element_nodes(0)[node_at({0, 0, -1})];
  m.place_node_on_cad(on_cad, Eigen::Vector3d(0.5, 0.5, 1.6), m.cad_attachment(on_cad));
  ASSERT_FALSE(valid(m, 0));
  const Eigen::MatrixX3d before = m.element_coordinates(0);
  const RepairStats stats = repair_in_place(m, model(), {0});
  ASSERT_EQ(stats.failures.size(), 1u);
  EXPECT_EQ(stats.failures[0].element, 0u);
  EXPECT_LT((stats.failures[0].centroid - Eigen::Vector3d(0.5, 0.5, 0.5)).norm(), 1e-12);
  EXPECT_NE(stats.failures[0].reason.find("element 0"), std::string::npos) << stats.failures[0].reason;
  EXPECT_NE(stats.failures[0].reason.find("'wall'"), std::string::npos) << stats.failures[0].reason;
  EXPECT_EQ(m.element_coordinates(0), before);  // left as it was
}

// A shell prism of order 2 (face 0-1-2 on the wall CAD at z = 0, straight outer face at z = 0.1)
// whose body face bulges above the outer face: straightening the free nodes cannot help (the CAD
// node folds it), but letting the column follow the body face does: x + f(xi, eta) e_z keeps det J.
TEST(RepairInvalid, ShellPrismFoldedByItsCurvedBodyFaceFollowsIt) {
  mesh::Mesh m(2, NodeSet::GLL);
  const Eigen::MatrixX3d r = reference_nodes(Shape::Prism, 2, NodeSet::GLL);
  std::vector<mesh::NodeId> nodes;
  mesh::NodeId bulging = 0;
  for (int i = 0; i < r.rows(); ++i) {
    const Eigen::Vector3d x(r(i, 0), r(i, 1), 0.05 * (r(i, 2) + 1.0));
    mesh::CadAttachment a;
    if (r(i, 2) == -1.0) a = {mesh::CadAttachment::Surface, wall(), x.x(), x.y()};
    nodes.push_back(m.add_node(x, a));
    if (r(i, 2) == -1.0 && std::abs(r(i, 0) - 0.5) < 1e-12 && std::abs(r(i, 1)) < 1e-12) bulging = nodes.back();
  }
  m.add_element(Shape::Prism, nodes);
  m.place_node_on_cad(bulging, Eigen::Vector3d(0.5, 0.0, 0.15), m.cad_attachment(bulging));
  auto prism_valid = [&] { return certify_jacobian(Shape::Prism, 2, NodeSet::GLL, m.element_coordinates(0)).valid; };
  ASSERT_FALSE(prism_valid());
  const RepairStats stats = repair_in_place(m, model(), {0});
  EXPECT_EQ(stats.repaired_body_following, 1);
  EXPECT_TRUE(stats.failures.empty());
  EXPECT_TRUE(prism_valid());
  EXPECT_EQ(m.node(bulging).z(), 0.15);  // the CAD node stays where the CAD put it
}

TEST(RepairInvalid, RejectsBadInput) {
  mesh::Mesh m = hex_column(1);
  EXPECT_THROW(repair_in_place(m, model(), {1}), std::invalid_argument);
  const RepairStats stats = repair_in_place(m, model(), {0});
  EXPECT_EQ(stats.already_valid, 1);
}

}  // namespace
}  // namespace semimesh::ho
