// Element shapes, reference elements and the canonical node order of high-order elements.
//
// Reference elements are Gmsh's (gmsh.info/doc/texinfo, "Node ordering"):
//   segment  [-1, 1]
//   triangle (0,0) (1,0) (0,1)                 quadrilateral [-1,1]^2
//   tetrahedron (0,0,0) (1,0,0) (0,1,0) (0,0,1)
//   pyramid  base [-1,1]^2 at z = 0, apex (0,0,1)
//   prism    triangle (0,0) (1,0) (0,1) x z in [-1, 1]
//   hexahedron [-1,1]^3
// The canonical node order of an element of order P is Gmsh's MSH order: the vertices, then the
// nodes inside each edge (edge by edge, in Gmsh's edge order and direction), then the nodes inside
// each face (recursively, as a lower-order face element), then the interior nodes (recursively, as a
// lower-order element of the same shape). The mesh stores element nodes in this order; writers for
// other formats permute it.
#pragma once

#include <Eigen/Core>

#include <array>
#include <string>
#include <vector>

namespace semimesh::ho {

enum class Shape { Segment, Triangle, Quadrilateral, Tetrahedron, Pyramid, Prism, Hexahedron };

/// Where the nodes of an order-P element sit in the reference element.
///  Equispaced: what Gmsh and VTK files assume for their Lagrange elements.
///  GLL: Gauss-Lobatto-Legendre points on tensor shapes; warp-and-blend (Warburton 2006) on
///       simplices; pyramids use the equispaced layout warped along edges and faces (documented
///       in node_set.cpp).
enum class NodeSet { Equispaced, GLL };

constexpr int kMaxOrder = 10;

namespace detail {
constexpr int kShapes = 7;  ///< the values of Shape, from 0
[[noreturn]] void throw_unknown_shape(const char* function);
/// The shapes' edge and face tables (element_type.cpp), by Shape value.
struct ElementTables {
  std::array<std::vector<std::array<int, 2>>, kShapes> edges;
  std::array<std::vector<std::vector<int>>, kShapes> faces;
};
ElementTables make_element_tables();
inline const ElementTables& element_tables() {
  static const ElementTables tables = make_element_tables();
  return tables;
}
}  // namespace detail

// Inline: the tables are read per element in every pass over a mesh; one function-local static
// (one guard, read on first use) where a call per lookup and a guard per shape cost ~2 % of a run.
inline int dimension(Shape shape) {
  constexpr int kDimension[detail::kShapes] = {1, 2, 2, 3, 3, 3, 3};
  const auto s = static_cast<unsigned>(shape);
  if (s >= detail::kShapes) detail::throw_unknown_shape("dimension");
  return kDimension[s];
}
inline int num_vertices(Shape shape) {
  constexpr int kVertices[detail::kShapes] = {2, 3, 4, 4, 5, 6, 8};
  const auto s = static_cast<unsigned>(shape);
  if (s >= detail::kShapes) detail::throw_unknown_shape("num_vertices");
  return kVertices[s];
}
/// Number of nodes of the order-P element (P >= 1).
int num_nodes(Shape shape, int order);
std::string to_string(Shape shape);

/// Reference coordinates of the vertices (Gmsh's reference element, see above); shape (num_vertices, 3).
Eigen::MatrixX3d reference_vertices(Shape shape);

/// Local edges as vertex pairs (Gmsh's order and direction).
inline const std::vector<std::array<int, 2>>& edges(Shape shape) {
  const auto s = static_cast<unsigned>(shape);
  if (s >= detail::kShapes) detail::throw_unknown_shape("edges");
  return detail::element_tables().edges[s];
}
/// Local faces of 3D shapes as vertex lists (3 or 4), ordered so that their normal by the right-hand
/// rule points out of the element (Gmsh's face order); none for segments, triangles, quadrilaterals.
inline const std::vector<std::vector<int>>& faces(Shape shape) {
  const auto s = static_cast<unsigned>(shape);
  if (s >= detail::kShapes) detail::throw_unknown_shape("faces");
  return detail::element_tables().faces[s];
}

/// Reference coordinates of the nodes of an order-P element in canonical order; row i is node i.
/// Shape (num_nodes, 3); unused coordinates are 0.
Eigen::MatrixX3d reference_nodes(Shape shape, int order, NodeSet set = NodeSet::Equispaced);

}  // namespace semimesh::ho
