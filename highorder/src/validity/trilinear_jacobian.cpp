#include "semimesh/ho/basis.hpp"
#include "semimesh/ho/validity.hpp"

#include "jacobian_polynomial.hpp"

#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
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
  // One direction at a time (a separable elevation: ~7k products at order 4, not the 140k of all
  // 27 x 1728 pairs). A product of segments numbers its coefficients in box order, i + n0 (j + n1 k)
  // (every box entry is inside), so the coefficients are the box. Each output entry is the sum along
  // its input line, started at 0 and taken in line order; the loops run over whole rows (planes) of
  // outputs at a time, which the compiler vectorises (the checks elevate every straight-sided
  // hexahedron). The 1D matrices, row-major, and the output layouts are kept per thread (a few:
  // found by a scan; the layout cache's lock would serialise the threads).
  struct Elevation {
    int from = -1, to = -1;
    std::vector<double> rows;  // [to + 1][from + 1]
  };
  thread_local std::vector<Elevation> elevations;
  thread_local std::vector<std::shared_ptr<const BernsteinLayout>> layouts;
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
  std::shared_ptr<const BernsteinLayout> to_layout;
  for (const auto& layout : layouts)
    if (layout->factors[0].degree == degree) to_layout = layout;
  if (!to_layout) {
    to_layout = BernsteinLayout::get(std::vector<SimplexFactor>(3, SimplexFactor{1, degree}));
    layouts.push_back(to_layout);
  }
  thread_local std::vector<double> box, next;
  std::array<int, 3> n{};
  for (int k = 0; k < 3; ++k) n[k] = from.factors[k].degree + 1;
  box.assign(p.coefficients().data(), p.coefficients().data() + p.size());
  const int m_var = degree + 1;
  for (int var = 0; var < 3; ++var) {
    const std::vector<double>& e = elevation(n[var] - 1);
    const int len = n[var];
    std::array<int, 3> m = n;
    m[var] = m_var;
    next.assign(static_cast<std::size_t>(m[0]) * m[1] * m[2], 0.0);
    double* o = next.data();
    const double* in = box.data();
    if (var == 0) {  // along i (stride 1): one output at a time, the line contiguous
      for (int line = 0; line < n[1] * n[2]; ++line, in += n[0])
        for (int i = 0; i < m_var; ++i, ++o)
          for (int r = 0; r < len; ++r) *o += e[static_cast<std::size_t>(i * len + r)] * in[r];
    } else {  // along j (k): a row (plane) of outputs from `len` input rows (planes)
      const long run = var == 1 ? n[0] : static_cast<long>(n[0]) * n[1];
      const long blocks = var == 1 ? n[2] : 1, block_in = run * len;
      for (long b = 0; b < blocks; ++b, in += block_in)
        for (int row = 0; row < m_var; ++row, o += run)
          for (int r = 0; r < len; ++r) {
            const double w = e[static_cast<std::size_t>(row * len + r)];
            const double* src = in + r * run;
            for (long q = 0; q < run; ++q) o[q] += w * src[q];
          }
    }
    std::swap(box, next);
    n = m;
  }
  BernsteinPolynomial out(std::move(to_layout));
  out.coefficients() = Eigen::Map<const Eigen::VectorXd>(box.data(), static_cast<Eigen::Index>(box.size()));
  return out;
}

}  // namespace detail

bool trilinear_jacobian(int order, NodeSet set, const Eigen::MatrixX3d& element_nodes, JacobianBounds& bounds,
                        int max_depth, double floor_ratio) {
  if (order < 2 || order > kMaxOrder || element_nodes.rows() != num_nodes(Shape::Hexahedron, order)) return false;
  thread_local Eigen::MatrixX3d vertices;  // this thread's: no allocation per element
  vertices = element_nodes.topRows(8);
  double longest = 0.0;
  for (const auto& e : edges(Shape::Hexahedron))
    longest = std::max(longest, (vertices.row(e[1]) - vertices.row(e[0])).norm());
  // The deviation as computed, plus what rounding at the coordinates' magnitude can hide from it
  // (node by node: no (nodes, 3) temporary).
  const double rounding = 8.0 * std::numeric_limits<double>::epsilon() * element_nodes.rowwise().norm().maxCoeff();
  const Eigen::MatrixXd& trilinear_at_nodes = vertex_interpolation(order, set);
  double deviation = 0.0;
  for (Eigen::Index r = 0; r < element_nodes.rows(); ++r) {
    Eigen::RowVector3d x = Eigen::RowVector3d::Zero();
    for (int v = 0; v < 8; ++v) x += trilinear_at_nodes(r, v) * vertices.row(v);
    const double d = (x - element_nodes.row(r)).norm();
    if (std::isnan(d)) return false;  // no trilinear element's nodes
    deviation = std::max(deviation, d);
  }
  deviation += rounding;
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
