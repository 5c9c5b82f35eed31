// mesh::without_unreferenced_nodes: orphan nodes dropped, everything else kept (compared with the
// source mesh through node positions, not through the function's own bookkeeping); and
// with_nodes_replaced, which a weld uses to join two elements given equal nodes under two ids.
#include "semimesh/mesh/compact.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <stdexcept>

namespace {

using semimesh::ho::Shape;
using semimesh::mesh::CadAttachment;
using semimesh::mesh::Mesh;
using semimesh::mesh::NodeId;

/// Two order-2 tets sharing a face, a boundary triangle, and three orphans (one with a CAD tag).
Mesh mesh_with_orphans() {
  Mesh m(2);
  auto node = [&](double x, double y, double z) { return m.add_node(Eigen::Vector3d(x, y, z)); };
  const Eigen::Vector3d v[5] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1}};
  m.add_node(Eigen::Vector3d(9, 9, 9));  // orphan before every used node
  std::vector<NodeId> id;
  for (const auto& x : v) id.push_back(m.add_node(x, CadAttachment{CadAttachment::Surface, 3, x[0], x[1]}));
  node(8, 8, 8);  // orphan in the middle
  auto mid = [&](int a, int b) { return node((v[a][0] + v[b][0]) / 2, (v[a][1] + v[b][1]) / 2, (v[a][2] + v[b][2]) / 2); };
  // Gmsh order-2 tet: vertices, then edges 0-1, 1-2, 2-0, 3-0, 3-2, 3-1.
  const NodeId m01 = mid(0, 1), m12 = mid(1, 2), m20 = mid(2, 0), m30 = mid(3, 0), m32 = mid(3, 2), m31 = mid(3, 1);
  m.add_element(Shape::Tetrahedron, {id[0], id[1], id[2], id[3], m01, m12, m20, m30, m32, m31});
  const NodeId m41 = mid(4, 1), m42 = mid(4, 2), m43 = mid(4, 3);
  // Tet (1, 2, 3, 4): edges 1-2, 2-3, 3-1, 4-1, 4-3, 4-2.
  m.add_element(Shape::Tetrahedron, {id[1], id[2], id[3], id[4], m12, m32, m31, m41, m43, m42},
                m.region_index("farfield"));
  m.add_boundary_face("wall", Shape::Triangle, {id[0], id[2], id[1], m20, m12, m01});
  m.add_node(Eigen::Vector3d(7, 7, 7), CadAttachment{CadAttachment::Curve, 1, 0.5, 0});  // orphan at the end
  return m;
}

std::multiset<std::vector<double>> element_points(const Mesh& m) {
  std::multiset<std::vector<double>> out;
  for (std::size_t e = 0; e < m.elements().size(); ++e) {
    std::vector<double> row;
    for (NodeId id : m.element_nodes(e)) row.insert(row.end(), m.node(id).data(), m.node(id).data() + 3);
    out.insert(row);
  }
  return out;
}

TEST(Compact, DropsExactlyTheOrphansAndKeepsElementsFacesAndCad) {
  const Mesh source = mesh_with_orphans();
  ASSERT_EQ(semimesh::mesh::count_unreferenced_nodes(source), 3u);
  const Mesh out = semimesh::mesh::without_unreferenced_nodes(source);
  EXPECT_EQ(out.num_nodes(), source.num_nodes() - 3);
  EXPECT_EQ(semimesh::mesh::count_unreferenced_nodes(out), 0u);
  EXPECT_EQ(out.order(), source.order());
  EXPECT_EQ(element_points(out), element_points(source));
  ASSERT_EQ(out.boundary_faces().size(), 1u);
  EXPECT_EQ(out.group_names(), source.group_names());
  EXPECT_EQ(out.region_names(), source.region_names());
  ASSERT_EQ(out.elements().size(), 2u);
  EXPECT_EQ(out.elements()[0].region, 0);
  EXPECT_EQ(out.elements()[1].region, source.elements()[1].region);
  std::vector<double> face_in, face_out;
  for (NodeId id : source.boundary_face_nodes(0)) face_in.insert(face_in.end(), source.node(id).data(), source.node(id).data() + 3);
  for (NodeId id : out.boundary_face_nodes(0)) face_out.insert(face_out.end(), out.node(id).data(), out.node(id).data() + 3);
  EXPECT_EQ(face_out, face_in);
  EXPECT_EQ(out.edges().size(), source.edges().size());
  EXPECT_EQ(out.faces().size(), source.faces().size());
  for (NodeId id = 0; id < out.num_nodes(); ++id) {  // same position, same CAD attachment
    NodeId same = 0;
    while (source.node(same) != out.node(id)) ++same;
    EXPECT_EQ(out.cad_attachment(id).kind, source.cad_attachment(same).kind);
    EXPECT_EQ(out.cad_attachment(id).entity, source.cad_attachment(same).entity);
    EXPECT_EQ(out.cad_attachment(id).u, source.cad_attachment(same).u);
  }
}

TEST(Compact, MeshWithoutOrphansKeepsItsNodeOrder) {
  const Mesh source = mesh_with_orphans();
  const Mesh once = semimesh::mesh::without_unreferenced_nodes(source);
  const Mesh twice = semimesh::mesh::without_unreferenced_nodes(once);
  EXPECT_EQ(twice.nodes(), once.nodes());
}

// Two order-1 tets on either side of the triangle (1,0,0) (0,1,0) (0,0,1), each with its own three
// ids for it: mapping the second tet's copies onto the first's joins them through one face.
TEST(Compact, ReplacingDuplicateNodesJoinsTheElements) {
  Mesh m(1);
  auto node = [&](double x, double y, double z) { return m.add_node(Eigen::Vector3d(x, y, z)); };
  const NodeId a = node(1, 0, 0), b = node(0, 1, 0), c = node(0, 0, 1), below = node(0, 0, 0);
  m.add_element(Shape::Tetrahedron, {below, a, b, c});
  const NodeId a2 = node(1, 0, 0), b2 = node(0, 1, 0), c2 = node(0, 0, 1), above = node(1, 1, 1);
  m.add_element(Shape::Tetrahedron, {above, a2, c2, b2});
  ASSERT_EQ(m.faces().size(), 8u);  // not joined: 4 + 4 faces
  std::vector<NodeId> to(m.num_nodes());
  for (NodeId v = 0; v < m.num_nodes(); ++v) to[v] = v;
  to[a2] = a, to[b2] = b, to[c2] = c;
  std::vector<double> fractions;
  const Mesh joined = semimesh::mesh::with_nodes_replaced(m, to, [&](double f) { fractions.push_back(f); });
  EXPECT_EQ(joined.num_nodes(), 5u);
  EXPECT_EQ(joined.faces().size(), 7u) << "the two tets share their middle face";
  EXPECT_EQ(element_points(joined), element_points(m));
  EXPECT_EQ(semimesh::mesh::count_unreferenced_nodes(joined), 0u);
  ASSERT_FALSE(fractions.empty());
  EXPECT_TRUE(std::is_sorted(fractions.begin(), fractions.end()));
  EXPECT_EQ(fractions.back(), 1.0);
  to.pop_back();
  EXPECT_THROW(semimesh::mesh::with_nodes_replaced(m, to), std::invalid_argument);
}

// Moved nodes (a weld carrying a snapped edge inwards): a listed node is kept at its new point,
// the others where they were; a node on the CAD cannot be moved off it.
TEST(Compact, ReplacingNodesCanMoveTheKeptOnesOffNoCad) {
  const Mesh source = mesh_with_orphans();
  std::vector<NodeId> to(source.num_nodes());
  for (NodeId v = 0; v < source.num_nodes(); ++v) to[v] = v;
  const std::vector<NodeId> tet = source.element_nodes(1);
  const NodeId free = tet.back();  // an edge node, no CAD attachment
  ASSERT_EQ(source.cad_attachment(free).kind, CadAttachment::None);
  const Eigen::Vector3d there(0.6, 0.7, 0.8);
  const Mesh out = semimesh::mesh::with_nodes_replaced(source, to, {{free, there}});
  const std::vector<NodeId> moved_tet = out.element_nodes(1);
  EXPECT_EQ(out.node(moved_tet.back()), there);
  for (std::size_t k = 0; k + 1 < tet.size(); ++k) EXPECT_EQ(out.node(moved_tet[k]), source.node(tet[k])) << k;
  EXPECT_THROW(semimesh::mesh::with_nodes_replaced(source, to, {{tet[0], there}}), std::invalid_argument);
}

}  // namespace
