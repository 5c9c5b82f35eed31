// The weld (pipeline/weld_nodes.hpp): two hexes given their shared face twice (as the far field's
// pre-cut skin and the split give one point two ids) become one conforming pair; only the nodes
// still used are kept, in order; the progress it reports rises to 1 through its steps. At high
// order a pyramid standing on a hex's curved face (as the far field's pyramids on the split's
// pieces of a curved rear interface) takes the hex's nodes by their place, however far the curve
// bulges, and follows the curve inwards.
#include "semimesh/pipeline/weld_nodes.hpp"

#include "semimesh/ho/basis.hpp"
#include "semimesh/ho/element_type.hpp"
#include "semimesh/ho/validity.hpp"
#include "semimesh/mesh/node_layout.hpp"

#include <gtest/gtest.h>

#include "highorder/mesh/same_entities.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <map>
#include <random>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>
#include <vector>

namespace semimesh::pipeline {
namespace {

mesh::Mesh two_hexes_with_a_doubled_face() {
  mesh::Mesh m(1);
  std::vector<mesh::NodeId> id;
  for (int side = 0; side < 2; ++side)  // hex `side` spans x in [side, side + 1]: 8 nodes each
    for (int k = 0; k < 8; ++k) {
      const int corner[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
      id.push_back(m.add_node(Eigen::Vector3d(side + corner[k][0], corner[k][1], corner[k][2])));
    }
  const int region = m.region_index("volume");
  m.add_element(ho::Shape::Hexahedron, std::vector<mesh::NodeId>(id.begin(), id.begin() + 8), region);
  m.add_element(ho::Shape::Hexahedron, std::vector<mesh::NodeId>(id.begin() + 8, id.end()), region);
  m.add_node(Eigen::Vector3d(5, 5, 5));  // used by nothing
  return m;
}

TEST(WeldNodes, DoubledFaceBecomesOneKeepingOnlyUsedNodesAndReportsProgress) {
  const mesh::Mesh m = two_hexes_with_a_doubled_face();
  ASSERT_EQ(m.faces().size(), 12u);  // the face at x = 1 twice
  std::vector<std::pair<double, std::string>> seen;
  const Welded w = weld_coincident_nodes(m, 1e-9, [&](double f, const std::string& step) { seen.push_back({f, step}); });
  EXPECT_EQ(w.merged, 4u);
  EXPECT_EQ(w.mesh.num_nodes(), 12u);  // 17 - 4 welded - 1 unused
  EXPECT_EQ(w.mesh.faces().size(), 11u);
  EXPECT_EQ(w.mesh.elements().size(), 2u);
  std::vector<Eigen::Vector3d> kept;  // the old nodes in order, less hex 1's welded face and the unused one
  for (mesh::NodeId v = 0; v < 16; ++v)
    if (v < 8 || m.node(v).x() != 1.0) kept.push_back(m.node(v));
  ASSERT_EQ(kept.size(), w.mesh.num_nodes());
  for (std::size_t v = 0; v < kept.size(); ++v) EXPECT_EQ(w.mesh.node(static_cast<mesh::NodeId>(v)), kept[v]) << v;
  ASSERT_FALSE(seen.empty());
  for (std::size_t k = 1; k < seen.size(); ++k) EXPECT_GE(seen[k].first, seen[k - 1].first);
  EXPECT_EQ(seen.back().first, 1.0);
  EXPECT_EQ(seen.front().second, "vertices");
  EXPECT_EQ(seen.back().second, "mesh");
}

// Points within the tolerance weld wherever they fall in the index's cells (offsets in every
// direction, the shared face at many places against the cells' borders); points beyond it do not.
TEST(WeldNodes, PointsWithinTheToleranceWeldAcrossTheIndexCellsAndOthersDoNot) {
  const double tolerance = 1e-3;
  std::mt19937 random(9);
  std::uniform_real_distribution<double> unit(-1.0, 1.0), shift(0.0, 1.0);
  for (int trial = 0; trial < 200; ++trial) {
    const bool within = trial % 2 == 0;
    const Eigen::Vector3d origin(shift(random), shift(random), shift(random));
    mesh::Mesh m(1);
    std::vector<mesh::NodeId> id;
    const int corner[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
    for (int side = 0; side < 2; ++side)
      for (int k = 0; k < 8; ++k) {
        Eigen::Vector3d x = origin + Eigen::Vector3d(side + corner[k][0], corner[k][1], corner[k][2]);
        if (side == 1 && corner[k][0] == 0) {  // hex 1's copy of the shared face, moved off it
          const Eigen::Vector3d direction = Eigen::Vector3d(unit(random), unit(random), unit(random)).normalized();
          x += (within ? 0.9 : 1.2) * tolerance * direction;
        }
        id.push_back(m.add_node(x));
      }
    m.add_element(ho::Shape::Hexahedron, std::vector<mesh::NodeId>(id.begin(), id.begin() + 8));
    m.add_element(ho::Shape::Hexahedron, std::vector<mesh::NodeId>(id.begin() + 8, id.end()));
    const Welded w = weld_coincident_nodes(m, tolerance);
    EXPECT_EQ(w.merged, within ? 4u : 0u) << "trial " << trial;
    EXPECT_EQ(w.mesh.faces().size(), within ? 11u : 12u) << "trial " << trial;
  }
}

// Only open faces' vertices weld (those of a face one element uses and no boundary face covers):
// in a stack of hexes x in [0, 1], [1, 1 + thin], [1 + thin, 2 + thin], the thin one thinner than
// the tolerance (a thin boundary layer's), the third given its own copy of the face it shares
// with the second, and boundary faces on the rest of the outside, the copies weld and the thin
// hex's two faces, within tolerance of each other, stay apart.
TEST(WeldNodes, VerticesOffTheOpenFacesNeverWeldHoweverNear) {
  const double tolerance = 1e-3, thin = 0.5 * tolerance;
  const int corner[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  mesh::Mesh m(1);
  std::array<std::vector<mesh::NodeId>, 3> hexes;
  for (const auto& c : corner) hexes[0].push_back(m.add_node(Eigen::Vector3d(c[0], c[1], c[2])));
  for (int k = 0; k < 8; ++k)  // at x = 1: hex 0's vertex with the same y, z (corner k ^ 1)
    hexes[1].push_back(corner[k][0] == 0 ? hexes[0][k ^ 1]
                                          : m.add_node(Eigen::Vector3d(1 + thin, corner[k][1], corner[k][2])));
  for (const auto& c : corner) hexes[2].push_back(m.add_node(Eigen::Vector3d(1 + thin + c[0], c[1], c[2])));
  for (const auto& hex : hexes) m.add_element(ho::Shape::Hexahedron, hex);
  // Boundary faces on every face one hex uses, but the doubled one (its two copies at x = 1 + thin).
  std::map<std::vector<mesh::NodeId>, int> uses;
  const auto key = [](std::vector<mesh::NodeId> ids) { return std::sort(ids.begin(), ids.end()), ids; };
  std::vector<std::vector<mesh::NodeId>> faces;
  for (const auto& hex : hexes)
    for (const auto& local : ho::faces(ho::Shape::Hexahedron)) {
      std::vector<mesh::NodeId> ids;
      for (int v : local) ids.push_back(hex[v]);
      ++uses[key(ids)];
      faces.push_back(ids);
    }
  for (const auto& ids : faces) {
    const bool doubled = std::all_of(ids.begin(), ids.end(), [&](mesh::NodeId v) { return m.node(v).x() == 1 + thin; });
    if (uses[key(ids)] == 1 && !doubled) m.add_boundary_face("outside", ho::Shape::Quadrilateral, ids);
  }
  ASSERT_EQ(m.faces().size(), 17u);  // 3 x 6, the face at x = 1 once
  const Welded w = weld_coincident_nodes(m, tolerance);
  EXPECT_EQ(w.merged, 4u);
  EXPECT_EQ(w.mesh.num_nodes(), 16u);  // 20 less the copy's 4
  EXPECT_EQ(w.mesh.faces().size(), 16u);
  EXPECT_EQ(w.mesh.elements().size(), 3u);
}

// The work beside the rebuild reads each element once it is rebuilt and sees its final points; it
// runs on another thread, ends before the weld returns, and the weld's mesh is the same without it.
TEST(WeldNodes, WorkBesideTheRebuildSeesEachElementOnceRebuiltOnAnotherThread) {
  const mesh::Mesh m = two_hexes_with_a_doubled_face();
  std::vector<Eigen::MatrixX3d> seen;
  std::thread::id beside_thread;
  bool stopped = false;
  const BesideRebuild beside = [&](const mesh::Mesh& being_rebuilt, const std::atomic<std::size_t>& rebuilt,
                                   const std::atomic<bool>& stop) {
    beside_thread = std::this_thread::get_id();
    for (std::size_t e = 0; e < being_rebuilt.elements().size(); ++e) {
      while (rebuilt.load(std::memory_order_acquire) <= e)
        if (stop.load() && rebuilt.load() <= e) return;  // `stop` comes after the last store
      seen.push_back(being_rebuilt.element_coordinates(e));
    }
    while (!stop.load()) std::this_thread::yield();
    stopped = true;
  };
  const Welded w = weld_coincident_nodes(m, 1e-9, {}, beside);
  EXPECT_TRUE(stopped);
  EXPECT_NE(beside_thread, std::this_thread::get_id());
  ASSERT_EQ(seen.size(), 2u);
  for (std::size_t e = 0; e < 2; ++e) EXPECT_EQ(seen[e], w.mesh.element_coordinates(e)) << e;
  const Welded alone = weld_coincident_nodes(m, 1e-9);
  ASSERT_EQ(alone.mesh.num_nodes(), w.mesh.num_nodes());
  for (std::size_t e = 0; e < 2; ++e) EXPECT_EQ(alone.mesh.element_nodes(e), w.mesh.element_nodes(e)) << e;
}

constexpr int kOrder = 3;
constexpr ho::NodeSet kSet = ho::NodeSet::GLL;

// The nodes of an order-kOrder element mapped from its vertices by its linear (P1) map.
Eigen::MatrixX3d straight_nodes(ho::Shape shape, const Eigen::MatrixX3d& vertices) {
  return ho::LagrangeBasis(shape, 1, ho::NodeSet::Equispaced).values(ho::reference_nodes(shape, kOrder, kSet)) * vertices;
}

std::vector<mesh::NodeId> add_nodes(mesh::Mesh& m, const Eigen::MatrixX3d& x) {
  std::vector<mesh::NodeId> ids;
  for (int k = 0; k < x.rows(); ++k) ids.push_back(m.add_node(x.row(k).transpose()));
  return ids;
}

// The hex's top face z = 0 bulges up near its edge y = 0 (by `bulge` at the edge's middle).
double lift(const Eigen::Vector3d& x, double bulge) {
  return bulge * 4.0 * x.x() * (1.0 - x.x()) * std::pow(1.0 - x.y(), 4) * (1.0 + x.z());
}

// A hex [0, 1]^2 x [-1, 0] lifted by `lift` (zero on its other faces), added first (the split's
// curved element), then a straight pyramid of apex height `apex` on its top face with nodes of its
// own (the far field's, on the pre-cut quad). `base_order`: the pyramid's base vertices, as indices
// into the hex's top face (0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0).
mesh::Mesh pyramid_on_a_bulging_hex(double bulge, double apex, std::array<int, 4> base_order = {0, 1, 2, 3}) {
  mesh::Mesh m(kOrder, kSet);
  Eigen::MatrixX3d hex_vertices(8, 3), top(4, 3), pyramid_vertices(5, 3);
  hex_vertices << 0, 0, -1, 1, 0, -1, 1, 1, -1, 0, 1, -1, 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0;
  top << 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0;
  for (int k = 0; k < 4; ++k) pyramid_vertices.row(k) = top.row(base_order[k]);
  pyramid_vertices.row(4) << 0.5, 0.5, apex;
  Eigen::MatrixX3d hex = straight_nodes(ho::Shape::Hexahedron, hex_vertices);
  for (int k = 0; k < hex.rows(); ++k) hex(k, 2) += lift(hex.row(k).transpose(), bulge);
  m.add_element(ho::Shape::Hexahedron, add_nodes(m, hex));
  m.add_element(ho::Shape::Pyramid, add_nodes(m, straight_nodes(ho::Shape::Pyramid, pyramid_vertices)));
  return m;
}

bool on_pyramid_base(int canonical) {
  return std::abs(ho::reference_nodes(ho::Shape::Pyramid, kOrder, kSet)(canonical, 2)) < 1e-12;
}

TEST(WeldNodes, InnerNodesTakeTheirPlaceInTheEntityHoweverFarTheCurveBulges) {
  // The edge y = 0 bulges by 0.4 at its inner nodes, nearly their spacing (0.45): the nearest of
  // the hex's nodes to a straight one is not clearly its own (the old rule left both unmatched
  // and the rebuild threw).
  const double bulge = 0.5;
  const mesh::Mesh m = pyramid_on_a_bulging_hex(bulge, 0.5);
  const Welded w = weld_coincident_nodes(m, 1e-9);
  ASSERT_EQ(w.mesh.elements().size(), 2u);
  EXPECT_EQ(w.mesh.faces().size(), 10u);  // 6 + 5, the base once
  EXPECT_EQ(w.mesh.num_nodes(), static_cast<std::size_t>(64 + 30 - 16));  // the base's 16 nodes once
  EXPECT_EQ(w.merged, 16u);
  EXPECT_NEAR(w.largest_move, bulge * 4.0 * 0.276393202250021 * 0.723606797749979, 1e-12);
  // Each base node of the pyramid is the hex's node at its own place: its straight point lifted.
  const Eigen::MatrixX3d straight = m.element_coordinates(1), welded = w.mesh.element_coordinates(1);
  for (int i = 0; i < straight.rows(); ++i) {
    if (!on_pyramid_base(i)) continue;
    Eigen::Vector3d expected = straight.row(i).transpose();
    expected.z() += lift(expected, bulge);
    EXPECT_LT((welded.row(i).transpose() - expected).norm(), 1e-12) << "node " << i;
  }
}

TEST(WeldNodes, FarFieldElementFollowsTheMovedEdgeInwards) {
  // A bulge of 0.2 (0.16 at the edge's inner nodes: the old nearest rule matched them): the
  // pyramid with only its base moved onto the hex's is inverted; carrying the move inwards (the
  // harmonic extension of its new boundary, as curving gives) keeps it valid.
  const mesh::Mesh m = pyramid_on_a_bulging_hex(0.2, 0.5);
  const Welded w = weld_coincident_nodes(m, 1e-9);
  ASSERT_TRUE(ho::certify_jacobian(ho::Shape::Pyramid, kOrder, kSet, m.element_coordinates(1)).valid);
  const Eigen::MatrixX3d welded = w.mesh.element_coordinates(1);
  Eigen::MatrixX3d matched_only = welded;  // the base from the hex, the rest where it was
  for (int i = 0; i < welded.rows(); ++i)
    if (!on_pyramid_base(i)) matched_only.row(i) = m.element_coordinates(1).row(i);
  EXPECT_FALSE(ho::certify_jacobian(ho::Shape::Pyramid, kOrder, kSet, matched_only).valid);
  EXPECT_TRUE(ho::certify_jacobian(ho::Shape::Pyramid, kOrder, kSet, welded).valid);
  EXPECT_TRUE(ho::certify_jacobian(ho::Shape::Hexahedron, kOrder, kSet, w.mesh.element_coordinates(0)).valid);
  // Moved: the inner node of the triangle face on the edge y = 0 and the pyramid's own.
  EXPECT_EQ(w.carried, 2u);
  // The entities renamed and joined in place (the base snapped by slot), as a fresh build makes them.
  EXPECT_EQ(w.entities, mesh::Mesh::EntityUpdate::Remapped);
  test::expect_same_entities(w.mesh, test::built_afresh(w.mesh));
}

TEST(WeldNodes, FaceWhoseWeldedVerticesAreNoRotationOfAnothersIsAnInternalError) {
  // The pyramid's base crosses itself (vertices 0, 2, 1, 3 of the hex's top): the same four
  // points, in an order no rotation or reflection gives.
  const mesh::Mesh m = pyramid_on_a_bulging_hex(0.0, 0.5, {0, 2, 1, 3});
  try {
    weld_coincident_nodes(m, 1e-9);
    FAIL() << "expected std::logic_error";
  } catch (const std::logic_error& e) {
    EXPECT_NE(std::string(e.what()).find("weld: face "), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("no rotation or reflection"), std::string::npos) << e.what();
  }
}

// Order 3: hex 1's nodes inside its face at x = 1 (and inside that face's edges along z) stand 0.13
// off hex 0's along z, the spacing being 1/3, as the split's interfaces stand off a far-field skin
// quad's straight ones: none is clearly the nearest of its counterpart. The weld pairs them by their
// slot in the welded edge or face and gives hex 1 hex 0's nodes (before: left apart, the rebuild
// threw an internal error).
TEST(WeldNodes, InnerNodesOfAWeldedFacePairBySlotNotByNearestPoint) {
  mesh::Mesh m(3);
  const Eigen::MatrixX3d reference = ho::reference_nodes(ho::Shape::Hexahedron, 3);
  const int region = m.region_index("volume");
  auto inside = [](double t) { return t > 1e-9 && t < 1.0 - 1e-9; };
  for (int side = 0; side < 2; ++side) {
    std::vector<mesh::NodeId> ids;
    for (int i = 0; i < reference.rows(); ++i) {
      Eigen::Vector3d x = 0.5 * (reference.row(i).transpose() + Eigen::Vector3d::Ones());
      x.x() += side;
      if (side == 1 && std::abs(x.x() - 1.0) < 1e-9 && inside(x.z())) x.z() += 0.13;
      ids.push_back(m.add_node(x));
    }
    m.add_element(ho::Shape::Hexahedron, ids, region);
  }
  const Welded w = weld_coincident_nodes(m, 1e-9);
  EXPECT_EQ(w.mesh.elements().size(), 2u);
  EXPECT_EQ(w.mesh.faces().size(), 11u);  // the face at x = 1 once
  int on_face = 0;
  for (mesh::NodeId v = 0; v < w.mesh.num_nodes(); ++v) {
    const Eigen::Vector3d& x = w.mesh.node(v);
    if (std::abs(x.x() - 1.0) > 1e-9) continue;
    ++on_face;
    const double thirds = 3.0 * x.z();
    EXPECT_NEAR(thirds, std::round(thirds), 1e-9) << "a node of hex 1's face kept at z = " << x.z();
  }
  EXPECT_EQ(on_face, 16);  // one order-3 quad's nodes
}

}  // namespace
}  // namespace semimesh::pipeline
