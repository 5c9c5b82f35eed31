// Bounds of an element's pieces from the element's own det J (see certify_pieces in validity.hpp).
#include "semimesh/ho/validity.hpp"

#include "jacobian_polynomial.hpp"

#include <limits>

namespace semimesh::ho {
namespace {

/// The box in the Bernstein domain's coordinates (t = (xi + 1) / 2 along a segment), per
/// reference direction; false when it is not a box of the element that a piece can be.
bool domain_box(Shape shape, const ReferenceBox& box, std::array<std::array<double, 2>, 3>& t) {
  for (int d = 0; d < 3; ++d) {
    const bool triangle = shape == Shape::Prism && d < 2;
    if (triangle) {
      if (box[d][0] != 0.0 || box[d][1] != 1.0) return false;  // a prism's triangle stays whole
      t[d] = {0.0, 1.0};
      continue;
    }
    if (!(-1.0 <= box[d][0] && box[d][0] < box[d][1] && box[d][1] <= 1.0)) return false;
    t[d] = {0.5 * (box[d][0] + 1.0), 0.5 * (box[d][1] + 1.0)};
  }
  return true;
}

/// det f: the product of the box's widths over the element's (the triangle's directions: 1).
double box_determinant(Shape shape, const ReferenceBox& box) {
  double det = 1.0;
  for (int d = (shape == Shape::Prism ? 2 : 0); d < 3; ++d) det *= 0.5 * (box[d][1] - box[d][0]);
  return det;
}

/// What certify_jacobian_by_subdivision returns when the whole element is one conclusive leaf, and
/// its volume: every Bernstein function of the piece's degrees has the same integral over the
/// reference element, the reference volume over their number.
std::optional<JacobianBounds> leaf_bounds(Shape shape, const BernsteinPolynomial& det_j) {
  const Eigen::VectorXd& c = det_j.coefficients();
  const double lowest = c.minCoeff(), highest = c.maxCoeff();
  if (!(lowest > kPieceMargin * highest)) return std::nullopt;  // near zero: the piece bisects itself
  JacobianBounds b;
  b.min_lower = lowest;
  b.max_upper = highest;
  b.min_upper = std::numeric_limits<double>::infinity();
  for (int id : det_j.layout().corners) b.min_upper = std::min(b.min_upper, c[id]);
  b.valid = b.proven = true;
  b.integral = c.mean() * reference_volume(shape);
  return b;
}

}  // namespace

std::vector<std::optional<JacobianBounds>> certify_pieces(Shape shape, int order, NodeSet set,
                                                          const Eigen::MatrixX3d& element_nodes,
                                                          const std::vector<ReferenceBox>& boxes) {
  std::vector<std::optional<JacobianBounds>> out(boxes.size());
  if (shape != Shape::Prism && shape != Shape::Hexahedron) return out;
  std::vector<std::array<std::array<double, 2>, 3>> t(boxes.size());
  std::vector<bool> usable(boxes.size());
  for (std::size_t k = 0; k < boxes.size(); ++k) usable[k] = domain_box(shape, boxes[k], t[k]);

  JacobianBounds affine;
  if (affine_jacobian(shape, order, set, element_nodes, affine)) {
    for (std::size_t k = 0; k < boxes.size(); ++k) {
      if (!usable[k]) continue;
      const double det = affine.min_lower * box_determinant(shape, boxes[k]);
      if (!(det > 0.0)) continue;  // an inverted element's pieces: certify them themselves
      JacobianBounds b = affine;
      b.min_lower = b.min_upper = b.max_upper = det;
      b.integral = det * reference_volume(shape);
      out[k] = b;
    }
    return out;
  }
  const BernsteinPolynomial whole = detail::jacobian_determinant(shape, order, set, element_nodes);
  // The Bernstein variable of each segment direction: the prism's zeta is its third variable, a
  // hexahedron's xi_d its variable d. The pieces cut along one direction only (one stack's layers)
  // are restricted together (restricted_to_each); the others one direction after another.
  const int first_direction = shape == Shape::Prism ? 2 : 0;
  const auto cut = [&](std::size_t k, int d) { return t[k][d][0] != 0.0 || t[k][d][1] != 1.0; };
  for (int d = first_direction; d < 3; ++d) {
    std::vector<std::size_t> along;
    std::vector<std::array<double, 2>> intervals;
    for (std::size_t k = 0; k < boxes.size(); ++k) {
      if (!usable[k] || !cut(k, d)) continue;
      bool only_d = true;
      for (int e = first_direction; e < 3; ++e) only_d = only_d && (e == d || !cut(k, e));
      if (!only_d) continue;
      along.push_back(k);
      intervals.push_back(t[k][d]);
    }
    std::vector<BernsteinPolynomial> pieces = whole.restricted_to_each(d, intervals);
    for (std::size_t i = 0; i < along.size(); ++i) {
      pieces[i] *= box_determinant(shape, boxes[along[i]]);
      out[along[i]] = leaf_bounds(shape, pieces[i]);
    }
  }
  for (std::size_t k = 0; k < boxes.size(); ++k) {
    int cuts = 0;
    for (int d = first_direction; d < 3; ++d) cuts += cut(k, d);
    if (!usable[k] || cuts == 1) continue;
    BernsteinPolynomial piece = whole;
    for (int d = first_direction; d < 3; ++d)
      if (cut(k, d)) piece = piece.restricted(d, t[k][d][0], t[k][d][1]);
    piece *= box_determinant(shape, boxes[k]);
    out[k] = leaf_bounds(shape, piece);
  }
  return out;
}

}  // namespace semimesh::ho
