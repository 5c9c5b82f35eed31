// One-dimensional polynomial building blocks shared by node sets and modal bases (internal).
#pragma once

#include <vector>

namespace semimesh::ho::detail {

/// Scaled Jacobi polynomials Q_k(X, t) = t^k P_k^{(alpha,0)}(X / t), k = 0..n, and their partial
/// derivatives. They are polynomials in (X, t), so collapsed-coordinate bases built from them have no
/// singular vertex. With t = 1 they are the ordinary Jacobi polynomials P_k^{(alpha,0)}(X).
struct ScaledJacobi {
  std::vector<double> value;  // (n+1)
  std::vector<double> d_dX;   // (n+1)
  std::vector<double> d_dt;   // (n+1)
};
void scaled_jacobi(int n, double alpha, double X, double t, ScaledJacobi& out);

/// The order+1 Gauss-Lobatto-Legendre points on [-1, 1] in ascending order (order >= 1).
const std::vector<double>& gll_points(int order);

}  // namespace semimesh::ho::detail
