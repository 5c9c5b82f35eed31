#include "semimesh/cad/curve.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace semimesh::cad {
namespace {

// 7-point Gauss-Legendre nodes/weights on [-1, 1] (Abramowitz & Stegun, table 25.4).
constexpr double kGaussX[7] = {0.0, 0.4058451513773972, -0.4058451513773972, 0.7415311855993945,
                               -0.7415311855993945, 0.9491079123427585, -0.9491079123427585};
constexpr double kGaussW[7] = {0.4179591836734694, 0.3818300505051189, 0.3818300505051189, 0.2797053914892767,
                               0.2797053914892767, 0.1294849661688697, 0.1294849661688697};

double speed_integral(const Curve& c, double a, double b) {
  double mid = 0.5 * (a + b), half = 0.5 * (b - a), sum = 0.0;
  for (int i = 0; i < 7; ++i) sum += kGaussW[i] * c.derivatives(mid + half * kGaussX[i]).d1.norm();
  return sum * half;
}

// Adaptive: split until the two halves agree with the whole to a relative tolerance.
double adaptive_length(const Curve& c, double a, double b, double whole, int depth) {
  double m = 0.5 * (a + b);
  double left = speed_integral(c, a, m), right = speed_integral(c, m, b);
  if (depth >= 20 || std::abs(left + right - whole) <= 1e-12 * std::max(1.0, std::abs(whole))) return left + right;
  return adaptive_length(c, a, m, left, depth + 1) + adaptive_length(c, m, b, right, depth + 1);
}

}  // namespace

const std::vector<double>& Curve::tangent_breaks() const {
  static const std::vector<double> none;
  return none;
}

double Curve::arc_length(double a, double b) const {
  if (a == b) return 0.0;
  if (b < a) return -arc_length(b, a);
  // Smooth pieces between the tangent's breaks inside (a, b).
  const std::vector<double>& breaks = tangent_breaks();
  double length = 0.0, from = a;
  for (auto k = std::upper_bound(breaks.begin(), breaks.end(), a); k != breaks.end() && *k < b; ++k) {
    length += adaptive_length(*this, from, *k, speed_integral(*this, from, *k), 0);
    from = *k;
  }
  return length + adaptive_length(*this, from, b, speed_integral(*this, from, b), 0);
}

double Curve::parameter_at_length(double t_start, double s) const {
  const Interval range = bounds();
  // Bracket the answer on [lo, hi] where g(t) = arc_length(t_start, t) - s is increasing.
  double lo = range.lo, hi = range.hi;
  if (s >= arc_length(t_start, hi)) return hi;
  if (s <= arc_length(t_start, lo)) return lo;
  double t = range.clamp(t_start + s / std::max(derivatives(t_start).d1.norm(), 1e-300));
  for (int it = 0; it < 100; ++it) {
    double g = arc_length(t_start, t) - s;
    if (g > 0) hi = t; else lo = t;
    if (std::abs(g) <= 1e-13 * std::max(1.0, std::abs(s))) return t;
    double speed = derivatives(t).d1.norm();
    double next = speed > 0 ? t - g / speed : 0.5 * (lo + hi);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);  // Newton left the bracket: bisect
    if (std::abs(next - t) <= 1e-15 * std::max(1.0, std::abs(t))) return next;
    t = next;
  }
  return t;
}

double Curve::curvature(double t) const {
  CurveDerivatives d = derivatives(t);
  double speed = d.d1.norm();
  if (speed == 0.0) return 0.0;
  return d.d1.cross(d.d2).norm() / (speed * speed * speed);
}

Vec3 Curve::tangent(double t) const { return derivatives(t).d1.normalized(); }

CurveProjection Curve::project(const Vec3& x, std::optional<double> guess) const {
  const Interval range = bounds();
  double t;
  if (guess) {
    t = range.clamp(*guess);
  } else {
    constexpr int kSamples = 64;
    double best = std::numeric_limits<double>::max();
    t = range.lo;
    for (int i = 0; i <= kSamples; ++i) {
      double ti = range.lo + range.length() * i / kSamples;
      double d = (point(ti) - x).squaredNorm();
      if (d < best) { best = d; t = ti; }
    }
  }
  // Newton on f(t) = C'(t).(C(t) - x) = 0, clamped to the range.
  bool converged = false;
  for (int it = 0; it < 50; ++it) {
    CurveDerivatives d = derivatives(t);
    Vec3 r = d.p - x;
    double f = d.d1.dot(r);
    double fp = d.d1.squaredNorm() + d.d2.dot(r);
    if (fp <= 0) fp = d.d1.squaredNorm();  // Gauss-Newton where the full Hessian is not positive
    if (fp == 0) break;
    double next = range.clamp(t - f / fp);
    double step = std::abs(next - t);
    t = next;
    if (step <= 1e-14 * std::max(1.0, range.length())) { converged = true; break; }
    if (std::abs(f) <= 1e-15 * std::max(1.0, d.d1.squaredNorm())) { converged = true; break; }
  }
  CurveProjection out;
  out.t = t;
  out.point = point(t);
  out.distance = (out.point - x).norm();
  out.converged = converged;
  return out;
}

}  // namespace semimesh::cad
