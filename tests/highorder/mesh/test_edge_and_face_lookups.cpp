// Two small lookups over a mesh's entities: items by directed edge (mesh/directed_edge_index.hpp)
// against a std::map assigned in turn, the reference; a mesh's open faces (mesh/open_faces.hpp) on
// two hexes given their shared face twice, with and without boundary faces on their outside.
#include "semimesh/mesh/directed_edge_index.hpp"
#include "semimesh/mesh/open_faces.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <random>
#include <utility>

namespace semimesh::mesh {
namespace {

TEST(DirectedEdgeIndex, FindsTheLastItemAddedWithAnEdgeAsAMapAssignedInTurn) {
  std::mt19937 random(5);
  std::uniform_int_distribution<std::uint32_t> node(0, 30);
  DirectedEdgeIndex index;
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::size_t> reference;
  for (std::size_t item = 0; item < 500; ++item) {
    const std::uint32_t a = node(random), b = node(random);
    index.add(a, b, item);
    reference[{a, b}] = item;
  }
  index.sort();
  for (std::uint32_t a = 0; a <= 31; ++a)
    for (std::uint32_t b = 0; b <= 31; ++b) {
      const auto found = index.find(a, b);
      const auto it = reference.find({a, b});
      ASSERT_EQ(found.has_value(), it != reference.end()) << a << " -> " << b;
      if (found) {
        EXPECT_EQ(*found, it->second) << a << " -> " << b;
      }
    }
}

TEST(OpenFaces, TheDoubledFacesCopiesAndTheOutsideWithoutBoundaryFaces) {
  Mesh m(1);
  const int corner[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  std::vector<NodeId> hexes[2];
  for (int side = 0; side < 2; ++side)  // hex `side` spans x in [side, side + 1], its own 8 nodes
    for (const auto& c : corner) hexes[side].push_back(m.add_node(Eigen::Vector3d(side + c[0], c[1], c[2])));
  m.add_element(ho::Shape::Hexahedron, hexes[0]);
  m.add_element(ho::Shape::Hexahedron, hexes[1]);
  EXPECT_EQ(open_faces(m).size(), 12u);  // no boundary faces: every face is open
  for (int side = 0; side < 2; ++side)
    for (const auto& local : ho::faces(ho::Shape::Hexahedron)) {
      std::vector<NodeId> ids;
      for (int v : local) ids.push_back(hexes[side][v]);
      const bool on_x1 = std::all_of(ids.begin(), ids.end(), [&](NodeId v) { return m.node(v).x() == 1.0; });
      if (!on_x1) m.add_boundary_face("outside", ho::Shape::Quadrilateral, ids);
    }
  const std::vector<OpenFace> open = open_faces(m);
  ASSERT_EQ(open.size(), 2u);  // the face at x = 1, once from each hex
  for (const OpenFace& f : open) {
    EXPECT_EQ(m.elements()[f.element].faces[f.local], f.face);
    for (int k = 0; k < 4; ++k) EXPECT_EQ(m.node(m.faces()[f.face].vertices[k]).x(), 1.0);
  }
  EXPECT_NE(open[0].element, open[1].element);
}

}  // namespace
}  // namespace semimesh::mesh
