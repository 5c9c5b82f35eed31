// Faces cut in advance (a sharp trailing edge's fan on a junction hex's face): after curving, the
// strips' nodes go onto the curved face, so the face's owner, once split at the cuts, meets them
// node for node; a planar face leaves the mesh bit for bit.
#include "semimesh/ho/splitting/precut_faces.hpp"

#include "semimesh/ho/basis.hpp"
#include "semimesh/ho/splitting/split_layers.hpp"

#include <gtest/gtest.h>

#include <array>
#include <functional>
#include <map>
#include <stdexcept>
#include <string>

namespace semimesh::ho {
namespace {

using Map = std::function<Eigen::Vector3d(const Eigen::Vector3d&)>;
constexpr double kCut = 0.3;  // the cut across the face, 1 / (1 + r) for two layers growing by r = 7/3

// Hex A = [0,1]^3 under `curve` (its face y = 0 curved when curve is), and beside it the strips'
// owners B0 = [0,cut] x [-1,0] x [0,1], B1 = [cut,1] x [-1,0] x [0,1], straight: the pipeline's
// junction hex and fan prisms after curving, before the split. Nodes at one place are one node.
struct Bench {
  mesh::Mesh mesh;
  PrecutFace face;
};

Bench hex_and_strips(int order, NodeSet set, const Map& curve) {
  Bench b{mesh::Mesh(order, set), {}};
  std::map<std::array<long, 3>, mesh::NodeId> by_place;
  auto node = [&](const Eigen::Vector3d& x) {
    const std::array<long, 3> key{std::lround(x(0) * 1e9), std::lround(x(1) * 1e9), std::lround(x(2) * 1e9)};
    const auto it = by_place.find(key);
    return it != by_place.end() ? it->second : by_place[key] = b.mesh.add_node(x);
  };
  const Eigen::MatrixX3d r = reference_nodes(Shape::Hexahedron, order, set);
  auto add_box = [&](const Eigen::Vector3d& lo, const Eigen::Vector3d& hi, const Map& map) {
    std::vector<mesh::NodeId> ids;
    for (Eigen::Index i = 0; i < r.rows(); ++i)
      ids.push_back(node(map(lo + 0.5 * (r.row(i).transpose() + Eigen::Vector3d::Ones()).cwiseProduct(hi - lo))));
    b.mesh.add_element(Shape::Hexahedron, ids);
  };
  const auto straight = [](const Eigen::Vector3d& x) { return x; };
  add_box({0, 0, 0}, {1, 1, 1}, curve);
  add_box({0, -1, 0}, {kCut, 0, 1}, straight);
  add_box({kCut, -1, 0}, {1, 0, 1}, straight);
  b.face.low = {node({0, 0, 0}), node({kCut, 0, 0}), node({1, 0, 0})};
  b.face.high = {node({0, 0, 1}), node({kCut, 0, 1}), node({1, 0, 1})};
  b.face.fractions = {0.0, kCut, 1.0};
  return b;
}

// Hex A's map: its edge y = z = 0 bent down in z (a curved wall under R-L), straight at x = 0, 1
// and on the opposite faces; degree 2 in x, 1 in y and z (any order >= 2 holds it exactly).
Eigen::Vector3d bend(const Eigen::Vector3d& x) {
  return {x(0), x(1), x(2) - 0.4 * x(0) * (1.0 - x(0)) * (1.0 - x(1)) * (1.0 - x(2))};
}

TEST(PrecutFaces, StripNodesLieOnTheCurvedFace) {
  for (NodeSet set : {NodeSet::Equispaced, NodeSet::GLL})
    for (int P : {2, 3}) {
      Bench b = hex_and_strips(P, set, bend);
      const mesh::Mesh before = b.mesh;
      const PrecutStats stats = follow_precut_faces(b.mesh, {b.face}, 1e-12);
      EXPECT_EQ(stats.faces_moved, 1u);
      // The cut's vertex on R-L goes down by 0.4 s (1 - s) at s = cut, the strips' edge nodes on it
      // by up to 0.1 (s = 1/2).
      EXPECT_GE(stats.largest_move, 0.4 * kCut * (1.0 - kCut) - 1e-12);
      EXPECT_LE(stats.largest_move, 0.1 + 1e-12);
      for (std::size_t e : {1u, 2u}) {
        const std::vector<mesh::NodeId> ids = b.mesh.element_nodes(e);
        for (mesh::NodeId v : ids) {
          const Eigen::Vector3d old = before.node(v);
          if (std::abs(old.y()) < 1e-15) {  // on the strip: where the curved face is
            EXPECT_LT((b.mesh.node(v) - bend(old)).norm(), 1e-13) << "P " << P << " node " << v;
          } else if (old.y() < -1.0 + 1e-15) {  // the far side: untouched
            EXPECT_EQ(b.mesh.node(v), old);
          }
        }
      }
      for (mesh::NodeId v : b.mesh.element_nodes(0)) EXPECT_EQ(b.mesh.node(v), before.node(v));  // the hex stays
    }
}

// The hex split at the cut (two layers along x, r = 7/3): its pieces' nodes on the face y = 0 are
// the strips' nodes, which the weld joins (within 1e-9 of the chord); with straight cuts they miss.
TEST(PrecutFaces, SplitHexMeetsTheStripsNodeForNode) {
  for (bool follow : {false, true}) {
    Bench b = hex_and_strips(3, NodeSet::GLL, bend);
    if (follow) follow_precut_faces(b.mesh, {b.face}, 1e-12);
    LayerSplit along_x;
    along_x.element = 0;
    along_x.direction = {0, -1};
    const mesh::Mesh fine = split_layers(b.mesh, {along_x}, {SplitFamily{{2, 7.0 / 3.0}, {}}}, nullptr, nullptr);
    int on_face = 0, matched = 0;
    for (std::size_t e = 0; e < 2; ++e)  // the hex's pieces
      for (mesh::NodeId v : fine.element_nodes(e)) {
        if (std::abs(fine.node(v).y()) > 1e-15) continue;
        ++on_face;
        bool found = false;
        for (std::size_t s : {2u, 3u})  // the strips' owners, after the pieces
          for (mesh::NodeId w : fine.element_nodes(s)) found = found || (fine.node(w) - fine.node(v)).norm() < 1e-12;
        matched += found;
      }
    EXPECT_GT(on_face, 0);
    if (follow) {
      EXPECT_EQ(matched, on_face);
    } else {
      EXPECT_LT(matched, on_face);
    }
  }
}

TEST(PrecutFaces, PlanarFaceLeavesTheMeshBitForBit) {
  Bench b = hex_and_strips(3, NodeSet::GLL, [](const Eigen::Vector3d& x) { return x; });
  const mesh::Mesh before = b.mesh;
  const PrecutStats stats = follow_precut_faces(b.mesh, {b.face}, 1e-12);
  EXPECT_EQ(stats.faces_moved, 0u);
  EXPECT_EQ(stats.nodes_moved, 0u);
  for (mesh::NodeId v = 0; v < before.num_nodes(); ++v) EXPECT_EQ(b.mesh.node(v), before.node(v));
}

TEST(PrecutFaces, RefusesAStripThatIsNotAFaceNamingItsCorners) {
  Bench b = hex_and_strips(2, NodeSet::GLL, bend);
  b.face.low[1] = b.mesh.elements()[1].vertices[1];  // (cut, -1, 0): off the face
  try {
    follow_precut_faces(b.mesh, {b.face}, 1e-12);
    FAIL() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("strip with corners " + std::to_string(b.face.low[0])), std::string::npos)
        << e.what();
  }
  b.face.fractions.pop_back();
  EXPECT_THROW(follow_precut_faces(b.mesh, {b.face}, 1e-12), std::invalid_argument);
}

}  // namespace
}  // namespace semimesh::ho
