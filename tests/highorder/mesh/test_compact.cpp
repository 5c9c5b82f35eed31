// mesh::without_unreferenced_nodes: orphan nodes dropped, everything else kept (compared with the
// source mesh through node positions, not through the function's own bookkeeping); and
// with_nodes_replaced, which a weld uses to join two elements given equal nodes under two ids;
// Mesh::replace_nodes, which does it in place, gives the entities a fresh build would.
#include "semimesh/mesh/compact.hpp"

#include "highorder/mesh/same_entities.hpp"

#include "semimesh/ho/element_type.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <functional>
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace {

using semimesh::ho::Shape;
using semimesh::mesh::CadAttachment;
using semimesh::mesh::Mesh;
using semimesh::mesh::NodeId;
using semimesh::test::built_afresh;
using semimesh::test::expect_same_entities;

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

// Two order-3 hexes side by side (x in [0, 1] and [1, 2]), each with its own 64 nodes, the second
// one's created first (lower ids) so that welding its x = 1 face onto the first's turns some of its
// edges around; a boundary quad on that face in the second hex's ids, and an orphan.
struct DoubledFace {
  Mesh mesh{3};
  std::vector<NodeId> to;  ///< every node of the second hex at a point of the first onto that one
};

DoubledFace two_order3_hexes_with_a_doubled_face() {
  DoubledFace d;
  Mesh& m = d.mesh;
  const Eigen::MatrixX3d reference = semimesh::ho::reference_nodes(Shape::Hexahedron, 3);  // [-1, 1]^3
  auto hex_nodes = [&](double x0) {
    std::vector<NodeId> ids;
    for (int i = 0; i < reference.rows(); ++i)
      ids.push_back(m.add_node((reference.row(i).transpose() + Eigen::Vector3d::Ones()) / 2 + Eigen::Vector3d(x0, 0, 0)));
    return ids;
  };
  const std::vector<NodeId> second = hex_nodes(1.0);
  m.add_node(Eigen::Vector3d(9, 9, 9));  // orphan
  const std::vector<NodeId> first = hex_nodes(0.0);
  m.add_element(Shape::Hexahedron, first);
  m.add_element(Shape::Hexahedron, second, m.region_index("farfield"));
  const long face = m.find_face({second[0], second[3], second[7], second[4]});  // its x = 1 side
  m.add_boundary_face("interface", Shape::Quadrilateral, m.face_nodes(static_cast<std::size_t>(face)));
  d.to.resize(m.num_nodes());
  for (NodeId v = 0; v < m.num_nodes(); ++v) d.to[v] = v;
  // The nodes sit at multiples of 1/3, each hex's computed its own way (equal up to round-off).
  auto lattice = [&](NodeId v) {
    const Eigen::Vector3d x = 3 * m.node(v);
    return std::array<long, 3>{std::lround(x.x()), std::lround(x.y()), std::lround(x.z())};
  };
  std::map<std::array<long, 3>, NodeId> of_first;
  for (NodeId v : first) of_first[lattice(v)] = v;
  for (NodeId v : second)
    if (const auto it = of_first.find(lattice(v)); it != of_first.end()) d.to[v] = it->second;
  return d;
}

TEST(Compact, ReplacingNodesInPlaceGivesTheEntitiesOfAFreshBuild) {
  DoubledFace d = two_order3_hexes_with_a_doubled_face();
  const Mesh expected = built_afresh(d.mesh, d.to);
  ASSERT_EQ(d.mesh.faces().size(), 12u);
  EXPECT_EQ(d.mesh.replace_nodes(d.to), Mesh::EntityUpdate::Remapped);
  const Mesh& m = d.mesh;
  EXPECT_EQ(m.num_nodes(), 2u * 64 - 16);
  EXPECT_EQ(m.faces().size(), 11u);
  ASSERT_EQ(m.elements().size(), 2u);
  ASSERT_EQ(m.boundary_faces().size(), 1u);
  expect_same_entities(m, expected);
}

// replace_nodes on the doubled hexes with map_of(the weld's map): remapped, `faces` faces after,
// the entities a fresh build of the renamed node lists makes.
void expect_remapped_as_built_afresh(const std::function<std::vector<NodeId>(const std::vector<NodeId>&)>& map_of,
                                     std::size_t faces) {
  DoubledFace d = two_order3_hexes_with_a_doubled_face();
  const std::vector<NodeId> map = map_of(d.to);
  const Mesh expected = built_afresh(d.mesh, map);
  EXPECT_EQ(d.mesh.replace_nodes(map), Mesh::EntityUpdate::Remapped);
  EXPECT_EQ(d.mesh.faces().size(), faces);
  expect_same_entities(d.mesh, expected);
}

// The weld's map the other way round: the first hex's x = 1 face onto the second's. The first
// element then names the joined face through the entity that goes, in its own frame: the face
// takes that frame (the rebuild meets it there first) and the second hex's code is found anew.
TEST(Compact, ReplacingNodesOntoALaterElementsTakesTheFirstUsersFrame) {
  expect_remapped_as_built_afresh(
      [](const std::vector<NodeId>& to) {
        std::vector<NodeId> other_way(to.size());
        for (NodeId v = 0; v < other_way.size(); ++v) other_way[v] = v;
        for (NodeId v = 0; v < to.size(); ++v)
          if (to[v] != v) other_way[to[v]] = v;
        return other_way;
      },
      11);
}

// A map that chains: the doubled face's nodes swapped between the hexes (each hex's onto the
// other's). Each face then has the other's old vertices but its own new ones: nothing joins (the
// face found under a moved face's new key moves too), and the hexes stay apart.
TEST(Compact, ReplacingNodesByASwapJoinsNothing) {
  expect_remapped_as_built_afresh(
      [](const std::vector<NodeId>& to) {
        std::vector<NodeId> swap = to;
        for (NodeId v = 0; v < to.size(); ++v)
          if (to[v] != v) swap[to[v]] = v;
        return swap;
      },
      12);
}

// The reference itself, against the fresh build, on the same two cases.
TEST(Compact, ReplacingNodesByRebuildGivesTheEntitiesOfAFreshBuild) {
  DoubledFace d = two_order3_hexes_with_a_doubled_face();
  const Mesh expected = built_afresh(d.mesh, d.to);
  d.mesh.replace_nodes_by_rebuild(d.to);
  expect_same_entities(d.mesh, expected);
}

// Order-2 tets, six to a unit cube, on n x n x n cubes, every node made twice (the second copies
// first, and an orphan between them): the elements on cubes of even x use the first copies, the
// others the second, so that the welded mesh joins them; the faces at x = 0 are boundary faces.
// More elements than replace_nodes assembles ahead at once: its blocks meet many times.
struct ManyTets {
  Mesh mesh{2};
  std::vector<NodeId> to;  ///< every second copy onto its first
  std::vector<NodeId> first, second;
};

ManyTets many_doubled_tets(int n) {
  ManyTets t;
  Mesh& m = t.mesh;
  const int points = 2 * n + 1;  // a lattice of half steps: vertices and edge midpoints
  auto at = [&](int i, int j, int k) { return (static_cast<std::size_t>(i) * points + j) * points + k; };
  const std::size_t count = static_cast<std::size_t>(points) * points * points;
  for (std::vector<NodeId>* copy : {&t.second, &t.first}) {
    for (int i = 0; i < points; ++i)
      for (int j = 0; j < points; ++j)
        for (int k = 0; k < points; ++k) copy->push_back(m.add_node(Eigen::Vector3d(i, j, k) / 2.0));
    if (copy == &t.second) m.add_node(Eigen::Vector3d(-9, -9, -9));  // orphan
  }
  t.to.resize(m.num_nodes());
  for (NodeId v = 0; v < m.num_nodes(); ++v) t.to[v] = v;
  for (std::size_t p = 0; p < count; ++p) t.to[t.second[p]] = t.first[p];
  const int farfield = m.region_index("farfield");
  // The six tets of the Kuhn split of a cube: the paths from corner 000 to 111 along the axes.
  const int paths[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  for (int ci = 0; ci < n; ++ci)
    for (int cj = 0; cj < n; ++cj)
      for (int ck = 0; ck < n; ++ck) {
        const std::vector<NodeId>& ids = ci % 2 == 0 ? t.first : t.second;
        for (const auto& path : paths) {
          std::array<std::array<int, 3>, 4> v;
          v[0] = {2 * ci, 2 * cj, 2 * ck};
          for (int s = 0; s < 3; ++s) v[s + 1] = v[s], v[s + 1][path[s]] += 2;
          auto node = [&](const std::array<int, 3>& a) { return ids[at(a[0], a[1], a[2])]; };
          auto mid = [&](int a, int b) {
            return ids[at((v[a][0] + v[b][0]) / 2, (v[a][1] + v[b][1]) / 2, (v[a][2] + v[b][2]) / 2)];
          };
          // Gmsh order-2 tet: vertices, then edges 0-1, 1-2, 2-0, 3-0, 3-2, 3-1.
          m.add_element(Shape::Tetrahedron,
                        {node(v[0]), node(v[1]), node(v[2]), node(v[3]), mid(0, 1), mid(1, 2), mid(2, 0), mid(3, 0),
                         mid(3, 2), mid(3, 1)},
                        ci % 2 == 0 ? 0 : farfield);
        }
      }
  for (std::size_t f = 0; f < m.faces().size(); ++f) {
    const auto& v = m.faces()[f].vertices;
    bool at_x0 = true;
    for (int k = 0; k < m.faces()[f].num_vertices; ++k) at_x0 = at_x0 && m.node(v[k]).x() == 0.0;
    if (at_x0) m.add_boundary_face("wall", Shape::Triangle, m.face_nodes(f));
  }
  return t;
}

TEST(Compact, ReplacingNodesInPlaceOverManyBlocksGivesTheEntitiesOfAFreshBuild) {
  ManyTets t = many_doubled_tets(18);
  ASSERT_GT(t.mesh.elements().size(), 30000u) << "several of replace_nodes' blocks";
  const Mesh expected = built_afresh(t.mesh, t.to);
  std::vector<double> reported;
  EXPECT_EQ(t.mesh.replace_nodes(t.to, {}, [&](double f) { reported.push_back(f); }), Mesh::EntityUpdate::Remapped);
  EXPECT_EQ(t.mesh.num_nodes(), t.first.size());
  expect_same_entities(t.mesh, expected);
  ASSERT_FALSE(reported.empty());
  EXPECT_TRUE(std::is_sorted(reported.begin(), reported.end()));
  EXPECT_EQ(reported.back(), 1.0);
}

TEST(Compact, ReplacingNodesByRebuildOverManyBlocksGivesTheEntitiesOfAFreshBuild) {
  ManyTets t = many_doubled_tets(6);
  const Mesh expected = built_afresh(t.mesh, t.to);
  t.mesh.replace_nodes_by_rebuild(t.to);
  expect_same_entities(t.mesh, expected);
}

// Only the vertices welded: the joined edges' and faces' inner nodes are other ids at the same
// places, which the rebuild accepts (the first element's stay, the others' are left unused); the
// remap does not guess, and the rebuild runs.
TEST(Compact, JoinedEntitiesWithOtherInnerNodesAreRebuilt) {
  ManyTets t = many_doubled_tets(4);
  std::vector<NodeId> vertices_only(t.to.size());
  for (NodeId v = 0; v < vertices_only.size(); ++v) vertices_only[v] = v;
  for (std::size_t e = 0; e < t.mesh.elements().size(); ++e)
    for (int k = 0; k < 4; ++k) {
      const NodeId v = t.mesh.elements()[e].vertices[k];
      vertices_only[v] = t.to[v];
    }
  const Mesh expected = built_afresh(t.mesh, vertices_only);
  EXPECT_EQ(t.mesh.replace_nodes(vertices_only), Mesh::EntityUpdate::Rebuilt);
  expect_same_entities(t.mesh, expected);
}

// Another thread reading each element as soon as `rebuilt` passes it sees the node list and points
// it has when the rebuild is over (what the weld's certification behind the rebuild relies on).
TEST(Compact, ReplacingNodesInPlacePublishesEachElementOnlyWhenItNoLongerChanges) {
  ManyTets t = many_doubled_tets(18);
  const std::size_t n = t.mesh.elements().size();
  std::atomic<std::size_t> rebuilt{0};
  std::atomic<bool> over{false};
  std::vector<std::vector<NodeId>> seen(n);
  std::vector<Eigen::MatrixX3d> seen_points(n);
  std::thread reader([&] {
    for (std::size_t e = 0; e < n; ++e) {
      while (rebuilt.load(std::memory_order_acquire) <= e)
        if (over.load() && rebuilt.load() <= e) return;  // `over` comes after the last store
      seen[e] = t.mesh.element_nodes(e);
      seen_points[e] = t.mesh.element_coordinates(e);
    }
  });
  t.mesh.replace_nodes(t.to, {}, {}, &rebuilt);
  over.store(true);
  reader.join();
  ASSERT_EQ(rebuilt.load(), n);
  for (std::size_t e = 0; e < n; ++e) {
    ASSERT_EQ(seen[e], t.mesh.element_nodes(e)) << e;
    ASSERT_EQ(seen_points[e], t.mesh.element_coordinates(e)) << e;
  }
}

TEST(Compact, ReplacingNodesInPlaceThrowsTheFreshBuildsErrorFromALateBlock) {
  ManyTets t = many_doubled_tets(18);
  // The last element's vertex 1 onto its vertex 0: it then names one vertex twice.
  const std::vector<NodeId> last = t.mesh.element_nodes(t.mesh.elements().size() - 1);
  t.to[last[1]] = t.to[last[0]];
  std::string fresh, in_place;
  try {
    built_afresh(t.mesh, t.to);
  } catch (const std::invalid_argument& e) {
    fresh = e.what();
  }
  try {
    t.mesh.replace_nodes(t.to);
  } catch (const std::invalid_argument& e) {
    in_place = e.what();
  }
  EXPECT_NE(fresh.find("appears twice"), std::string::npos) << fresh;
  EXPECT_EQ(in_place, fresh);
}

// A weld that makes two quadrilaterals one face in two vertex cycles (twisted) is refused as a
// fresh build refuses it, wherever that face comes among the remap's faces (it makes them in two
// halves, on two threads): first, or last.
TEST(Compact, ReplacingNodesRefusesATwistedQuadrilateralAsAFreshBuildDoes) {
  for (bool last : {false, true}) {
    Mesh m(2);
    // A hexahedron of its own nodes (order 2: 27), the unit cube at `at`; returns its node ids.
    const auto add_cube = [&](const Eigen::Vector3d& at) {
      const Eigen::MatrixX3d ref = semimesh::ho::reference_nodes(Shape::Hexahedron, 2, semimesh::ho::NodeSet::Equispaced);
      std::vector<NodeId> ids;
      for (int i = 0; i < ref.rows(); ++i) ids.push_back(m.add_node(at + 0.5 * (ref.row(i).transpose() + Eigen::Vector3d::Ones())));
      m.add_element(Shape::Hexahedron, ids);
      return ids;
    };
    std::vector<NodeId> below, above;
    if (!last) below = add_cube({0, 0, -1}), above = add_cube({0, 0, 1});
    for (int k = 0; k < 300; ++k) add_cube({3.0 + 2 * k, 0, 0});  // ~1,800 other faces
    if (last) below = add_cube({0, 0, -1}), above = add_cube({0, 0, 1});
    std::vector<NodeId> to(m.num_nodes());
    for (NodeId v = 0; v < m.num_nodes(); ++v) to[v] = v;
    // The upper cube's bottom (vertices 0-3) onto the lower one's top (4-7), two corners swapped: the
    // same four vertices in another cycle. (Its other nodes go onto themselves: only the vertices matter.)
    const int onto[4] = {4, 6, 5, 7};
    for (int k = 0; k < 4; ++k) to[above[k]] = below[onto[k]];
    std::string fresh, in_place;
    try {
      built_afresh(m, to);
    } catch (const std::invalid_argument& e) {
      fresh = e.what();
    }
    try {
      m.replace_nodes(to);
    } catch (const std::invalid_argument& e) {
      in_place = e.what();
    }
    EXPECT_NE(fresh.find("different cycle"), std::string::npos) << (last ? "last: " : "first: ") << fresh;
    EXPECT_EQ(in_place, fresh) << (last ? "last" : "first");
  }
}

// A mesh with the nodes (the first `nodes` of them), regions and the first `elements` elements of
// `m`, each added by add_element.
Mesh first_elements_of(const Mesh& m, std::size_t nodes, std::size_t elements) {
  Mesh out(m.order(), m.node_set());
  for (NodeId v = 0; v < nodes; ++v) out.add_node(m.node(v), m.cad_attachment(v));
  out.copy_regions_from(m);
  for (std::size_t e = 0; e < elements; ++e)
    out.add_element(m.elements()[e].shape, m.element_nodes(e), m.elements()[e].region);
  return out;
}

TEST(Compact, AddingAnotherMeshsElementsOverManyBlocksIsAddingThemOneByOne) {
  const ManyTets t = many_doubled_tets(18);
  const Mesh& m = t.mesh;
  const Mesh expected = first_elements_of(m, m.num_nodes(), m.elements().size());
  Mesh out = first_elements_of(m, m.num_nodes(), 1000);
  out.add_elements_of(m, 1000, 1000);  // none
  out.add_elements_of(m, 1000, m.elements().size());
  expect_same_entities(out, expected);
  EXPECT_THROW(out.add_elements_of(m, 5, 4), std::out_of_range);
  EXPECT_THROW(out.add_elements_of(m, 0, m.elements().size() + 1), std::out_of_range);
  EXPECT_THROW(out.add_elements_of(out, 0, 1), std::invalid_argument);
}

// Elements that come over as they are into a mesh that took all the entities (the split's
// copies): the elements add_element makes, and, renumbered, its entities; a mesh that did not
// take them refuses them.
TEST(Compact, ElementsComeOverAsTheyAreIntoAMeshThatTookTheEntities) {
  const ManyTets t = many_doubled_tets(4);
  const Mesh& m = t.mesh;
  Mesh out(m.order(), m.node_set());
  for (NodeId v = 0; v < m.num_nodes(); ++v) out.add_node(m.node(v), m.cad_attachment(v));
  out.copy_regions_from(m);
  out.adopt_all_entities(m);
  const std::size_t half = m.elements().size() / 2;
  out.add_elements_as_in(m, 0, half);
  for (std::size_t e = half; e < m.elements().size(); ++e)  // new elements find the taken entities
    out.add_element(m.elements()[e].shape, m.element_nodes(e), m.elements()[e].region);
  for (std::size_t b = 0; b < m.boundary_faces().size(); ++b)
    out.add_boundary_face(m.group_names()[m.boundary_faces()[b].group], m.boundary_faces()[b].shape,
                          m.boundary_face_nodes(b));
  ASSERT_EQ(out.elements().size(), m.elements().size());
  for (std::size_t e = 0; e < m.elements().size(); ++e) EXPECT_EQ(out.element_nodes(e), m.element_nodes(e)) << e;
  EXPECT_EQ(out.edges().size(), m.edges().size());
  EXPECT_EQ(out.faces().size(), m.faces().size());
  expect_same_entities(semimesh::mesh::without_unreferenced_nodes(out), semimesh::mesh::without_unreferenced_nodes(m));
  EXPECT_THROW(out.add_elements_as_in(m, 5, 4), std::out_of_range);
  EXPECT_THROW(out.adopt_all_entities(m), std::logic_error);  // it has entities already
  Mesh fresh = first_elements_of(m, m.num_nodes(), 0);
  EXPECT_THROW(fresh.add_elements_as_in(m, 0, 1), std::logic_error);  // it took no entities
  // A mesh given up gives its lookups instead of a copy: the same finds here, none left there.
  Mesh given = m, taker = first_elements_of(m, m.num_nodes(), 0);
  EXPECT_THROW(taker.adopt_all_entities(m, &given), std::invalid_argument);  // not the mesh adopted
  taker.adopt_all_entities(given, &given);
  for (std::size_t e = 0; e < m.edges().size(); ++e) {
    const auto& v = m.edges()[e].vertices;
    EXPECT_EQ(taker.find_edge(v[0], v[1]), static_cast<long>(e));
    EXPECT_EQ(given.find_edge(v[0], v[1]), -1);
  }
  for (std::size_t f = 0; f < m.faces().size(); ++f) {
    const semimesh::mesh::Face& face = m.faces()[f];
    const std::vector<NodeId> v(face.vertices.begin(), face.vertices.begin() + face.num_vertices);
    EXPECT_EQ(taker.find_face(v), static_cast<long>(f));
    EXPECT_EQ(given.find_face(v), -1);
  }
}

TEST(Compact, AddingAnotherMeshsElementsThrowsTheOneByOneErrorFromALateBlock) {
  const ManyTets t = many_doubled_tets(18);
  const Mesh& m = t.mesh;
  // Without the last node the elements use: the first element naming it fails, in a late block.
  NodeId last_used = 0;
  for (std::size_t e = 0; e < m.elements().size(); ++e)
    for (NodeId v : m.element_nodes(e)) last_used = std::max(last_used, v);
  std::string one_by_one, in_blocks;
  try {
    first_elements_of(m, last_used, m.elements().size());
  } catch (const std::invalid_argument& e) {
    one_by_one = e.what();
  }
  Mesh out = first_elements_of(m, last_used, 0);
  try {
    out.add_elements_of(m, 0, m.elements().size());
  } catch (const std::invalid_argument& e) {
    in_blocks = e.what();
  }
  EXPECT_NE(one_by_one.find("unknown node id"), std::string::npos) << one_by_one;
  EXPECT_EQ(in_blocks, one_by_one);
}

TEST(Compact, ReplacingNodesInPlaceRefusesABadMapWithoutChangingTheMesh) {
  DoubledFace d = two_order3_hexes_with_a_doubled_face();
  const std::vector<Eigen::Vector3d> before = d.mesh.nodes();
  const std::size_t faces = d.mesh.faces().size();
  std::vector<NodeId> short_map(d.to.begin(), d.to.end() - 1);
  EXPECT_THROW(d.mesh.replace_nodes(short_map), std::invalid_argument);
  EXPECT_EQ(d.mesh.nodes(), before);
  EXPECT_EQ(d.mesh.faces().size(), faces);
}

}  // namespace
