// The Jacobian determinant of one element as an exact Bernstein polynomial (internal to validity).
//
// Spaces, derived from the element spaces (each term of det J takes one column from each of the
// three derivative columns, so degrees add; compare Johnen, Remacle & Geuzaine 2013, J. Comput. Phys.
// 233, and Johnen & Geuzaine 2015 for pyramids). With x in the order-P Lagrange space:
//   tetrahedron  x in P_P                    dx/dxi_k in P_{P-1}            det J in P_{3P-3}
//   hexahedron   x in Q_P                    dx/dxi_k: degree P-1 in xi_k,   det J in Q_{3P-1}
//                                            P in the other two
//   prism        x in P_P(xi,eta) x P_P(zeta) d/dxi, d/deta: (P-1) x P;       det J in P_{3P-2} x P_{3P-1}
//                                            d/dzeta: P x (P-1)
//   pyramid      (rational) see below        det J in Q_{3P-1} x Q_{3P-1} x P_{3P-3} (collapsed cube)
// Pyramid: Gmsh's order-P pyramid space (Bergot, Cohen & Durufle 2010, the one Gmsh's
// BergotBasis spans) written in collapsed coordinates xi = a (1-c), eta = b (1-c), zeta = c, with
// (a, b, c) in [-1,1]^2 x [0,1], is  V = sum_{s=0..P} Q_{P-s}(a, b) B^P_s(c)  (B^P_s: 1D Bernstein
// in c), a subspace of the polynomials Q_P(a, b) x P_P(c). Because B^P_s(c) has the factor (1-c)^{P-s},
// dX/da and dX/db carry a factor (1-c) exactly, and since det d(xi,eta,zeta)/d(a,b,c) = (1-c)^2,
//   det J_xi = det[dX/da / (1-c), dX/db / (1-c), dX/dc],
// a polynomial on the closed cube, whose Bernstein coefficients bound det J over the pyramid with no
// approximation. The apex (c = 1) becomes the top face of the cube: det J there is the limit of det J
// along each ray into the apex, and must be positive too.
//
// Instead of sampling det J at the nodes of its space and applying the (large, for P = 8 badly
// conditioned) interpolation-to-Bezier matrix, the element nodes are converted once to Bezier control
// points of the order-P map (a num_nodes x num_nodes matrix, cached per shape/order/node set) and
// det J is formed by exact Bernstein derivatives and products. Both give the same coefficients in
// exact arithmetic; this one needs no matrix of the size of the det J space (13824^2 for a P = 8 hex).
#pragma once

#include "semimesh/ho/bernstein.hpp"
#include "semimesh/ho/element_type.hpp"
#include "semimesh/ho/validity.hpp"

#include <Eigen/Core>

namespace semimesh::ho::detail {

/// certify_jacobian_by_subdivision's bounds from det J's Bernstein form (bisections, floor) instead
/// of the element's nodes.
JacobianBounds certify_determinant(BernsteinPolynomial root, int max_depth, double floor_ratio);

/// A polynomial on a product of segments (a hexahedron's space) written in degree `degree` along
/// every variable (each at most that already): the same polynomial, each 1D factor degree-elevated.
BernsteinPolynomial elevated_on_segments(const BernsteinPolynomial& p, int degree);

/// Bernstein form of det J (derivatives with respect to Gmsh's reference coordinates).
/// Domain variables: tet (xi, eta, zeta) as barycentric lambda_1..3; prism (xi, eta) on the
/// triangle, t = (zeta+1)/2; hex t_k = (xi_k+1)/2; pyramid t_a = (a+1)/2, t_b = (b+1)/2, c.
/// element_nodes: (num_nodes(shape, order), 3), canonical order, positions of `set`.
/// Throws std::invalid_argument for a 2D shape, an order outside 1..kMaxOrder or a wrong node count.
/// The products chained in the scaled basis with reused buffers (ScaledProduct).
BernsteinPolynomial jacobian_determinant(Shape shape, int order, NodeSet set, const Eigen::MatrixX3d& element_nodes);

/// The same polynomial formed as written, det J = w . (u x v) over BernsteinPolynomial's derivative,
/// division and products: the slow, obviously right reference jacobian_determinant is tested
/// against (equal to rounding).
BernsteinPolynomial jacobian_determinant_by_products(Shape shape, int order, NodeSet set,
                                                     const Eigen::MatrixX3d& element_nodes);

/// The point of the Bernstein domain (see above) of a reference point; for the pyramid apex the
/// collapsed (a, b) is taken as (0, 0).
Eigen::Vector3d bernstein_domain_point(Shape shape, const Eigen::Vector3d& reference_point);

}  // namespace semimesh::ho::detail
