// Bounds of an element's pieces from its own det J (certify_pieces) pinned to the reference: each
// piece built as the isoparametric split builds it (the element's Lagrange map at the piece's
// reference points) and certified on its own nodes with certify_jacobian. Every shape that is split
// (prism, hexahedron), orders 1-4, both node sets; a well-shaped element, a barely valid one, one
// whose bottom pieces are inverted, one whose pieces fall under the margin.
#include "semimesh/ho/basis.hpp"
#include "mapped_nodes.hpp"
#include "semimesh/ho/bernstein.hpp"
#include "semimesh/ho/validity.hpp"

#include <gtest/gtest.h>

#include <Eigen/LU>

#include <cmath>
#include <functional>
#include <random>
#include <string>

namespace semimesh::ho {
namespace {

using testing::Map;
using testing::mapped_nodes;

/// The piece's nodes as split_layers makes them: the element's map at the box's reference nodes.
Eigen::MatrixX3d piece_nodes(Shape shape, int order, NodeSet set, const Eigen::MatrixX3d& element,
                             const ReferenceBox& box) {
  Eigen::MatrixX3d q = reference_nodes(shape, order, set);
  for (int i = 0; i < q.rows(); ++i)
    for (int d = (shape == Shape::Prism ? 2 : 0); d < 3; ++d)
      q(i, d) = box[d][0] + 0.5 * (q(i, d) + 1.0) * (box[d][1] - box[d][0]);
  return map_points(LagrangeBasis(shape, order, set), element, q);
}

/// Interfaces -1 = z_0 < ... < z_N = 1 of N layers whose thicknesses grow by r (as the split's).
std::vector<double> layer_interfaces(int layers, double r) {
  double total = 0.0;
  for (int k = 0; k < layers; ++k) total += std::pow(r, k);
  std::vector<double> z{-1.0};
  for (int k = 0; k < layers; ++k) z.push_back(z.back() + 2.0 * std::pow(r, k) / total);
  z.back() = 1.0;
  return z;
}

/// Boxes of 5 layers growing by 2 along `direction` (and, for a hexahedron, 3 by 1.5 along the
/// next direction too when `two`).
std::vector<ReferenceBox> layer_boxes(Shape shape, int direction, bool two) {
  ReferenceBox whole;
  for (int d = 0; d < 3; ++d) whole[d] = {shape == Shape::Prism && d < 2 ? 0.0 : -1.0, 1.0};
  const std::vector<double> za = layer_interfaces(5, 2.0), zb = layer_interfaces(3, 1.5);
  const int other = (direction + 1) % 3;
  std::vector<ReferenceBox> boxes;
  for (int kb = 0; kb < (two ? 3 : 1); ++kb)
    for (int ka = 0; ka < 5; ++ka) {
      ReferenceBox box = whole;
      box[direction] = {za[ka], za[ka + 1]};
      if (two) box[other] = {zb[kb], zb[kb + 1]};
      boxes.push_back(box);
    }
  return boxes;
}

std::string label(Shape shape, int order, NodeSet set) {
  return to_string(shape) + " P" + std::to_string(order) + (set == NodeSet::GLL ? " GLL" : " equispaced");
}

/// Checks every derived piece against the reference; returns how many pieces were derived.
int pin_pieces(Shape shape, int order, NodeSet set, const Eigen::MatrixX3d& element,
               const std::vector<ReferenceBox>& boxes) {
  const std::vector<std::optional<JacobianBounds>> derived = certify_pieces(shape, order, set, element, boxes);
  EXPECT_EQ(derived.size(), boxes.size());
  int present = 0;
  for (std::size_t k = 0; k < boxes.size(); ++k) {
    SCOPED_TRACE("piece " + std::to_string(k));
    const JacobianBounds reference = certify_jacobian(shape, order, set, piece_nodes(shape, order, set, element, boxes[k]));
    if (!derived[k]) continue;  // certified on its own: the reference is what the mesh gets
    ++present;
    const JacobianBounds& b = *derived[k];
    // A derived piece is one the reference proves valid at its first expansion (or affine).
    EXPECT_TRUE(reference.valid);
    EXPECT_TRUE(reference.proven);
    EXPECT_EQ(reference.subdivisions, 0);
    EXPECT_TRUE(b.valid && b.proven);
    const double scale = std::abs(reference.max_upper);
    EXPECT_NEAR(b.min_lower, reference.min_lower, 1e-8 * scale);
    EXPECT_NEAR(b.min_upper, reference.min_upper, 1e-8 * scale);
    EXPECT_NEAR(b.max_upper, reference.max_upper, 1e-8 * scale);
    EXPECT_NEAR(scaled_jacobian(b), scaled_jacobian(reference), 1e-8);
  }
  return present;
}

// A smooth curved map of the reference element (not in the element's space: its interpolant is
// the element), turned and stretched so that no direction is special.
Eigen::Vector3d curved(const Eigen::Vector3d& r) {
  const double x = r(0), y = r(1), z = r(2);
  const Eigen::Vector3d p(x + 0.08 * std::sin(1.3 * y + 0.4 * z), 0.9 * y + 0.06 * x * x + 0.05 * z * y,
                          0.3 * (z + 1.0) + 0.07 * std::cos(x + y) + 0.02 * x * z);
  Eigen::Matrix3d turn;
  turn << 0.8, -0.6, 0.0, 0.6, 0.8, 0.0, 0.1, 0.0, 1.0;
  return turn * p + Eigen::Vector3d(4.0, -2.0, 1.0);
}

// det J of (x, y (1 + g z), z) is 1 + g z (in every shape's space from order 1): g < 1 is valid with
// min det J = 1 - g at z = -1, g > 1 is inverted below z = -1 / g.
Map sheared(double g) {
  return [g](const Eigen::Vector3d& r) -> Eigen::Vector3d { return {r(0), r(1) * (1.0 + g * r(2)), r(2)}; };
}

TEST(CertifyPieces, RestrictionIsThePolynomialOnThePart) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (const std::vector<SimplexFactor>& factors :
       std::vector<std::vector<SimplexFactor>>{{{1, 4}, {1, 3}, {1, 5}}, {{2, 4}, {1, 6}}}) {
    BernsteinPolynomial p(factors);
    for (int i = 0; i < p.size(); ++i) p.coefficients()[i] = u(rng) - 0.5;
    const int var = p.layout().num_vars - 1;
    for (const auto& [a, b] : std::vector<std::pair<double, double>>{{0.0, 0.3}, {0.2, 0.7}, {0.6, 1.0}, {0.0, 1.0}}) {
      const BernsteinPolynomial q = p.restricted(var, a, b);
      for (int trial = 0; trial < 20; ++trial) {
        Eigen::Vector3d s(u(rng), u(rng), u(rng));
        if (factors[0].dim == 2 && s(0) + s(1) > 1.0) s.head<2>() = Eigen::Vector2d(1.0 - s(0), 1.0 - s(1));
        Eigen::Vector3d t = s;
        t(var) = a + (b - a) * s(var);
        EXPECT_NEAR(q.evaluate(s), p.evaluate(t), 1e-13);
      }
    }
  }
  BernsteinPolynomial p(std::vector<SimplexFactor>{{2, 2}, {1, 2}});
  EXPECT_THROW(p.restricted(0, 0.0, 0.5), std::invalid_argument);  // a triangle's variable
  EXPECT_THROW(p.restricted(2, 0.5, 0.5), std::invalid_argument);
  EXPECT_THROW(p.restricted(2, -0.1, 0.5), std::invalid_argument);
}

// The fast path (one matrix product per interval) against restricted()'s de Casteljau, interval by
// interval, on every segment variable of a hexahedron's and a prism's determinant layouts.
TEST(CertifyPieces, RestrictionToEachIntervalIsRestrictionToIt) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const std::vector<std::array<double, 2>> intervals{{0.0, 0.03}, {0.03, 0.1}, {0.1, 0.45}, {0.45, 1.0}, {0.2, 0.7}};
  for (const std::vector<SimplexFactor>& factors :
       std::vector<std::vector<SimplexFactor>>{{{1, 11}, {1, 11}, {1, 11}}, {{1, 2}, {1, 5}, {1, 8}}, {{2, 10}, {1, 11}}}) {
    BernsteinPolynomial p(factors);
    for (int i = 0; i < p.size(); ++i) p.coefficients()[i] = u(rng) - 0.3;
    for (int var = 0; var < p.layout().num_vars; ++var) {
      if (p.layout().factors[p.layout().var_factor[var]].dim != 1) continue;
      SCOPED_TRACE("variable " + std::to_string(var));
      const std::vector<BernsteinPolynomial> each = p.restricted_to_each(var, intervals);
      ASSERT_EQ(each.size(), intervals.size());
      for (std::size_t k = 0; k < intervals.size(); ++k) {
        const BernsteinPolynomial reference = p.restricted(var, intervals[k][0], intervals[k][1]);
        EXPECT_EQ(&each[k].layout(), &reference.layout());
        EXPECT_LT((each[k].coefficients() - reference.coefficients()).cwiseAbs().maxCoeff(), 1e-14);
      }
    }
  }
  BernsteinPolynomial p(std::vector<SimplexFactor>{{2, 2}, {1, 2}});
  EXPECT_THROW(p.restricted_to_each(0, {{0.0, 0.5}}), std::invalid_argument);  // a triangle's variable
  EXPECT_THROW(p.restricted_to_each(2, {{0.0, 0.5}, {0.5, 0.5}}), std::invalid_argument);
  EXPECT_TRUE(p.restricted_to_each(2, {}).empty());
}

TEST(CertifyPieces, CurvedElementsMatchTheReferenceOnEveryShapeAndOrder) {
  for (Shape shape : {Shape::Prism, Shape::Hexahedron})
    for (NodeSet set : {NodeSet::Equispaced, NodeSet::GLL})
      for (int order = 1; order <= 4; ++order) {
        SCOPED_TRACE(label(shape, order, set));
        const Eigen::MatrixX3d element = mapped_nodes(shape, order, set, curved);
        std::vector<ReferenceBox> boxes = layer_boxes(shape, 2, false);
        if (shape == Shape::Hexahedron) {
          for (const ReferenceBox& b : layer_boxes(shape, 0, false)) boxes.push_back(b);
          for (const ReferenceBox& b : layer_boxes(shape, 1, true)) boxes.push_back(b);
        }
        // Well inside validity: every piece is derived (the test cannot pass vacuously).
        EXPECT_EQ(pin_pieces(shape, order, set, element, boxes), static_cast<int>(boxes.size()));
      }
}

TEST(CertifyPieces, AffineElementsGiveConstantPieces) {
  Eigen::Matrix3d a;
  a << 2.0, 0.3, 0.1, 0.2, 1.5, -0.2, 0.1, 0.4, 0.8;
  for (Shape shape : {Shape::Prism, Shape::Hexahedron})
    for (int order = 1; order <= 4; ++order) {
      SCOPED_TRACE(label(shape, order, NodeSet::GLL));
      const Eigen::MatrixX3d element = mapped_nodes(
          shape, order, NodeSet::GLL, [&](const Eigen::Vector3d& x) -> Eigen::Vector3d { return a * x; });
      const std::vector<ReferenceBox> boxes = layer_boxes(shape, 2, false);
      EXPECT_EQ(pin_pieces(shape, order, NodeSet::GLL, element, boxes), 5);
      const std::vector<std::optional<JacobianBounds>> derived =
          certify_pieces(shape, order, NodeSet::GLL, element, boxes);
      for (std::size_t k = 0; k < boxes.size(); ++k) {
        const double det = a.determinant() * 0.5 * (boxes[k][2][1] - boxes[k][2][0]);
        EXPECT_NEAR(derived[k]->min_lower, det, 1e-12 * det);
        EXPECT_EQ(derived[k]->min_lower, derived[k]->max_upper);
      }
    }
}

TEST(CertifyPieces, BarelyValidElementMatchesTheReference) {
  // min det J / max det J = 1e-3 / 2 over the element: valid, but barely, in its bottom layer.
  for (Shape shape : {Shape::Prism, Shape::Hexahedron})
    for (int order = 1; order <= 4; ++order) {
      SCOPED_TRACE(label(shape, order, NodeSet::GLL));
      const Eigen::MatrixX3d element = mapped_nodes(shape, order, NodeSet::GLL, sheared(1.0 - 1e-3));
      const std::vector<ReferenceBox> boxes = layer_boxes(shape, 2, false);
      EXPECT_EQ(pin_pieces(shape, order, NodeSet::GLL, element, boxes), 5);
      const JacobianBounds whole = certify_jacobian(shape, order, NodeSet::GLL, element);
      EXPECT_TRUE(whole.valid);
      EXPECT_LT(scaled_jacobian(whole), 1e-3);
    }
}

TEST(CertifyPieces, PiecesUnderTheMarginAreLeftToTheReference) {
  // min det J = 1e-9 at the body: the bottom piece's bounds are not derived (rounding of its nodes
  // could matter there); it is certified on its own (and is valid), the others are derived.
  for (Shape shape : {Shape::Prism, Shape::Hexahedron})
    for (int order = 1; order <= 4; ++order) {
      SCOPED_TRACE(label(shape, order, NodeSet::GLL));
      const Eigen::MatrixX3d element = mapped_nodes(shape, order, NodeSet::GLL, sheared(1.0 - 1e-9));
      const std::vector<ReferenceBox> boxes = layer_boxes(shape, 2, false);
      const std::vector<std::optional<JacobianBounds>> derived =
          certify_pieces(shape, order, NodeSet::GLL, element, boxes);
      EXPECT_FALSE(derived[0].has_value());
      EXPECT_EQ(pin_pieces(shape, order, NodeSet::GLL, element, boxes), 4);
      EXPECT_TRUE(certify_jacobian(shape, order, NodeSet::GLL, piece_nodes(shape, order, NodeSet::GLL, element, boxes[0])).valid);
    }
}

TEST(CertifyPieces, InvertedPiecesAreNeverDerived) {
  // g = 1.2: det J < 0 below z = -1/1.2; the bottom layers (z up to -0.81) are inverted or folded.
  for (Shape shape : {Shape::Prism, Shape::Hexahedron})
    for (int order = 1; order <= 4; ++order) {
      SCOPED_TRACE(label(shape, order, NodeSet::GLL));
      const Eigen::MatrixX3d element = mapped_nodes(shape, order, NodeSet::GLL, sheared(1.2));
      EXPECT_FALSE(certify_jacobian(shape, order, NodeSet::GLL, element).valid);
      const std::vector<ReferenceBox> boxes = layer_boxes(shape, 2, false);
      const std::vector<std::optional<JacobianBounds>> derived =
          certify_pieces(shape, order, NodeSet::GLL, element, boxes);
      int invalid = 0;
      for (std::size_t k = 0; k < boxes.size(); ++k) {
        const JacobianBounds reference =
            certify_jacobian(shape, order, NodeSet::GLL, piece_nodes(shape, order, NodeSet::GLL, element, boxes[k]));
        if (!reference.valid) {
          ++invalid;
          EXPECT_FALSE(derived[k].has_value()) << "piece " << k;
        }
      }
      EXPECT_EQ(invalid, 2);
      EXPECT_EQ(pin_pieces(shape, order, NodeSet::GLL, element, boxes), 3);
    }
}

TEST(CertifyPieces, OtherShapesAndBoxesAreLeftToTheReference) {
  const Eigen::MatrixX3d tet = mapped_nodes(Shape::Tetrahedron, 2, NodeSet::GLL, curved);
  ReferenceBox whole{{{-1.0, 1.0}, {-1.0, 1.0}, {-1.0, 0.0}}};
  EXPECT_FALSE(certify_pieces(Shape::Tetrahedron, 2, NodeSet::GLL, tet, {whole})[0].has_value());
  const Eigen::MatrixX3d prism = mapped_nodes(Shape::Prism, 2, NodeSet::GLL, curved);
  ReferenceBox cut_triangle{{{0.0, 0.5}, {0.0, 1.0}, {-1.0, 0.0}}};  // a prism's triangle is never cut
  ReferenceBox outside{{{0.0, 1.0}, {0.0, 1.0}, {-1.0, 1.5}}};
  const auto derived = certify_pieces(Shape::Prism, 2, NodeSet::GLL, prism, {cut_triangle, outside});
  EXPECT_FALSE(derived[0].has_value());
  EXPECT_FALSE(derived[1].has_value());
}

}  // namespace
}  // namespace semimesh::ho
