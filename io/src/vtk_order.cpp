#include "semimesh/io/vtk_order.hpp"

#include <Eigen/Core>

#include <array>
#include <map>
#include <mutex>
#include <stdexcept>
#include <string>

namespace semimesh::io {
namespace {

using Point = std::array<int, 3>;  // VTK lattice coordinates times the order P

/// The lattice point i/n of the way from a to b (exact: the lattice has n steps along a->b).
Point lerp(const Point& a, const Point& b, int i, int n) {
  Point p{};
  for (int k = 0; k < 3; ++k) p[k] = a[k] + (b[k] - a[k]) * i / n;
  return p;
}

/// Corners of the order n-3 triangle inside the order-n triangle (a, b, c): each corner moved one
/// lattice step along both of its edges.
std::array<Point, 3> inner_triangle(const Point& a, const Point& b, const Point& c, int n) {
  const std::array<Point, 3> t{a, b, c};
  std::array<Point, 3> inner{};
  for (int v = 0; v < 3; ++v)
    for (int k = 0; k < 3; ++k)
      inner[v][k] = t[v][k] + ((t[(v + 1) % 3][k] - t[v][k]) + (t[(v + 2) % 3][k] - t[v][k])) / n;
  return inner;
}

/// Recursive simplex ordering shared by VTK's triangle and the faces/interior of its tetrahedron:
/// the corners, the points inside each edge (a->b), then the same pattern on the inner triangle.
/// corners: lattice points of the sub-triangle's vertices; n: its order (0 = single point).
void triangle_points(const std::array<Point, 3>& c, int n, std::vector<Point>& out) {
  if (n < 0) return;
  if (n == 0) {
    out.push_back(c[0]);
    return;
  }
  for (const auto& v : c) out.push_back(v);
  for (int e = 0; e < 3; ++e)
    for (int i = 1; i < n; ++i) out.push_back(lerp(c[e], c[(e + 1) % 3], i, n));
  if (n < 3) return;
  triangle_points(inner_triangle(c[0], c[1], c[2], n), n - 3, out);
}

void tetra_points(const std::array<Point, 4>& c, int n, std::vector<Point>& out) {
  if (n < 0) return;
  if (n == 0) {
    out.push_back(c[0]);
    return;
  }
  for (const auto& v : c) out.push_back(v);
  static constexpr int kEdges[6][2] = {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}};
  for (const auto& e : kEdges)
    for (int i = 1; i < n; ++i) out.push_back(lerp(c[e[0]], c[e[1]], i, n));
  if (n < 3) return;
  // Faces with their starting corner as VTK lists them.
  static constexpr int kFaces[4][3] = {{0, 1, 3}, {2, 3, 1}, {0, 3, 2}, {0, 2, 1}};
  for (const auto& f : kFaces) triangle_points(inner_triangle(c[f[0]], c[f[1]], c[f[2]], n), n - 3, out);
  if (n < 4) return;
  std::array<Point, 4> inner{};
  for (int v = 0; v < 4; ++v)
    for (int k = 0; k < 3; ++k) {
      int shift = 0;
      for (int w = 0; w < 4; ++w)
        if (w != v) shift += c[w][k] - c[v][k];
      inner[v][k] = c[v][k] + shift / n;
    }
  tetra_points(inner, n - 4, out);
}

std::vector<Point> quad_points(int p) {
  std::vector<Point> out = {{0, 0, 0}, {p, 0, 0}, {p, p, 0}, {0, p, 0}};
  for (int i = 1; i < p; ++i) out.push_back({i, 0, 0});
  for (int j = 1; j < p; ++j) out.push_back({p, j, 0});
  for (int i = 1; i < p; ++i) out.push_back({i, p, 0});
  for (int j = 1; j < p; ++j) out.push_back({0, j, 0});
  for (int j = 1; j < p; ++j)
    for (int i = 1; i < p; ++i) out.push_back({i, j, 0});
  return out;
}

std::vector<Point> hex_points(int p) {
  std::vector<Point> out;
  for (int k : {0, p})
    for (const Point& q : std::vector<Point>{{0, 0, 0}, {p, 0, 0}, {p, p, 0}, {0, p, 0}}) out.push_back({q[0], q[1], k});
  for (int k : {0, p}) {
    for (int i = 1; i < p; ++i) out.push_back({i, 0, k});
    for (int j = 1; j < p; ++j) out.push_back({p, j, k});
    for (int i = 1; i < p; ++i) out.push_back({i, p, k});
    for (int j = 1; j < p; ++j) out.push_back({0, j, k});
  }
  for (const auto& [i, j] : std::vector<std::pair<int, int>>{{0, 0}, {p, 0}, {p, p}, {0, p}})
    for (int k = 1; k < p; ++k) out.push_back({i, j, k});
  for (int i : {0, p})
    for (int k = 1; k < p; ++k)
      for (int j = 1; j < p; ++j) out.push_back({i, j, k});
  for (int j : {0, p})
    for (int k = 1; k < p; ++k)
      for (int i = 1; i < p; ++i) out.push_back({i, j, k});
  for (int k : {0, p})
    for (int j = 1; j < p; ++j)
      for (int i = 1; i < p; ++i) out.push_back({i, j, k});
  for (int k = 1; k < p; ++k)
    for (int j = 1; j < p; ++j)
      for (int i = 1; i < p; ++i) out.push_back({i, j, k});
  return out;
}

std::vector<Point> wedge_points(int p) {
  std::vector<Point> out;
  for (int k : {0, p})
    for (const Point& q : std::vector<Point>{{0, 0, 0}, {p, 0, 0}, {0, p, 0}}) out.push_back({q[0], q[1], k});
  for (int k : {0, p}) {
    for (int i = 1; i < p; ++i) out.push_back({i, 0, k});
    for (int i = 1; i < p; ++i) out.push_back({p - i, i, k});
    for (int i = 1; i < p; ++i) out.push_back({0, p - i, k});
  }
  for (const auto& [i, j] : std::vector<std::pair<int, int>>{{0, 0}, {p, 0}, {0, p}})
    for (int k = 1; k < p; ++k) out.push_back({i, j, k});
  auto triangle_interior = [&](int k) {
    for (int j = 1; j < p; ++j)
      for (int i = 1; i + j < p; ++i) out.push_back({i, j, k});
  };
  triangle_interior(0);
  triangle_interior(p);
  for (int k = 1; k < p; ++k)
    for (int i = 1; i < p; ++i) out.push_back({i, 0, k});
  for (int k = 1; k < p; ++k)
    for (int i = 1; i < p; ++i) out.push_back({p - i, i, k});
  for (int k = 1; k < p; ++k)
    for (int i = 1; i < p; ++i) out.push_back({0, p - i, k});
  for (int k = 1; k < p; ++k) triangle_interior(k);
  return out;
}

std::vector<int> build(ho::Shape shape, int p) {
  std::vector<Point> lattice;
  bool tensor_z = false, tensor_xy = false;  // VTK [0,1] coordinates that Gmsh maps to [-1,1]
  switch (shape) {
    case ho::Shape::Triangle: triangle_points({{{0, 0, 0}, {p, 0, 0}, {0, p, 0}}}, p, lattice); break;
    case ho::Shape::Tetrahedron: tetra_points({{{0, 0, 0}, {p, 0, 0}, {0, p, 0}, {0, 0, p}}}, p, lattice); break;
    case ho::Shape::Quadrilateral: lattice = quad_points(p), tensor_xy = true; break;
    case ho::Shape::Hexahedron: lattice = hex_points(p), tensor_xy = tensor_z = true; break;
    case ho::Shape::Prism: lattice = wedge_points(p), tensor_z = true; break;
    case ho::Shape::Pyramid: return {0, 1, 2, 3, 4};
    default: throw std::invalid_argument("VTU: no VTK cell for " + ho::to_string(shape));
  }
  const Eigen::MatrixX3d ref = ho::reference_nodes(shape, p, ho::NodeSet::Equispaced);
  if (static_cast<long>(lattice.size()) != ref.rows())
    throw std::logic_error("VTU: VTK lattice of " + ho::to_string(shape) + " has the wrong size");
  std::vector<int> perm;
  for (const Point& q : lattice) {
    Eigen::RowVector3d x(double(q[0]) / p, double(q[1]) / p, double(q[2]) / p);
    if (tensor_xy) x.head<2>() = 2.0 * x.head<2>().array() - 1.0;
    if (tensor_z) x[2] = 2.0 * x[2] - 1.0;
    int found = -1;
    for (int i = 0; i < ref.rows() && found < 0; ++i)
      if ((ref.row(i) - x).norm() < 1e-9) found = i;
    if (found < 0) throw std::logic_error("VTU: VTK point of " + ho::to_string(shape) + " matches no Gmsh node");
    perm.push_back(found);
  }
  return perm;
}

}  // namespace

int vtk_cell_type(ho::Shape shape) {
  switch (shape) {
    case ho::Shape::Triangle: return 69;
    case ho::Shape::Quadrilateral: return 70;
    case ho::Shape::Tetrahedron: return 71;
    case ho::Shape::Hexahedron: return 72;
    case ho::Shape::Prism: return 73;
    case ho::Shape::Pyramid: return 14;
    default: throw std::invalid_argument("VTU: no VTK cell for " + ho::to_string(shape));
  }
}

const std::vector<int>& vtk_from_canonical(ho::Shape shape, int order) {
  static std::mutex mutex;
  static std::map<std::pair<int, int>, std::vector<int>> cache;
  const std::lock_guard<std::mutex> lock(mutex);
  auto& entry = cache[{static_cast<int>(shape), order}];
  if (entry.empty()) entry = build(shape, order);
  return entry;
}

}  // namespace semimesh::io
