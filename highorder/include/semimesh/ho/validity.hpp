// Certified validity of high-order elements: bounds of the Jacobian determinant det J over the whole
// reference element, not only at the nodes.
//
// Method (Johnen, Remacle & Geuzaine 2013, "Geometrical validity of curvilinear finite elements",
// J. Comput. Phys. 233): det J of an order-P element is a polynomial (pyramids: a polynomial on the
// collapsed cube, see src/validity/jacobian_polynomial.hpp); written in a Bernstein basis, which is
// non-negative and sums to one, its coefficients bound it from below and above, and its coefficients
// at the corners of the domain are exact values. When the coefficients straddle zero, the domain is
// bisected (de Casteljau along its longest edge in the Bernstein domain's coordinates) and the
// pieces are re-examined; bisection makes the coefficients converge to the values.
#pragma once

#include "semimesh/ho/element_type.hpp"

#include <Eigen/Core>

#include <limits>

#include <array>
#include <optional>
#include <vector>

namespace semimesh::ho {

/// Bounds of det J (derivatives with respect to Gmsh's reference coordinates) over the element.
///  min_lower  certified lower bound of min det J (smallest Bernstein coefficient over the pieces).
///  min_upper  upper bound of min det J: the smallest det J value actually evaluated (at the corners
///             of every piece examined), so min det J lies in [min_lower, min_upper].
///  max_upper  certified upper bound of max det J (largest coefficient over the pieces).
///  valid      true only when proven: every piece has all coefficients > 0.
///  proven     the verdict is proven: valid, or invalid because some evaluated det J <= 0. When false
///             (depth or budget exhausted with coefficients straddling zero) `valid` is false too:
///             an unproven element is treated as invalid.
///  subdivisions  number of bisections performed (each splits one piece in two).
struct JacobianBounds {
  double min_lower = 0.0;
  double min_upper = 0.0;
  double max_upper = 0.0;
  bool valid = false;
  bool proven = false;
  int subdivisions = 0;
  /// The integral of det J over the reference element (the element's volume) where the
  /// certification had it whole: affine_jacobian (det A times the reference volume),
  /// trilinear_jacobian (the trilinear element's) and certify_pieces (the mean of a piece's
  /// Bernstein coefficients times it, or det A times it); NaN elsewhere.
  double integral = std::numeric_limits<double>::quiet_NaN();
};

/// The volume of the reference element of a 3D shape (Gmsh's): 1/6 (tetrahedron), 4/3 (pyramid:
/// base [-1, 1]^2, height 1), 1 (prism: the unit triangle times [-1, 1]), 8 (hexahedron: [-1, 1]^3).
double reference_volume(Shape shape);

/// Certifies the sign of det J of one 3D element (tetrahedron, pyramid, prism, hexahedron; orders
/// 1..kMaxOrder). element_nodes: (num_nodes(shape, order), 3), canonical (Gmsh) order, nodes of the
/// reference positions of `set`. max_depth: levels of refinement, each level being three bisections
/// (the analogue of one split into 8 children), so the smallest piece is about 2^-max_depth of the
/// element across; at most kMaxCertificationPieces pieces are examined in all.
/// Throws std::invalid_argument for a 2D shape, a bad order or a wrong number of nodes.
/// floor_ratio > 0: where a piece's lower bound is below floor_ratio x the whole element's bound of
/// max det J, it is bisected further (same depth and piece limits) until it is above, or until an
/// evaluated det J proves min det J / max det J < floor_ratio; so scaled_jacobian(bounds) >=
/// floor_ratio decides "not numerically degenerate" without a loose bound failing a good element.
/// It changes the bounds, never `valid` or `proven` (those are about the sign).
/// Fast paths: an element whose nodes are an affine image of the reference nodes (every straight-sided
/// tet, and the far field is made of them) has the constant det J = det A, returned without the
/// Bernstein expansion (see affine_jacobian); a hexahedron that is its trilinear vertex element has
/// that element's det J (see trilinear_jacobian); everything else goes to
/// certify_jacobian_by_subdivision.
JacobianBounds certify_jacobian(Shape shape, int order, NodeSet set, const Eigen::MatrixX3d& element_nodes,
                                int max_depth = 8, double floor_ratio = 0.0);

/// The general path of certify_jacobian (Bernstein coefficients and bisection), for every element;
/// the reference the affine fast path is tested against.
JacobianBounds certify_jacobian_by_subdivision(Shape shape, int order, NodeSet set,
                                               const Eigen::MatrixX3d& element_nodes, int max_depth = 8,
                                               double floor_ratio = 0.0);

/// When every node is within kAffineTolerance x sigma_min(A) (bounded below by 2 |det A| / |A|_F^2)
/// of the image of its reference node
/// under one affine map x = A r + b (fitted on four vertices), returns the bounds min_lower =
/// min_upper = max_upper = det A (proven, subdivisions 0) and the integral det A x
/// reference_volume(shape); otherwise false. Why that is a proof: the
/// true J = A + E with |E| <= L d, d the largest node deviation and L the largest sum of the
/// reference gradients of the Lagrange basis (< 1e4 for orders <= 10), so |E| < 1e-6 sigma_min(A)
/// and det J has the sign of det A with a relative error below 3e-6.
constexpr double kAffineTolerance = 1e-10;
bool affine_jacobian(Shape shape, int order, NodeSet set, const Eigen::MatrixX3d& element_nodes,
                     JacobianBounds& bounds);

/// Fast path for a hexahedron whose nodes are the image of the reference nodes under the trilinear
/// map of its eight vertices (the wake block's split pieces, straight-sided boxes with graded
/// layers): its det J is the trilinear element's, a polynomial of degree 2 per direction (27
/// coefficients, not (3P)^3), elevated to the element's degree 3P - 1 and certified as
/// certify_jacobian_by_subdivision certifies (the same bisections and floor). Why that is a proof
/// for the element: its true J = J_1 + E, |E| <= L d with d the largest node deviation from the
/// trilinear image (plus rounding) and L < 1e4 (affine_jacobian); with |J_1| <= G (sqrt 3 times the
/// longest edge: J_1's columns are averages of edge vectors), det J is within delta = 3 G^2 e +
/// 3 G e^2 + e^3 (e = L d) of det J_1: valid when the trilinear element's lower bound exceeds
/// delta. The bounds returned are the trilinear element's (as affine_jacobian returns det A: within
/// delta, a rounding-sized relative error, of the element's), and its integral (the mean of its
/// Bernstein coefficients times the reference volume). `element_nodes`: an order-`order`
/// hexahedron's. Returns false (nothing set) for order 1 or a wrong node count, nodes off the
/// trilinear image by more than kAffineTolerance x the longest edge, or when the bounds do not
/// prove the element valid with that margin: the general path decides.
bool trilinear_jacobian(int order, NodeSet set, const Eigen::MatrixX3d& element_nodes, JacobianBounds& bounds,
                        int max_depth = 8, double floor_ratio = 0.0);

constexpr int kMaxCertificationPieces = 200000;

/// A box of a prism's or hexahedron's reference element: [lo, hi] per reference direction; a
/// prism's xi and eta stay whole ([0, 1]: only its zeta range may be a part of [-1, 1]).
using ReferenceBox = std::array<std::array<double, 2>, 3>;

/// Bounds of the pieces of one element, derived from the element's own det J instead of a fresh
/// Bernstein expansion per piece. Piece k is the element whose map is x o f_k, f_k the affine
/// map from the reference element onto boxes[k] that scales each direction by (hi - lo) / (whole
/// length), which is what splitting an element along reference directions with constant
/// interfaces gives (split_layers). Then det J_k(xi) = det J(f_k(xi)) * det f_k, a polynomial of the
/// same space, whose Bernstein coefficients are the element's restricted to the box (de Casteljau)
/// times det f_k: exactly the coefficients certify_jacobian_by_subdivision computes from the
/// piece's own nodes, before it bisects.
/// Returns per piece what certify_jacobian would return for it when that needs no bisection: all
/// coefficients above kPieceMargin x the largest (a margin far above the rounding of the piece's
/// nodes), so valid and proven with min_lower / min_upper / max_upper from those coefficients. An
/// affine element (affine_jacobian) gives each piece min = max = det A * det f_k (the element's
/// proof carries over: J_k = J(f_k) A_k). Otherwise (a piece whose coefficients come near zero, a
/// tetrahedron or pyramid, a box outside the element) std::nullopt: certify that piece itself.
/// A floor on the scaled Jacobian is the caller's to apply (certify_mesh does).
constexpr double kPieceMargin = 1e-6;
std::vector<std::optional<JacobianBounds>> certify_pieces(Shape shape, int order, NodeSet set,
                                                          const Eigen::MatrixX3d& element_nodes,
                                                          const std::vector<ReferenceBox>& boxes);

/// Scaled Jacobian from certified bounds: min_lower / max(|max_upper|, |min_lower|), in [-1, 1].
/// For a valid element that is min_lower / max_upper, a lower bound of min det J / max det J (the
/// conservative side: the true ratio is at least this). Negative when min_lower <= 0; -1 when the
/// whole element is inverted (max_upper <= 0).
double scaled_jacobian(const JacobianBounds& bounds);

/// Slow, obviously right reference: det J from the Lagrange basis at a dense grid of the reference
/// element (samples_per_direction >= 2 points per direction, boundary included; for the pyramid the
/// apex layer z = 1 is replaced by z = 1 - 1e-6 because the rational basis is not defined there).
struct SampledJacobian {
  double min = 0.0;
  double max = 0.0;
};
SampledJacobian sample_jacobian(Shape shape, int order, NodeSet set, const Eigen::MatrixX3d& element_nodes,
                                int samples_per_direction);

}  // namespace semimesh::ho
