#include "semimesh/ho/validity.hpp"

#include "jacobian_polynomial.hpp"

#include <algorithm>
#include <limits>
#include <utility>
#include <vector>

namespace semimesh::ho {
namespace {

/// Vertices of one factor of a piece in the factor's own coordinates (lambda_1..lambda_d, or t):
/// (dim + 1) points of R^dim.
using FactorVertices = std::array<std::array<double, 3>, 4>;

/// One per factor (at most three: a hexahedron's segments); a piece is copied at every bisection.
using PieceVertices = std::array<FactorVertices, 3>;

struct Piece {
  BernsteinPolynomial det_j;
  PieceVertices vertices;  // [factors] used
  int depth = 0;           // bisections from the whole element
};

PieceVertices whole_domain(const BernsteinLayout& layout) {
  PieceVertices vertices{};
  for (std::size_t f = 0; f < layout.factors.size(); ++f)
    for (int vertex = 1; vertex < 4; ++vertex) vertices[f][vertex][vertex - 1] = 1.0;  // unit simplex
  return vertices;
}

/// The longest edge over all factors of the piece: (factor, vertex a, vertex b).
std::array<int, 3> longest_edge(const Piece& piece) {
  const BernsteinLayout& layout = piece.det_j.layout();
  std::array<int, 3> best{0, 0, 1};
  double best_length = -1.0;
  for (int f = 0; f < static_cast<int>(layout.factors.size()); ++f) {
    const int dim = layout.factors[f].dim;
    for (int a = 0; a <= dim; ++a)
      for (int b = a + 1; b <= dim; ++b) {
        double length = 0.0;
        for (int k = 0; k < dim; ++k) {
          const double d = piece.vertices[f][a][k] - piece.vertices[f][b][k];
          length += d * d;
        }
        if (length > best_length + 1e-12) {
          best_length = length;
          best = {f, a, b};
        }
      }
  }
  return best;
}

}  // namespace

JacobianBounds certify_jacobian(Shape shape, int order, NodeSet set, const Eigen::MatrixX3d& element_nodes,
                                int max_depth, double floor_ratio) {
  JacobianBounds bounds;
  if (affine_jacobian(shape, order, set, element_nodes, bounds)) return bounds;
  if (shape == Shape::Hexahedron && trilinear_jacobian(order, set, element_nodes, bounds, max_depth, floor_ratio))
    return bounds;
  return certify_jacobian_by_subdivision(shape, order, set, element_nodes, max_depth, floor_ratio);
}

JacobianBounds certify_jacobian_by_subdivision(Shape shape, int order, NodeSet set,
                                               const Eigen::MatrixX3d& element_nodes, int max_depth,
                                               double floor_ratio) {
  return detail::certify_determinant(detail::jacobian_determinant(shape, order, set, element_nodes), max_depth,
                                     floor_ratio);
}

namespace detail {

JacobianBounds certify_determinant(BernsteinPolynomial root, int max_depth, double floor_ratio) {
  const int max_bisections = 3 * std::max(0, max_depth);
  JacobianBounds bounds;
  bounds.min_lower = std::numeric_limits<double>::infinity();
  bounds.min_upper = std::numeric_limits<double>::infinity();
  bounds.max_upper = -std::numeric_limits<double>::infinity();
  bool invalid_found = false;
  bool undecided = false;
  int pieces_examined = 0;

  // Every piece's coefficients lie below the root's largest (convex hull), so this bounds max det J.
  const double floor_value = floor_ratio * root.coefficients().maxCoeff();
  double highest_value = -std::numeric_limits<double>::infinity();  // largest evaluated det J
  bool below_floor = false;  // proven: an evaluated det J below floor_ratio x an evaluated one
  std::vector<Piece> stack;
  const PieceVertices whole = whole_domain(root.layout());
  stack.push_back(Piece{std::move(root), whole, 0});
  while (!stack.empty()) {
    Piece piece = std::move(stack.back());
    stack.pop_back();
    ++pieces_examined;
    const Eigen::VectorXd& c = piece.det_j.coefficients();
    const double lowest = c.minCoeff();
    double lowest_value = std::numeric_limits<double>::infinity();  // corners are exact values
    for (int id : piece.det_j.layout().corners) {
      lowest_value = std::min(lowest_value, c[id]);
      highest_value = std::max(highest_value, c[id]);
    }
    bounds.min_upper = std::min(bounds.min_upper, lowest_value);
    if (lowest_value <= 0.0) invalid_found = true;
    if (bounds.min_upper < floor_ratio * highest_value) below_floor = true;

    const bool conclusive = lowest > 0.0 || invalid_found;
    const bool floor_decided = floor_ratio <= 0.0 || lowest > floor_value || below_floor || invalid_found;
    const bool can_split = piece.depth < max_bisections && pieces_examined + 2 <= kMaxCertificationPieces;
    // The floor may use a quarter of the piece budget, so it never leaves the sign undecided.
    const bool floor_can_split = can_split && pieces_examined < kMaxCertificationPieces / 4;
    if (!((!conclusive && can_split) || (!floor_decided && floor_can_split))) {
      // A leaf: its coefficients bound det J over its part of the element.
      bounds.min_lower = std::min(bounds.min_lower, lowest);
      bounds.max_upper = std::max(bounds.max_upper, c.maxCoeff());
      if (!conclusive) undecided = true;
      continue;
    }
    const std::array<int, 3> edge = longest_edge(piece);
    Piece first{BernsteinPolynomial(piece.det_j.layout_ptr()), piece.vertices, piece.depth + 1};
    Piece second{BernsteinPolynomial(piece.det_j.layout_ptr()), piece.vertices, piece.depth + 1};
    piece.det_j.bisect(edge[0], edge[1], edge[2], first.det_j, second.det_j);
    const auto& va = piece.vertices[edge[0]][edge[1]];
    const auto& vb = piece.vertices[edge[0]][edge[2]];
    std::array<double, 3> midpoint{};
    for (int k = 0; k < 3; ++k) midpoint[k] = 0.5 * (va[k] + vb[k]);
    first.vertices[edge[0]][edge[2]] = midpoint;
    second.vertices[edge[0]][edge[1]] = midpoint;
    ++bounds.subdivisions;
    stack.push_back(std::move(second));
    stack.push_back(std::move(first));
  }
  bounds.valid = !invalid_found && !undecided;
  bounds.proven = invalid_found || !undecided;
  return bounds;
}

}  // namespace detail
}  // namespace semimesh::ho
