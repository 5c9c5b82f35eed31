#include "semimesh/ho/basis.hpp"
#include "semimesh/ho/validity.hpp"

#include "jacobian_polynomial.hpp"

#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>
#include <utility>

namespace semimesh::ho {
namespace {

// (num_nodes(hex, order), 8): the trilinear map of the eight vertices at the order's reference nodes.
// Kept per thread: the certification's threads ask for it once per element, a lock would serialise them.
const Eigen::MatrixXd& vertex_interpolation(int order, NodeSet set) {
  thread_local std::map<std::pair<int, NodeSet>, Eigen::MatrixXd> cache;
  auto [it, made] = cache.try_emplace({order, set});
  if (made) it->second = interpolation_matrix(LagrangeBasis(Shape::Hexahedron, 1), LagrangeBasis(Shape::Hexahedron, order, set));
  return it->second;
}

// An upper bound of the largest sum over the Lagrange basis of |d phi / d xi_k| (orders <= 10),
// as affine_jacobian takes it: the nodes' deviation d moves J by at most this times d.
constexpr double kGradientSum = 1e4;

}  // namespace

namespace detail {

BernsteinPolynomial elevated_on_segments(const BernsteinPolynomial& p, int degree) {
  const BernsteinLayout& from = p.layout();
  if (from.num_vars != 3 || from.factors.size() != 3)
    throw std::invalid_argument("elevated_on_segments: a product of three segments is needed");
  BernsteinPolynomial out(std::vector<SimplexFactor>(3, SimplexFactor{1, degree}));
  // One direction at a time over a dense box (a separable elevation: ~7k products at order 4, not
  // the 140k of all 27 x 1728 pairs), box index i + n0 (j + n1 k); the 1D matrices kept per thread.
  thread_local std::map<std::pair<int, int>, Eigen::MatrixXd> elevations;
  thread_local std::vector<double> box, next;
  std::array<int, 3> n{};
  for (int k = 0; k < 3; ++k) n[k] = from.factors[k].degree + 1;
  box.assign(static_cast<std::size_t>(n[0]) * n[1] * n[2], 0.0);
  for (int id = 0; id < from.size(); ++id)
    box[from.index[id][0] + n[0] * (from.index[id][1] + n[1] * from.index[id][2])] = p.coefficients()[id];
  for (int var = 0; var < 3; ++var) {
    auto [it, made] = elevations.try_emplace({n[var] - 1, degree});
    if (made) it->second = bernstein_elevation_1d(n[var] - 1, degree);
    const Eigen::MatrixXd& e = it->second;
    std::array<int, 3> m = n;
    m[var] = degree + 1;
    // Strides of the box along (var, the others) before and after.
    const std::array<long, 3> stride_in{1, n[0], static_cast<long>(n[0]) * n[1]};
    const std::array<long, 3> stride_out{1, m[0], static_cast<long>(m[0]) * m[1]};
    next.assign(static_cast<std::size_t>(m[0]) * m[1] * m[2], 0.0);
    for (int k = 0; k < m[2]; ++k)
      for (int j = 0; j < m[1]; ++j)
        for (int i = 0; i < m[0]; ++i) {
          const std::array<int, 3> at{i, j, k};
          long base = 0;
          for (int d = 0; d < 3; ++d)
            if (d != var) base += at[d] * stride_in[d];
          double sum = 0.0;
          for (int r = 0; r < n[var]; ++r) sum += e(at[var], r) * box[base + r * stride_in[var]];
          next[i * stride_out[0] + j * stride_out[1] + k * stride_out[2]] = sum;
        }
    std::swap(box, next);
    n = m;
  }
  const BernsteinLayout& to = out.layout();
  for (int id = 0; id < to.size(); ++id)
    out.coefficients()[id] = box[to.index[id][0] + n[0] * (to.index[id][1] + n[1] * to.index[id][2])];
  return out;
}

}  // namespace detail

bool trilinear_jacobian(int order, NodeSet set, const Eigen::MatrixX3d& element_nodes, JacobianBounds& bounds,
                        int max_depth, double floor_ratio) {
  if (order < 2 || order > kMaxOrder || element_nodes.rows() != num_nodes(Shape::Hexahedron, order)) return false;
  const Eigen::MatrixX3d vertices = element_nodes.topRows(8);
  double longest = 0.0;
  for (const auto& e : edges(Shape::Hexahedron))
    longest = std::max(longest, (vertices.row(e[1]) - vertices.row(e[0])).norm());
  // The deviation as computed, plus what rounding at the coordinates' magnitude can hide from it.
  const double rounding = 8.0 * std::numeric_limits<double>::epsilon() * element_nodes.rowwise().norm().maxCoeff();
  const double deviation =
      (vertex_interpolation(order, set) * vertices - element_nodes).rowwise().norm().maxCoeff() + rounding;
  if (!(longest > 0.0) || !(deviation <= kAffineTolerance * longest)) return false;
  const BernsteinPolynomial trilinear = detail::jacobian_determinant(Shape::Hexahedron, 1, set, vertices);
  JacobianBounds b =
      detail::certify_determinant(detail::elevated_on_segments(trilinear, 3 * order - 1), max_depth, floor_ratio);
  const double g = std::sqrt(3.0) * longest, e = kGradientSum * deviation;
  const double delta = 3.0 * g * g * e + 3.0 * g * e * e + e * e * e;
  if (!b.valid || !b.proven || !(b.min_lower > delta)) return false;
  bounds = b;
  return true;
}

}  // namespace semimesh::ho
