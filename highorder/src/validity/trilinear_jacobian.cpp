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
  // the 140k of all 27 x 1728 pairs), box index i + n0 (j + n1 k). Each output entry is a weighted
  // sum along one line of the box, read from its start with the direction's fixed stride (the checks
  // elevate every straight-sided hexahedron). The 1D matrices, row-major, are kept per thread (a
  // few: found by a scan).
  struct Elevation {
    int from = -1, to = -1;
    std::vector<double> rows;  // [to + 1][from + 1]
  };
  thread_local std::vector<Elevation> elevations;
  const auto elevation = [&](int from_degree) -> const std::vector<double>& {
    for (const Elevation& e : elevations)
      if (e.from == from_degree && e.to == degree) return e.rows;
    const Eigen::MatrixXd m = bernstein_elevation_1d(from_degree, degree);
    Elevation e{from_degree, degree, std::vector<double>(static_cast<std::size_t>(m.size()))};
    for (Eigen::Index r = 0; r < m.rows(); ++r)
      for (Eigen::Index c = 0; c < m.cols(); ++c) e.rows[static_cast<std::size_t>(r * m.cols() + c)] = m(r, c);
    elevations.push_back(std::move(e));
    return elevations.back().rows;
  };
  thread_local std::vector<double> box, next;
  std::array<int, 3> n{};
  for (int k = 0; k < 3; ++k) n[k] = from.factors[k].degree + 1;
  box.assign(static_cast<std::size_t>(n[0]) * n[1] * n[2], 0.0);
  for (int id = 0; id < from.size(); ++id)
    box[from.index[id][0] + n[0] * (from.index[id][1] + n[1] * from.index[id][2])] = p.coefficients()[id];
  const int m_var = degree + 1;
  for (int var = 0; var < 3; ++var) {
    const std::vector<double>& e = elevation(n[var] - 1);
    const int len = n[var];
    std::array<int, 3> m = n;
    m[var] = m_var;
    const long stride = var == 0 ? 1 : var == 1 ? n[0] : static_cast<long>(n[0]) * n[1];
    next.resize(static_cast<std::size_t>(m[0]) * m[1] * m[2]);
    double* o = next.data();
    // Output entries in memory order (i fastest); each the sum over its input line, in line order.
    for (int k = 0; k < m[2]; ++k)
      for (int j = 0; j < m[1]; ++j)
        for (int i = 0; i < m[0]; ++i) {
          const int row = var == 0 ? i : var == 1 ? j : k;
          const double* line = box.data() + (var == 0 ? 0 : i) + (var == 1 ? 0 : static_cast<long>(j) * n[0]) +
                               (var == 2 ? 0 : static_cast<long>(k) * n[0] * n[1]);
          const double* weights = e.data() + static_cast<long>(row) * len;
          double sum = 0.0;
          for (int r = 0; r < len; ++r) sum += weights[r] * line[r * stride];
          *o++ = sum;
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
  // Every Bernstein function of the degrees has the same integral: the mean coefficient times the
  // reference volume is the trilinear element's volume (as det A's is the affine element's).
  b.integral = trilinear.coefficients().mean() * reference_volume(Shape::Hexahedron);
  bounds = b;
  return true;
}

}  // namespace semimesh::ho
