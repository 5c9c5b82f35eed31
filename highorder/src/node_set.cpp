// Reference node sets in canonical (Gmsh MSH) order.
//
// Order. Built recursively, exactly as Gmsh numbers its Lagrange elements (verified node by node
// against Gmsh 4.8's getElementProperties for every shape and order it knows, and for prisms of order
// 3..6 against PyFR's published Gmsh node maps, see tests/highorder):
//   vertices; the P-1 interior nodes of each edge in edges() order, from its first vertex to its
//   second; the interior nodes of each face in faces() order, laid out as the interior nodes of an
//   order-P triangle/quadrilateral whose vertices 0, 1, 2(, 3) are the face's vertex list; the
//   interior nodes, which form a smaller element of the same shape (order P-3 triangle, P-2 quad,
//   P-4 tet, P-2 hex, P-3 pyramid starting one layer above the base), numbered recursively.
//   The prism interior is a product: for each node of the order P-3 interior triangle (recursive
//   order), the interior z-levels in the order of an order P-2 segment (both ends, then the inside).
//
// Positions. Equispaced: the lattice of spacing 1/P (simplices) or 2/P ([-1,1] directions).
// GLL: the same nodes, each moved by a map of its equispaced position:
//   segment, quadrilateral, hexahedron: each coordinate to the Gauss-Lobatto-Legendre points;
//   triangle: Warburton's warp & blend (2006), written in barycentric coordinates (displacements
//     along edge vectors), which makes it affine-invariant, so any triangle face gets the same nodes;
//     blend parameter alpha from Warburton's table for triangles;
//   tetrahedron: Warburton's 3D warp & blend (face warps blended into the volume), using the same
//     triangle alpha so that each tet face carries exactly the triangle's node set (conforming with
//     prism and pyramid triangle faces);
//   prism: triangle warp & blend in (x, y) times GLL in z;
//   pyramid: base face at GLL x GLL, triangular faces by the triangle warp & blend (both therefore
//     match neighbouring hexes/prisms/tets), interior nodes by layers: z-levels at GLL points of
//     [0, 1] and, in the layer of index k, an order P-k GLL grid scaled to the layer's square.
#include "semimesh/ho/element_type.hpp"

#include "polynomials.hpp"

#include <Eigen/Dense>

#include <cmath>
#include <stdexcept>
#include <string>

namespace semimesh::ho {

namespace {

using Point = Eigen::Vector3d;
using Points = std::vector<Point>;

Points vertex_points(Shape shape) {
  switch (shape) {
    case Shape::Segment: return {{-1, 0, 0}, {1, 0, 0}};
    case Shape::Triangle: return {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    case Shape::Quadrilateral: return {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
    case Shape::Tetrahedron: return {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    case Shape::Pyramid: return {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}, {0, 0, 1}};
    case Shape::Prism: return {{0, 0, -1}, {1, 0, -1}, {0, 1, -1}, {0, 0, 1}, {1, 0, 1}, {0, 1, 1}};
    case Shape::Hexahedron:
      return {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
              {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
  }
  throw std::invalid_argument("reference_vertices: unknown element shape");
}

Points canonical_equispaced(Shape shape, int order);

// Interior nodes of the order-P element, canonical order.
Points interior_nodes(Shape shape, int p) {
  Points out;
  switch (shape) {
    case Shape::Segment:
      for (int i = 1; i < p; ++i) out.emplace_back(-1.0 + 2.0 * i / p, 0, 0);
      break;
    case Shape::Triangle:
      if (p >= 3)
        for (const Point& n : canonical_equispaced(shape, p - 3))
          out.emplace_back((1.0 + (p - 3) * n.x()) / p, (1.0 + (p - 3) * n.y()) / p, 0);
      break;
    case Shape::Tetrahedron:
      if (p >= 4)
        for (const Point& n : canonical_equispaced(shape, p - 4))
          out.push_back((Point::Ones() + (p - 4) * n) / p);
      break;
    case Shape::Quadrilateral:
    case Shape::Hexahedron:
      if (p >= 2)
        for (const Point& n : canonical_equispaced(shape, p - 2)) out.push_back(n * (p - 2.0) / p);
      break;
    case Shape::Pyramid:
      if (p >= 3)
        for (const Point& n : canonical_equispaced(shape, p - 3))
          out.emplace_back(n.x() * (p - 3.0) / p, n.y() * (p - 3.0) / p, (1.0 + (p - 3) * n.z()) / p);
      break;
    case Shape::Prism:
      if (p >= 3) {
        const Points triangle = interior_nodes(Shape::Triangle, p);
        const Points levels = canonical_equispaced(Shape::Segment, p - 2);
        for (const Point& t : triangle)
          for (const Point& level : levels) out.emplace_back(t.x(), t.y(), level.x() * (p - 2.0) / p);
      }
      break;
  }
  return out;
}

// All nodes of the order-P element (P >= 0; order 0 is one node, used by the recursion).
Points canonical_equispaced(Shape shape, int p) {
  if (p == 0) return {Point::Zero()};
  const Points vertices = vertex_points(shape);
  Points out = vertices;
  for (const auto& edge : edges(shape)) {
    const Point& a = vertices[edge[0]];
    const Point& b = vertices[edge[1]];
    for (int i = 1; i < p; ++i) out.push_back(a + (b - a) * (double(i) / p));
  }
  for (const auto& face : faces(shape)) {
    if (face.size() == 3) {
      const Point& a = vertices[face[0]];
      for (const Point& n : interior_nodes(Shape::Triangle, p))
        out.push_back(a + (vertices[face[1]] - a) * n.x() + (vertices[face[2]] - a) * n.y());
    } else {
      for (const Point& n : interior_nodes(Shape::Quadrilateral, p)) {
        const double x = n.x(), y = n.y();
        out.push_back(0.25 * ((1 - x) * (1 - y) * vertices[face[0]] + (1 + x) * (1 - y) * vertices[face[1]] +
                              (1 + x) * (1 + y) * vertices[face[2]] + (1 - x) * (1 + y) * vertices[face[3]]));
      }
    }
  }
  if (shape != Shape::Segment) {
    const Points inside = interior_nodes(shape, p);
    out.insert(out.end(), inside.begin(), inside.end());
  }
  return out;
}

// ---- GLL / warp & blend positions ------------------------------------------------------------

// Lattice index of an equispaced coordinate in [-1, 1] (or [0, 1] with `unit`).
int lattice_index(double x, int p, bool unit) {
  return static_cast<int>(std::lround(unit ? x * p : (x + 1.0) * 0.5 * p));
}

double gll_coordinate(double x, int p) { return detail::gll_points(p)[lattice_index(x, p, false)]; }

// Warburton's optimised blend parameter for triangles, N = 1..15 (Warburton 2006, Table 1; also
// Hesthaven & Warburton, "Nodal DG methods", Nodes2D).
double triangle_alpha(int p) {
  static const double table[] = {0.0000, 0.0000, 1.4152, 0.1001, 0.2751, 0.9800, 1.0999, 1.2832,
                                 1.3648, 1.4773, 1.4959, 1.5743, 1.5770, 1.6223, 1.6258};
  return p <= 15 ? table[p - 1] : 5.0 / 3.0;
}

// 1D warp w(r) = sum_i (gll_i - equispaced_i) l_i(r): the interpolant on the equispaced points of
// the displacement that moves them to the GLL points.
double warp(int p, double r) {
  const std::vector<double>& gll = detail::gll_points(p);
  double sum = 0.0;
  for (int i = 0; i <= p; ++i) {
    const double ri = -1.0 + 2.0 * i / p;
    double lagrange = 1.0;
    for (int j = 0; j <= p; ++j)
      if (j != i) lagrange *= (r - (-1.0 + 2.0 * j / p)) / (ri - (-1.0 + 2.0 * j / p));
    sum += (gll[i] - ri) * lagrange;
  }
  return sum;
}

// Warp & blend displacement of a triangle (or a tet face), in barycentric coordinates of its three
// vertices. On an edge it is exactly the GLL displacement; lambdas need not sum to 1 (tet interior).
Eigen::Vector3d triangle_shift(int p, const Eigen::Vector3d& lambda) {
  const double alpha = triangle_alpha(p);
  Eigen::Vector3d shift = Eigen::Vector3d::Zero();
  for (int e = 0; e < 3; ++e) {
    const int a = e, b = (e + 1) % 3, c = (e + 2) % 3;
    const double r = lambda[b] - lambda[a];
    const double denominator = 1.0 - r * r;
    if (denominator < 1e-14) continue;  // at a vertex: no displacement
    const double blend = 4.0 * lambda[a] * lambda[b] / denominator * (1.0 + std::pow(alpha * lambda[c], 2));
    const double along = 0.5 * warp(p, r) * blend;  // along the edge vector e_b - e_a
    shift[b] += along;
    shift[a] -= along;
  }
  return shift;
}

bool is_zero(double x) { return std::abs(x) < 1e-12; }

Eigen::Vector4d tetrahedron_shift(int p, const Eigen::Vector4d& lambda) {
  static const int face_vertices[4][3] = {{1, 2, 3}, {0, 2, 3}, {0, 1, 3}, {0, 1, 2}};  // face f: opposite f
  const double alpha = triangle_alpha(p);
  // On a face: exactly the triangle's warp (the volume blend is 0/0 on the face's boundary).
  for (int f = 0; f < 4; ++f) {
    if (!is_zero(lambda[f])) continue;
    const int* v = face_vertices[f];
    const Eigen::Vector3d s = triangle_shift(p, {lambda[v[0]], lambda[v[1]], lambda[v[2]]});
    Eigen::Vector4d shift = Eigen::Vector4d::Zero();
    for (int i = 0; i < 3; ++i) shift[v[i]] = s[i];
    return shift;
  }
  Eigen::Vector4d shift = Eigen::Vector4d::Zero();
  for (int f = 0; f < 4; ++f) {
    const int* v = face_vertices[f];
    const double la = lambda[v[0]], lb = lambda[v[1]], lc = lambda[v[2]], ld = lambda[f];
    // Warburton's face blend: 1 on the face, 0 on the three other faces.
    const double blend = (1.0 + std::pow(alpha * ld, 2)) * la * lb * lc /
                         ((la + 0.5 * ld) * (lb + 0.5 * ld) * (lc + 0.5 * ld));
    const Eigen::Vector3d s = triangle_shift(p, {la, lb, lc});
    for (int i = 0; i < 3; ++i) shift[v[i]] += blend * s[i];
  }
  return shift;
}

Point warped_triangle_point(int p, const Point& a, const Point& b, const Point& c, const Eigen::Vector3d& lambda) {
  const Eigen::Vector3d moved = lambda + triangle_shift(p, lambda);
  return moved[0] * a + moved[1] * b + moved[2] * c;
}

// Barycentric coordinates of x in the plane of triangle (a, b, c), if x lies on that triangle.
bool on_triangle(const Point& x, const Point& a, const Point& b, const Point& c, Eigen::Vector3d& lambda) {
  Eigen::Matrix<double, 3, 2> edges_matrix;
  edges_matrix << b - a, c - a;
  const Eigen::Vector2d st = edges_matrix.colPivHouseholderQr().solve(x - a);
  if ((edges_matrix * st - (x - a)).norm() > 1e-12) return false;
  lambda = {1.0 - st[0] - st[1], st[0], st[1]};
  return lambda.minCoeff() > -1e-12;
}

Point pyramid_gll(int p, const Point& x, const Points& vertices) {
  if (is_zero(x.z())) return {gll_coordinate(x.x(), p), gll_coordinate(x.y(), p), 0.0};
  for (const auto& face : faces(Shape::Pyramid)) {
    if (face.size() != 3) continue;
    const Point &a = vertices[face[0]], &b = vertices[face[1]], &c = vertices[face[2]];
    Eigen::Vector3d lambda;
    if (on_triangle(x, a, b, c, lambda)) return warped_triangle_point(p, a, b, c, lambda);
  }
  // Interior: layer k at a GLL level of [0, 1], order P-k GLL grid across the layer.
  const int k = lattice_index(x.z(), p, true);
  const int layer_order = p - k;
  const double z = 0.5 * (1.0 + detail::gll_points(p)[k]);
  const double half_width = 1.0 - x.z();
  const auto across = [&](double coordinate) {
    const int i = lattice_index((coordinate / half_width + 1.0) * 0.5, layer_order, true);
    return (1.0 - z) * detail::gll_points(layer_order)[i];
  };
  return {across(x.x()), across(x.y()), z};
}

Point gll_position(Shape shape, int p, const Point& x, const Points& vertices) {
  switch (shape) {
    case Shape::Segment: return {gll_coordinate(x.x(), p), 0, 0};
    case Shape::Quadrilateral: return {gll_coordinate(x.x(), p), gll_coordinate(x.y(), p), 0};
    case Shape::Hexahedron: return {gll_coordinate(x.x(), p), gll_coordinate(x.y(), p), gll_coordinate(x.z(), p)};
    case Shape::Triangle:
      return warped_triangle_point(p, vertices[0], vertices[1], vertices[2], {1.0 - x.x() - x.y(), x.x(), x.y()});
    case Shape::Prism: {
      const Point base = warped_triangle_point(p, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1.0 - x.x() - x.y(), x.x(), x.y()});
      return {base.x(), base.y(), gll_coordinate(x.z(), p)};
    }
    case Shape::Tetrahedron: {
      const Eigen::Vector4d lambda{1.0 - x.x() - x.y() - x.z(), x.x(), x.y(), x.z()};
      const Eigen::Vector4d moved = lambda + tetrahedron_shift(p, lambda);
      return moved[1] * vertices[1] + moved[2] * vertices[2] + moved[3] * vertices[3];  // vertex 0 is the origin
    }
    case Shape::Pyramid: return pyramid_gll(p, x, vertices);
  }
  throw std::invalid_argument("reference_nodes: unknown element shape");
}

}  // namespace

Eigen::MatrixX3d reference_vertices(Shape shape) {
  const Points vertices = vertex_points(shape);
  Eigen::MatrixX3d out(vertices.size(), 3);
  for (std::size_t i = 0; i < vertices.size(); ++i) out.row(i) = vertices[i].transpose();
  return out;
}

Eigen::MatrixX3d reference_nodes(Shape shape, int order, NodeSet set) {
  if (order < 1 || order > kMaxOrder) {
    throw std::invalid_argument("reference_nodes: order of " + to_string(shape) + " must be in [1, " +
                                std::to_string(kMaxOrder) + "], got " + std::to_string(order));
  }
  const Points equispaced = canonical_equispaced(shape, order);
  const Points vertices = vertex_points(shape);
  Eigen::MatrixX3d out(equispaced.size(), 3);
  for (std::size_t i = 0; i < equispaced.size(); ++i) {
    const Point x = set == NodeSet::GLL ? gll_position(shape, order, equispaced[i], vertices) : equispaced[i];
    out.row(i) = x.transpose();
  }
  return out;
}

}  // namespace semimesh::ho
