// Element sizes and Gmsh's edge/face tables.
#include "semimesh/ho/element_type.hpp"
#include "all_shapes.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <set>
#include <stdexcept>

namespace semimesh::ho {
namespace {

using testing::kAllShapes;

TEST(ElementType, DimensionsAndVertexCounts) {
  EXPECT_EQ(dimension(Shape::Segment), 1);
  EXPECT_EQ(dimension(Shape::Quadrilateral), 2);
  EXPECT_EQ(dimension(Shape::Pyramid), 3);
  EXPECT_EQ(num_vertices(Shape::Pyramid), 5);
  EXPECT_EQ(num_vertices(Shape::Prism), 6);
  EXPECT_EQ(num_vertices(Shape::Hexahedron), 8);
  for (Shape shape : kAllShapes) EXPECT_EQ(reference_vertices(shape).rows(), num_vertices(shape));
}

// Counts of the Gmsh element types (MSH type table: tri 10/15, tet 20/35, pyr 14/30, prism 18/40,
// hex 27/64) and the closed forms of the polynomial spaces.
TEST(ElementType, NodeCounts) {
  EXPECT_EQ(num_nodes(Shape::Triangle, 3), 10);
  EXPECT_EQ(num_nodes(Shape::Triangle, 4), 15);
  EXPECT_EQ(num_nodes(Shape::Tetrahedron, 3), 20);
  EXPECT_EQ(num_nodes(Shape::Tetrahedron, 4), 35);
  EXPECT_EQ(num_nodes(Shape::Pyramid, 2), 14);
  EXPECT_EQ(num_nodes(Shape::Pyramid, 3), 30);
  EXPECT_EQ(num_nodes(Shape::Prism, 2), 18);
  EXPECT_EQ(num_nodes(Shape::Prism, 3), 40);
  EXPECT_EQ(num_nodes(Shape::Hexahedron, 2), 27);
  EXPECT_EQ(num_nodes(Shape::Hexahedron, 3), 64);
  for (int p = 1; p <= kMaxOrder; ++p) {
    int pyramid_layers = 0;  // layer k of an order-p pyramid is a (p-k+1)^2 grid
    for (int k = 0; k <= p; ++k) pyramid_layers += (p - k + 1) * (p - k + 1);
    EXPECT_EQ(num_nodes(Shape::Pyramid, p), pyramid_layers);
    EXPECT_EQ(num_nodes(Shape::Pyramid, p), (p + 1) * (p + 2) * (2 * p + 3) / 6);
    EXPECT_EQ(num_nodes(Shape::Prism, p), num_nodes(Shape::Triangle, p) * (p + 1));
    EXPECT_EQ(num_nodes(Shape::Segment, p), p + 1);
  }
  EXPECT_THROW(num_nodes(Shape::Triangle, 0), std::invalid_argument);
}

TEST(ElementType, EdgeAndFaceCountsMatchEuler) {
  // V - E + F = 2 for the 3D shapes.
  for (Shape shape : {Shape::Tetrahedron, Shape::Pyramid, Shape::Prism, Shape::Hexahedron}) {
    const int v = num_vertices(shape);
    const int e = static_cast<int>(edges(shape).size());
    const int f = static_cast<int>(faces(shape).size());
    EXPECT_EQ(v - e + f, 2) << to_string(shape);
  }
  EXPECT_EQ(edges(Shape::Triangle).size(), 3u);
  EXPECT_EQ(edges(Shape::Quadrilateral).size(), 4u);
}

// Every face's boundary is made of the element's edges, and every edge bounds exactly two faces.
TEST(ElementType, FacesAreBoundedByEdges) {
  for (Shape shape : {Shape::Tetrahedron, Shape::Pyramid, Shape::Prism, Shape::Hexahedron}) {
    std::multiset<std::pair<int, int>> face_edges;
    for (const auto& face : faces(shape))
      for (std::size_t i = 0; i < face.size(); ++i) {
        const int a = face[i], b = face[(i + 1) % face.size()];
        face_edges.insert({std::min(a, b), std::max(a, b)});
      }
    for (const auto& edge : edges(shape))
      EXPECT_EQ(face_edges.count({std::min(edge[0], edge[1]), std::max(edge[0], edge[1])}), 2u)
          << to_string(shape) << " edge " << edge[0] << "-" << edge[1];
    EXPECT_EQ(face_edges.size(), 2 * edges(shape).size());
  }
}

TEST(ElementType, FaceNormalsPointOutward) {
  for (Shape shape : {Shape::Tetrahedron, Shape::Pyramid, Shape::Prism, Shape::Hexahedron}) {
    const Eigen::MatrixX3d v = reference_vertices(shape);
    const Eigen::Vector3d centroid = v.colwise().mean();
    for (const auto& face : faces(shape)) {
      const Eigen::Vector3d a = v.row(face[0]), b = v.row(face[1]), c = v.row(face[2]);
      const Eigen::Vector3d normal = (b - a).cross(c - a);
      EXPECT_GT(normal.dot(a - centroid), 0.0) << to_string(shape) << " face starting at " << face[0];
    }
  }
}

}  // namespace
}  // namespace semimesh::ho
