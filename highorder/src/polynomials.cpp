#include "polynomials.hpp"

#include <cmath>
#include <mutex>
#include <stdexcept>
#include <string>

namespace semimesh::ho::detail {

// Three-term recurrence of P_n^{(a,0)} (Abramowitz & Stegun 22.7.1 with beta = 0), multiplied through
// by t^{n+1} so that it runs on the homogeneous form Q_n(X, t).
void scaled_jacobi(int n, double alpha, double X, double t, ScaledJacobi& out) {
  out.value.assign(n + 1, 0.0);
  out.d_dX.assign(n + 1, 0.0);
  out.d_dt.assign(n + 1, 0.0);
  out.value[0] = 1.0;
  if (n == 0) return;
  const double a = alpha;
  out.value[1] = 0.5 * ((a + 2.0) * X + a * t);
  out.d_dX[1] = 0.5 * (a + 2.0);
  out.d_dt[1] = 0.5 * a;
  for (int k = 1; k < n; ++k) {
    const double s = 2.0 * k + a;
    const double denominator = 2.0 * (k + 1) * (k + a + 1) * s;
    const double c1 = (s + 1.0) / denominator;
    const double linear_X = (s + 2.0) * s;
    const double linear_t = a * a;
    const double c2 = 2.0 * k * (k + a) * (s + 2.0) / denominator;
    const double lin = linear_X * X + linear_t * t;
    out.value[k + 1] = c1 * lin * out.value[k] - c2 * t * t * out.value[k - 1];
    out.d_dX[k + 1] = c1 * (linear_X * out.value[k] + lin * out.d_dX[k]) - c2 * t * t * out.d_dX[k - 1];
    out.d_dt[k + 1] = c1 * (linear_t * out.value[k] + lin * out.d_dt[k]) -
                      c2 * (2.0 * t * out.value[k - 1] + t * t * out.d_dt[k - 1]);
  }
}

namespace {

// Legendre P_n(x) and P_{n-1}(x).
void legendre_pair(int n, double x, double& pn, double& pn_minus_1) {
  double previous = 1.0, current = x;
  for (int k = 1; k < n; ++k) {
    const double next = ((2.0 * k + 1.0) * x * current - k * previous) / (k + 1.0);
    previous = current;
    current = next;
  }
  pn = current;
  pn_minus_1 = previous;
}

// GLL points are the roots of q(x) = (1 - x^2) P_n'(x); Newton on q with q'(x) = -n(n+1) P_n(x),
// started from the Chebyshev-Gauss-Lobatto points.
std::vector<double> compute_gll_points(int n) {
  std::vector<double> points(n + 1);
  points[0] = -1.0;
  points[n] = 1.0;
  const double pi = std::acos(-1.0);
  for (int i = 1; i < n; ++i) {
    double x = -std::cos(pi * i / n);
    for (int iteration = 0; iteration < 100; ++iteration) {
      double pn = 0.0, pm = 0.0;
      legendre_pair(n, x, pn, pm);
      const double q = n * (pm - x * pn);  // (1 - x^2) P_n'(x)
      const double step = q / (-n * (n + 1.0) * pn);
      x -= step;
      if (std::abs(step) < 1e-16) break;
    }
    points[i] = x;
  }
  for (int i = 0; i <= n / 2; ++i) {  // exact symmetry about 0
    const double half = 0.5 * (points[n - i] - points[i]);
    points[i] = -half;
    points[n - i] = half;
  }
  if (n % 2 == 0) points[n / 2] = 0.0;
  return points;
}

}  // namespace

const std::vector<double>& gll_points(int order) {
  constexpr int kCachedOrders = 64;
  if (order < 1 || order >= kCachedOrders) {
    throw std::invalid_argument("gll_points: order must be in [1, 63], got " + std::to_string(order));
  }
  static std::vector<double> cache[kCachedOrders];
  static std::once_flag flags[kCachedOrders];
  std::call_once(flags[order], [order] { cache[order] = compute_gll_points(order); });
  return cache[order];
}

}  // namespace semimesh::ho::detail
