#include "reference_lattice.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace semimesh::ho::detail {
namespace {

// Which reference coordinates run over [-1, 1] (the others run over [0, 1]); see element_type.hpp.
std::array<bool, 3> symmetric_coordinates(Shape shape) {
  switch (shape) {
    case Shape::Segment: return {true, false, false};
    case Shape::Quadrilateral: return {true, true, false};
    case Shape::Hexahedron: return {true, true, true};
    case Shape::Prism: return {false, false, true};
    case Shape::Triangle:
    case Shape::Tetrahedron: return {false, false, false};
    case Shape::Pyramid: break;
  }
  throw std::invalid_argument("reference lattice: no integer lattice for shape " + to_string(shape));
}

}  // namespace

std::vector<LatticePoint> lattice_points(Shape shape, int order) {
  const std::array<bool, 3> symmetric = symmetric_coordinates(shape);
  const Eigen::MatrixX3d r = reference_nodes(shape, order, NodeSet::Equispaced);
  const int dim = dimension(shape);
  std::vector<LatticePoint> points(r.rows(), LatticePoint{0, 0, 0});
  for (Eigen::Index i = 0; i < r.rows(); ++i)
    for (int c = 0; c < dim; ++c) {
      const double unit = symmetric[c] ? 0.5 * (r(i, c) + 1.0) : r(i, c);
      points[i][c] = static_cast<int>(std::lround(unit * order));
    }
  return points;
}

std::map<LatticePoint, int> lattice_index(Shape shape, int order) {
  std::map<LatticePoint, int> index;
  const std::vector<LatticePoint> points = lattice_points(shape, order);
  for (std::size_t i = 0; i < points.size(); ++i) index.emplace(points[i], static_cast<int>(i));
  return index;
}

std::vector<int> face_node_indices(Shape shape, int order, const std::vector<int>& face_vertices) {
  const int n = static_cast<int>(face_vertices.size());
  if (n != 3 && n != 4) throw std::invalid_argument("face_node_indices: a face has 3 or 4 vertices");
  const Shape face_shape = n == 3 ? Shape::Triangle : Shape::Quadrilateral;
  const std::vector<LatticePoint> element = lattice_points(shape, order);
  const std::map<LatticePoint, int> index = lattice_index(shape, order);
  const std::vector<LatticePoint> face = lattice_points(face_shape, order);
  std::vector<int> out;
  out.reserve(face.size());
  for (const LatticePoint& f : face) {
    // Face lattice (a, b) in [0, P]; the element point is the matching lattice combination of the
    // face's vertices (affine on a triangle, bilinear on a quad; both exact on the integers because
    // quad faces of prisms and hexes are lattice rectangles).
    LatticePoint p{0, 0, 0};
    for (int c = 0; c < 3; ++c) {
      const auto v = [&](int k) { return element[face_vertices[k]][c]; };
      long num;
      if (n == 3) {
        num = static_cast<long>(v(0)) * (order - f[0] - f[1]) + static_cast<long>(v(1)) * f[0] +
              static_cast<long>(v(2)) * f[1];
        p[c] = static_cast<int>(num / order);
      } else {
        // Gmsh quad vertices (-1,-1), (1,-1), (1,1), (-1,1).
        const long a = f[0], b = f[1], P = order;
        num = v(0) * (P - a) * (P - b) + v(1) * a * (P - b) + v(2) * a * b + v(3) * (P - a) * b;
        p[c] = static_cast<int>(num / (P * P));
      }
    }
    const auto it = index.find(p);
    if (it == index.end())
      throw std::logic_error("face_node_indices: the face vertices do not form a face of the " + to_string(shape));
    out.push_back(it->second);
  }
  return out;
}

}  // namespace semimesh::ho::detail
