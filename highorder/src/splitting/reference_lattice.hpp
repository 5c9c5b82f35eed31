// Integer lattice coordinates of the equispaced nodes of an order-P element.
//
// The equispaced node set of an order-P element sits on the lattice of step 1/P of its reference
// element, so each canonical node has exact integer coordinates in [0, P]: x P on unit-interval
// coordinates (triangle, tetrahedron, the prism's triangle), (x + 1) P / 2 on [-1, 1] coordinates
// (segment, quadrilateral, hexahedron, the prism's z). Every node set keeps the role of the i-th node
// (a GLL set is the equispaced lattice warped in place), so these integers name nodes of any set.
// Unused coordinates are 0.
#pragma once

#include "semimesh/ho/element_type.hpp"

#include <array>
#include <map>
#include <vector>

namespace semimesh::ho::detail {

using LatticePoint = std::array<int, 3>;

/// Lattice coordinates of the canonical nodes; shape (num_nodes(shape, order)). Throws
/// std::invalid_argument for the pyramid (its nodes are not on one lattice of this kind).
std::vector<LatticePoint> lattice_points(Shape shape, int order);

/// Canonical index of every lattice point of lattice_points(shape, order).
std::map<LatticePoint, int> lattice_index(Shape shape, int order);

/// Canonical node list of a face of an element, the face given by element-local vertex indices in
/// the order wanted (3: triangle, 4: quadrilateral, Gmsh's vertex order of that face element).
/// element_nodes: the element's canonical node ids; returns the face's canonical node ids.
template <typename Id>
std::vector<Id> face_nodes_of_element(Shape shape, int order, const std::vector<Id>& element_nodes,
                                      const std::vector<int>& face_vertices);

/// The same, returning canonical indices into the element's node list.
std::vector<int> face_node_indices(Shape shape, int order, const std::vector<int>& face_vertices);

template <typename Id>
std::vector<Id> face_nodes_of_element(Shape shape, int order, const std::vector<Id>& element_nodes,
                                      const std::vector<int>& face_vertices) {
  std::vector<Id> out;
  for (int i : face_node_indices(shape, order, face_vertices)) out.push_back(element_nodes[i]);
  return out;
}

}  // namespace semimesh::ho::detail
