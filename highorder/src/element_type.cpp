// Element shapes: sizes and Gmsh's local edge and face tables.
//
// Tables are Gmsh's conventions (gmsh.info "Node ordering"; edge/face tables of Gmsh's MTetrahedron,
// MHexahedron, MPrism, MPyramid). The face vertex lists also fix where a face's interior nodes start
// and how they turn: the face's own canonical nodes are laid out from its first vertex, towards the
// second, then the third (checked against Gmsh 4.8 in tests/highorder).
#include "semimesh/ho/element_type.hpp"

#include <stdexcept>

namespace semimesh::ho {

int dimension(Shape shape) {
  switch (shape) {
    case Shape::Segment: return 1;
    case Shape::Triangle:
    case Shape::Quadrilateral: return 2;
    case Shape::Tetrahedron:
    case Shape::Pyramid:
    case Shape::Prism:
    case Shape::Hexahedron: return 3;
  }
  throw std::invalid_argument("dimension: unknown element shape");
}

int num_vertices(Shape shape) {
  switch (shape) {
    case Shape::Segment: return 2;
    case Shape::Triangle: return 3;
    case Shape::Quadrilateral: return 4;
    case Shape::Tetrahedron: return 4;
    case Shape::Pyramid: return 5;
    case Shape::Prism: return 6;
    case Shape::Hexahedron: return 8;
  }
  throw std::invalid_argument("num_vertices: unknown element shape");
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

const std::vector<std::array<int, 2>>& edges(Shape shape) {
  static const std::vector<std::array<int, 2>> segment{{0, 1}};
  static const std::vector<std::array<int, 2>> triangle{{0, 1}, {1, 2}, {2, 0}};
  static const std::vector<std::array<int, 2>> quadrilateral{{0, 1}, {1, 2}, {2, 3}, {3, 0}};
  static const std::vector<std::array<int, 2>> tetrahedron{{0, 1}, {1, 2}, {2, 0},
                                                           {3, 0}, {3, 2}, {3, 1}};
  static const std::vector<std::array<int, 2>> pyramid{{0, 1}, {0, 3}, {0, 4}, {1, 2},
                                                       {1, 4}, {2, 3}, {2, 4}, {3, 4}};
  static const std::vector<std::array<int, 2>> prism{{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 4},
                                                     {2, 5}, {3, 4}, {3, 5}, {4, 5}};
  static const std::vector<std::array<int, 2>> hexahedron{{0, 1}, {0, 3}, {0, 4}, {1, 2},
                                                          {1, 5}, {2, 3}, {2, 6}, {3, 7},
                                                          {4, 5}, {4, 7}, {5, 6}, {6, 7}};
  switch (shape) {
    case Shape::Segment: return segment;
    case Shape::Triangle: return triangle;
    case Shape::Quadrilateral: return quadrilateral;
    case Shape::Tetrahedron: return tetrahedron;
    case Shape::Pyramid: return pyramid;
    case Shape::Prism: return prism;
    case Shape::Hexahedron: return hexahedron;
  }
  throw std::invalid_argument("edges: unknown element shape");
}

const std::vector<std::vector<int>>& faces(Shape shape) {
  static const std::vector<std::vector<int>> none{};
  static const std::vector<std::vector<int>> tetrahedron{{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {3, 1, 2}};
  static const std::vector<std::vector<int>> pyramid{
      {0, 1, 4}, {3, 0, 4}, {1, 2, 4}, {2, 3, 4}, {0, 3, 2, 1}};
  static const std::vector<std::vector<int>> prism{
      {0, 2, 1}, {3, 4, 5}, {0, 1, 4, 3}, {0, 3, 5, 2}, {1, 2, 5, 4}};
  static const std::vector<std::vector<int>> hexahedron{{0, 3, 2, 1}, {0, 1, 5, 4}, {0, 4, 7, 3},
                                                        {1, 2, 6, 5}, {2, 3, 7, 6}, {4, 5, 6, 7}};
  switch (shape) {
    case Shape::Segment:
    case Shape::Triangle:
    case Shape::Quadrilateral: return none;
    case Shape::Tetrahedron: return tetrahedron;
    case Shape::Pyramid: return pyramid;
    case Shape::Prism: return prism;
    case Shape::Hexahedron: return hexahedron;
  }
  throw std::invalid_argument("faces: unknown element shape");
}

}  // namespace semimesh::ho
