// Element shapes: sizes and Gmsh's local edge and face tables.
//
// Tables are Gmsh's conventions (gmsh.info "Node ordering"; edge/face tables of Gmsh's MTetrahedron,
// MHexahedron, MPrism, MPyramid). The face vertex lists also fix where a face's interior nodes start
// and how they turn: the face's own canonical nodes are laid out from its first vertex, towards the
// second, then the third (checked against Gmsh 4.8 in tests/highorder).
#include "semimesh/ho/element_type.hpp"

#include <stdexcept>

namespace semimesh::ho {

void detail::throw_unknown_shape(const char* function) {
  throw std::invalid_argument(std::string(function) + ": unknown element shape");
}

int num_nodes(Shape shape, int order) {
  if (order < 1) {
    throw std::invalid_argument("num_nodes: polynomial order must be >= 1, got " + std::to_string(order));
  }
  const int p = order;
  switch (shape) {
    case Shape::Segment: return p + 1;
    case Shape::Triangle: return (p + 1) * (p + 2) / 2;
    case Shape::Quadrilateral: return (p + 1) * (p + 1);
    case Shape::Tetrahedron: return (p + 1) * (p + 2) * (p + 3) / 6;
    case Shape::Pyramid: return (p + 1) * (p + 2) * (2 * p + 3) / 6;
    case Shape::Prism: return (p + 1) * (p + 1) * (p + 2) / 2;
    case Shape::Hexahedron: return (p + 1) * (p + 1) * (p + 1);
  }
  throw std::invalid_argument("num_nodes: unknown element shape");
}

std::string to_string(Shape shape) {
  switch (shape) {
    case Shape::Segment: return "segment";
    case Shape::Triangle: return "triangle";
    case Shape::Quadrilateral: return "quadrilateral";
    case Shape::Tetrahedron: return "tetrahedron";
    case Shape::Pyramid: return "pyramid";
    case Shape::Prism: return "prism";
    case Shape::Hexahedron: return "hexahedron";
  }
  return "unknown";
}

detail::ElementTables detail::make_element_tables() {
  ElementTables t;
  const auto at = [](Shape shape) { return static_cast<std::size_t>(shape); };
  t.edges[at(Shape::Segment)] = {{0, 1}};
  t.edges[at(Shape::Triangle)] = {{0, 1}, {1, 2}, {2, 0}};
  t.edges[at(Shape::Quadrilateral)] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}};
  t.edges[at(Shape::Tetrahedron)] = {{0, 1}, {1, 2}, {2, 0}, {3, 0}, {3, 2}, {3, 1}};
  t.edges[at(Shape::Pyramid)] = {{0, 1}, {0, 3}, {0, 4}, {1, 2}, {1, 4}, {2, 3}, {2, 4}, {3, 4}};
  t.edges[at(Shape::Prism)] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 4}, {2, 5}, {3, 4}, {3, 5}, {4, 5}};
  t.edges[at(Shape::Hexahedron)] = {{0, 1}, {0, 3}, {0, 4}, {1, 2}, {1, 5}, {2, 3},
                                    {2, 6}, {3, 7}, {4, 5}, {4, 7}, {5, 6}, {6, 7}};
  t.faces[at(Shape::Tetrahedron)] = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {3, 1, 2}};
  t.faces[at(Shape::Pyramid)] = {{0, 1, 4}, {3, 0, 4}, {1, 2, 4}, {2, 3, 4}, {0, 3, 2, 1}};
  t.faces[at(Shape::Prism)] = {{0, 2, 1}, {3, 4, 5}, {0, 1, 4, 3}, {0, 3, 5, 2}, {1, 2, 5, 4}};
  t.faces[at(Shape::Hexahedron)] = {{0, 3, 2, 1}, {0, 1, 5, 4}, {0, 4, 7, 3},
                                    {1, 2, 6, 5}, {2, 3, 7, 6}, {4, 5, 6, 7}};
  return t;
}

}  // namespace semimesh::ho
