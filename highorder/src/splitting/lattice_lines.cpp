#include "lattice_lines.hpp"

#include "reference_lattice.hpp"

#include <stdexcept>
#include <string>

namespace semimesh::ho::detail {
namespace {

// The 1D Lagrange polynomials through t[0..n) at x: l[m] = prod_{k != m} (x - t[k]) / (t[m] - t[k]).
void lagrange_1d(const double* t, int n, double x, double* l) {
  for (int m = 0; m < n; ++m) {
    double value = 1.0;
    for (int k = 0; k < n; ++k)
      if (k != m) value *= (x - t[k]) / (t[m] - t[k]);
    l[m] = value;
  }
}

}  // namespace

LatticeLines lattice_lines(Shape shape, int order, NodeSet set, const std::array<int, 2>& directions) {
  const int count = directions[1] >= 0 ? 2 : 1;
  for (int s = 0; s < count; ++s)
    if (directions[s] < 0 || directions[s] > 2)
      throw std::invalid_argument("lattice_lines: direction " + std::to_string(directions[s]) + " is not 0, 1 or 2");
  const bool hexahedron = shape == Shape::Hexahedron && (count == 1 || directions[0] != directions[1]);
  const bool prism = shape == Shape::Prism && count == 1 && directions[0] == 2;
  if (!hexahedron && !prism)
    throw std::invalid_argument("lattice_lines: a " + to_string(shape) +
                                " has no tensor lines in these directions (hexahedra: one or two, prisms: zeta)");
  LatticeLines lines;
  lines.order = order;
  lines.count = count;
  lines.directions = directions;
  const int n1 = order + 1;
  lines.stride = count == 2 ? n1 * n1 : n1;
  const std::vector<LatticePoint> lattice = lattice_points(shape, order);
  const std::map<LatticePoint, int> index = lattice_index(shape, order);
  const Eigen::MatrixX3d reference = reference_nodes(shape, order, set);
  const int num = static_cast<int>(lattice.size());
  lines.nodes.resize(static_cast<std::size_t>(num) * lines.stride);
  lines.coordinates.resize(static_cast<std::size_t>(num) * 2 * n1, 0.0);
  for (int node = 0; node < num; ++node) {
    for (int mb = 0; mb < (count == 2 ? n1 : 1); ++mb)
      for (int ma = 0; ma < n1; ++ma) {
        LatticePoint p = lattice[node];
        p[directions[0]] = ma;
        if (count == 2) p[directions[1]] = mb;
        lines.nodes[static_cast<std::size_t>(node) * lines.stride + mb * n1 + ma] = index.at(p);
      }
    for (int s = 0; s < count; ++s)
      for (int m = 0; m < n1; ++m) {
        LatticePoint p = lattice[node];
        p[directions[s]] = m;
        lines.coordinates[(static_cast<std::size_t>(node) * 2 + s) * n1 + m] = reference(index.at(p), directions[s]);
      }
  }
  return lines;
}

Eigen::Vector3d map_along_line(const LatticeLines& lines, const Eigen::MatrixX3d& element_nodes, int node,
                               const std::array<double, 2>& along) {
  const int n1 = lines.order + 1;
  std::array<std::array<double, kMaxOrder + 1>, 2> l{};
  for (int s = 0; s < lines.count; ++s)
    lagrange_1d(&lines.coordinates[(static_cast<std::size_t>(node) * 2 + s) * n1], n1, along[s], l[s].data());
  if (lines.count == 1) l[1][0] = 1.0;
  const int* ids = &lines.nodes[static_cast<std::size_t>(node) * lines.stride];
  Eigen::Vector3d x = Eigen::Vector3d::Zero();
  for (int mb = 0; mb < (lines.count == 2 ? n1 : 1); ++mb)
    for (int ma = 0; ma < n1; ++ma) x += (l[0][ma] * l[1][mb]) * element_nodes.row(ids[mb * n1 + ma]).transpose();
  return x;
}

Eigen::MatrixX3d map_along_lines(const LatticeLines& lines, const Eigen::MatrixX3d& element_nodes,
                                 const Eigen::MatrixX3d& points) {
  const auto num = static_cast<int>(element_nodes.rows());
  Eigen::MatrixX3d x(points.rows(), 3);
  for (Eigen::Index r = 0; r < points.rows(); ++r) {
    const int node = static_cast<int>(r % num);
    const std::array<double, 2> along{points(r, lines.directions[0]),
                                      lines.count == 2 ? points(r, lines.directions[1]) : 0.0};
    x.row(r) = map_along_line(lines, element_nodes, node, along).transpose();
  }
  return x;
}

std::array<double, 8> linear_weights(Shape shape, const Eigen::RowVector3d& r) {
  std::array<double, 8> w{};
  if (shape == Shape::Hexahedron) {
    // Gmsh's hexahedron: vertices (-1,-1,-1), (1,-1,-1), (1,1,-1), (-1,1,-1), then the same at z = 1.
    static constexpr double sx[4] = {-1, 1, 1, -1}, sy[4] = {-1, -1, 1, 1};
    for (int level = 0; level < 2; ++level)
      for (int v = 0; v < 4; ++v)
        w[4 * level + v] = 0.125 * (1.0 + sx[v] * r[0]) * (1.0 + sy[v] * r[1]) * (1.0 + (level ? r[2] : -r[2]));
  } else if (shape == Shape::Prism) {
    // Gmsh's prism: triangle (0,0), (1,0), (0,1) at z = -1, then at z = 1.
    const double lambda[3] = {1.0 - r[0] - r[1], r[0], r[1]};
    for (int v = 0; v < 3; ++v) {
      w[v] = lambda[v] * 0.5 * (1.0 - r[2]);
      w[3 + v] = lambda[v] * 0.5 * (1.0 + r[2]);
    }
  } else {
    throw std::invalid_argument("linear_weights: a " + to_string(shape) + " is not a hexahedron or prism");
  }
  return w;
}

}  // namespace semimesh::ho::detail
