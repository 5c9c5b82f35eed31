#include "semimesh/io/gmsh_types.hpp"

#include <array>
#include <stdexcept>
#include <string>

namespace semimesh::io {
namespace {

struct Row {
  ho::Shape shape;
  std::array<int, kMaxMshOrder> types;  // orders 1..kMaxMshOrder
};

// gmsh.model.mesh.getElementType(family, order) for family Triangle, Quadrangle, Tetrahedron,
// Pyramid, Prism, Hexahedron and order 1..9 (gmsh 4.8; prisms, pyramids and hexes stop at 9).
constexpr std::array<Row, 6> kTable = {{
    {ho::Shape::Triangle, {2, 9, 21, 23, 25, 42, 43, 44, 45}},
    {ho::Shape::Quadrilateral, {3, 10, 36, 37, 38, 47, 48, 49, 50}},
    {ho::Shape::Tetrahedron, {4, 11, 29, 30, 31, 71, 72, 73, 74}},
    {ho::Shape::Pyramid, {7, 14, 118, 119, 120, 121, 122, 123, 124}},
    {ho::Shape::Prism, {6, 13, 90, 91, 106, 107, 108, 109, 110}},
    {ho::Shape::Hexahedron, {5, 12, 92, 93, 94, 95, 96, 97, 98}},
}};

}  // namespace

int gmsh_element_type(ho::Shape shape, int order) {
  if (order < 1 || order > kMaxMshOrder)
    throw std::invalid_argument("MSH: order " + std::to_string(order) + " is not supported (orders 1.." +
                                std::to_string(kMaxMshOrder) + ")");
  for (const Row& row : kTable)
    if (row.shape == shape) return row.types[order - 1];
  throw std::invalid_argument("MSH: no Gmsh element type for " + ho::to_string(shape));
}

bool gmsh_shape_and_order(int type, ho::Shape& shape, int& order) {
  for (const Row& row : kTable)
    for (int k = 0; k < kMaxMshOrder; ++k)
      if (row.types[k] == type) {
        shape = row.shape;
        order = k + 1;
        return true;
      }
  return false;
}

}  // namespace semimesh::io
