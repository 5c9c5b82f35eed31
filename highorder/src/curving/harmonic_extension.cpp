#include "harmonic_extension.hpp"
#include "per_element_type.hpp"

#include "semimesh/ho/curving/extend_inward.hpp"

#include "semimesh/ho/quadrature.hpp"
#include "semimesh/ho/basis.hpp"
#include "semimesh/mesh/node_layout.hpp"

#include <Eigen/Cholesky>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <stdexcept>
#include <string>

namespace semimesh::ho::detail {
namespace {

HarmonicExtension build_extension(Shape shape, int order, NodeSet set) {
  HarmonicExtension h;
  const mesh::NodeLayout& layout = mesh::node_layout(shape, order);
  const auto inside = dimension(shape) == 3 ? mesh::NodeSlot::Interior : mesh::NodeSlot::Face;
  for (std::size_t i = 0; i < layout.slots.size(); ++i)
    (layout.slots[i].kind == inside ? h.interior : h.boundary).push_back(static_cast<int>(i));
  if (h.interior.empty()) return h;

  // Stiffness K = sum_q w_q sum_c dphi/dx_c dphi/dx_c; gradients of degree <= order per direction
  // (plus the collapse factors), so order + 3 points per direction integrate it exactly.
  const LagrangeBasis basis(shape, order, set);
  const Quadrature q = reference_quadrature(shape, order + 3);
  const auto grads = basis.gradients(q.points);
  const int n = basis.size();
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(n, n);
  for (int c = 0; c < dimension(shape); ++c) K += grads[c].transpose() * q.weights.asDiagonal() * grads[c];

  const int ni = static_cast<int>(h.interior.size()), nb = static_cast<int>(h.boundary.size());
  Eigen::MatrixXd Kii(ni, ni), Kib(ni, nb);
  for (int i = 0; i < ni; ++i) {
    for (int j = 0; j < ni; ++j) Kii(i, j) = K(h.interior[i], h.interior[j]);
    for (int j = 0; j < nb; ++j) Kib(i, j) = K(h.interior[i], h.boundary[j]);
  }
  h.extension = -Kii.ldlt().solve(Kib);
  return h;
}

// Canonical indices of an element's reference nodes by their coordinates (the node sets place a
// prism's levels on the triangle's nodes and a quadrilateral's rows on the segment's).
class NodeFinder {
 public:
  explicit NodeFinder(const Eigen::MatrixX3d& nodes) {
    for (int i = 0; i < nodes.rows(); ++i) index_[key(nodes(i, 0), nodes(i, 1), nodes(i, 2))] = i;
  }
  int at(double x, double y, double z) const {
    const auto it = index_.find(key(x, y, z));
    if (it == index_.end())
      throw std::logic_error("inner_extension: no reference node at (" + std::to_string(x) + ", " + std::to_string(y) +
                             ", " + std::to_string(z) + ")");
    return it->second;
  }

 private:
  static std::array<long long, 3> key(double x, double y, double z) {
    return {std::llround(x * 1e9), std::llround(y * 1e9), std::llround(z * 1e9)};
  }
  std::map<std::array<long long, 3>, int> index_;
};

// The transfinite extension of a quadrilateral or prism (inner_extension), its rows summed from
// weights on boundary nodes.
HarmonicExtension build_transfinite(Shape shape, int order, NodeSet set) {
  const HarmonicExtension& harmonic = harmonic_extension(shape, order, set);
  HarmonicExtension h{harmonic.interior, harmonic.boundary, Eigen::MatrixXd::Zero(harmonic.interior.size(), harmonic.boundary.size())};
  if (h.interior.empty()) return h;
  std::map<int, int> column;  // canonical index of a boundary node -> its column
  for (std::size_t j = 0; j < h.boundary.size(); ++j) column[h.boundary[j]] = static_cast<int>(j);
  const Eigen::MatrixX3d X = reference_nodes(shape, order, set);
  const NodeFinder find(X);
  // A prism's triangles lie at zeta = -1 and 1; each level's nodes at the triangle's.
  const HarmonicExtension& triangle = harmonic_extension(Shape::Triangle, order, set);
  const Eigen::MatrixX3d T = reference_nodes(Shape::Triangle, order, set);
  const NodeFinder on_triangle(T);
  for (std::size_t r = 0; r < h.interior.size(); ++r) {
    const auto add = [&](int node, double weight) {
      const auto it = column.find(node);
      if (it == column.end()) throw std::logic_error("inner_extension: node " + std::to_string(node) + " is not on the boundary");
      h.extension(r, it->second) += weight;
    };
    const int i = h.interior[r];
    if (shape == Shape::Quadrilateral) {
      const double x = X(i, 0), y = X(i, 1), a = 0.5 * (x + 1.0), b = 0.5 * (y + 1.0);
      add(find.at(x, -1, 0), 1.0 - b);
      add(find.at(x, 1, 0), b);
      add(find.at(-1, y, 0), 1.0 - a);
      add(find.at(1, y, 0), a);
      add(find.at(-1, -1, 0), -(1.0 - a) * (1.0 - b));
      add(find.at(1, -1, 0), -a * (1.0 - b));
      add(find.at(1, 1, 0), -a * b);
      add(find.at(-1, 1, 0), -(1.0 - a) * b);
      continue;
    }
    const double u = X(i, 0), v = X(i, 1), z = X(i, 2), s = 0.5 * (z + 1.0);
    const int m = static_cast<int>(std::find(triangle.interior.begin(), triangle.interior.end(), on_triangle.at(u, v, 0)) -
                                   triangle.interior.begin());
    for (std::size_t c = 0; c < triangle.boundary.size(); ++c) {
      const double e = triangle.extension(m, c), tu = T(triangle.boundary[c], 0), tv = T(triangle.boundary[c], 1);
      add(find.at(tu, tv, z), e);
      add(find.at(tu, tv, -1), -(1.0 - s) * e);
      add(find.at(tu, tv, 1), -s * e);
    }
    add(find.at(u, v, -1), 1.0 - s);
    add(find.at(u, v, 1), s);
  }
  return h;
}

}  // namespace

const HarmonicExtension& inner_extension(Shape shape, int order, NodeSet set) {
  if (shape != Shape::Quadrilateral && shape != Shape::Prism) return harmonic_extension(shape, order, set);
  static PerElementType<HarmonicExtension> table;
  return table.get(shape, order, set, build_transfinite);
}

const HarmonicExtension& harmonic_extension(Shape shape, int order, NodeSet set) {
  static PerElementType<HarmonicExtension> table;
  return table.get(shape, order, set, build_extension);
}

void extend_harmonically(const HarmonicExtension& h, Eigen::MatrixXd& values) {
  if (h.interior.empty()) return;
  // Buffers per thread: the curving extends every face and element, and two allocations each were
  // a sizable share of an off-CAD face's time. (noalias: the same product kernel, into the buffer.)
  thread_local Eigen::MatrixXd boundary, inner;
  boundary.resize(static_cast<Eigen::Index>(h.boundary.size()), values.cols());
  for (std::size_t j = 0; j < h.boundary.size(); ++j) boundary.row(j) = values.row(h.boundary[j]);
  inner.resize(h.extension.rows(), values.cols());
  inner.noalias() = h.extension * boundary;
  for (std::size_t i = 0; i < h.interior.size(); ++i) values.row(h.interior[i]) = inner.row(i);
}

}  // namespace semimesh::ho::detail

namespace semimesh::ho {

void extend_inward(Shape shape, int order, NodeSet set, Eigen::MatrixXd& x) {
  detail::extend_harmonically(detail::inner_extension(shape, order, set), x);
}

}  // namespace semimesh::ho
