// Closest-point solvers shared by the analytic entities: Newton on f = |S - x|^2 / 2 with the
// exact Hessian, Gauss-Newton where that Hessian is not positive definite (x beyond a centre of
// curvature), an active set for parameters held on a bound, and a halving line search on long
// steps so the distance does not grow. Templates over the evaluators so the hot loop inlines and
// allocates nothing.
#pragma once

#include "semimesh/cad/types.hpp"

#include <array>
#include <cmath>

namespace semimesh::mock_cad::detail {

constexpr int kNewtonIterations = 60;
constexpr int kLineSearchHalvings = 40;

// Increase of |S - x|^2 a step may cause and still be taken: the round-off of the squared distance.
// Near the foot Newton lowers f by only (tangential residual)^2, below that noise, so a strict
// decrease test would stall the solver at a residual of about sqrt(eps |x| |S - x|).
inline double distance_noise(double f0, const cad::Vec3& x) { return 1e-14 * (std::sqrt(f0) + 1e-3) * (x.norm() + 1.0); }

// Step lengths, relative to the model's length scale: below kFinalStep a full Newton step ends
// the solve (quadratic convergence leaves a residual ~ curvature * step^2, far below the
// tolerance), below kTrustedStep no line search is needed.
constexpr double kFinalStep = 1e-8;
constexpr double kTrustedStep = 1e-3;

/// Newton from `uv` (clamped to `box`). Converged when, for every parameter not held on a bound,
/// the residual's component along that tangent is below `tol` (a length). `scale` is the model's
/// length scale (the chord). `crease_u`: a u where S is continuous but its u-derivatives jump
/// (any value outside box[0] for none); eval() there must return the right-hand limits. The
/// solver works on one side of the crease at a time and stops on it when both sides descend
/// towards it. `inside` is left false.
/// `eval(uv)` -> SurfaceDerivatives, `point(uv)` -> Vec3.
template <class Eval, class Point>
cad::SurfaceProjection newton_project_surface(const Eval& eval, const Point& point, const cad::Vec3& x,
                                              cad::Vec2 uv, const std::array<cad::Interval, 2>& box, double tol,
                                              double scale, double crease_u) {
  const bool has_crease = box[0].lo < crease_u && crease_u < box[0].hi;
  uv = cad::Vec2(box[0].clamp(uv.x()), box[1].clamp(uv.y()));
  bool converged = false;
  for (int it = 0; it < kNewtonIterations; ++it) {
    cad::SurfaceDerivatives d = eval(uv);
    // The part of the u-range this iteration stays on.
    cad::Interval range_u = box[0];
    if (has_crease) {
      if (uv.x() < crease_u) {
        range_u.hi = crease_u;
      } else if (uv.x() > crease_u) {
        range_u.lo = crease_u;
      } else if (d.du.dot(d.p - x) < 0.0) {
        range_u.lo = crease_u;  // descending to the right
      } else {
        const cad::SurfaceDerivatives left = eval(cad::Vec2(std::nextafter(crease_u, box[0].lo), uv.y()));
        if (left.du.dot(left.p - x) > 0.0) {
          range_u.hi = crease_u;  // descending to the left
          d = left;
        } else {
          range_u = cad::Interval{crease_u, crease_u};  // a minimum on the crease
        }
      }
    }
    auto clamp = [&](const cad::Vec2& p) { return cad::Vec2(range_u.clamp(p.x()), box[1].clamp(p.y())); };
    const cad::Vec3 r = d.p - x;
    const double gu = d.du.dot(r), gv = d.dv.dot(r);
    const double suu = d.du.squaredNorm(), suv = d.du.dot(d.dv), svv = d.dv.squaredNorm();
    // A parameter on its bound whose descent direction leaves the box stays on the bound.
    const bool hold_u = (uv.x() <= range_u.lo && gu > 0.0) || (uv.x() >= range_u.hi && gu < 0.0);
    const bool hold_v = (uv.y() <= box[1].lo && gv > 0.0) || (uv.y() >= box[1].hi && gv < 0.0);
    const bool done_u = hold_u || gu * gu <= tol * tol * suu;
    const bool done_v = hold_v || gv * gv <= tol * tol * svv;
    if (done_u && done_v) { converged = true; break; }

    const double huu = suu + d.duu.dot(r), huv = suv + d.duv.dot(r), hvv = svv + d.dvv.dot(r);
    cad::Vec2 step(0.0, 0.0);
    bool exact_hessian = true;
    if (hold_u) {
      exact_hessian = hvv > 0.0;
      step.y() = -gv / (exact_hessian ? hvv : svv);
    } else if (hold_v) {
      exact_hessian = huu > 0.0;
      step.x() = -gu / (exact_hessian ? huu : suu);
    } else {
      double a = huu, b = huv, c = hvv;
      if (!(a > 0.0 && a * c - b * b > 0.0)) { a = suu; b = suv; c = svv; exact_hessian = false; }
      const double det = a * c - b * b;
      if (!(det > 0.0)) break;  // degenerate tangent plane
      step = cad::Vec2(-(c * gu - b * gv) / det, -(a * gv - b * gu) / det);
    }
    const double length = std::abs(step.x()) * std::sqrt(suu) + std::abs(step.y()) * std::sqrt(svv);
    cad::Vec2 next = clamp(uv + step);
    if (exact_hessian && length <= kFinalStep * scale && next == uv + step) {
      uv = next;
      converged = true;
      break;
    }
    if (length > kTrustedStep * scale) {
      const double f_max = r.squaredNorm() + distance_noise(r.squaredNorm(), x);
      for (int ls = 0; ls < kLineSearchHalvings && (point(next) - x).squaredNorm() > f_max; ++ls) next = clamp(uv + (step *= 0.5));
    }
    if (next == uv) break;  // no progress possible in floating point
    uv = next;
  }
  cad::SurfaceProjection out;
  out.uv = uv;
  out.point = point(uv);
  out.distance = (out.point - x).norm();
  out.converged = converged;
  return out;
}

/// The same on a curve, with an optional crease at t = crease_t: `eval(t)` -> CurveDerivatives,
/// `point(t)` -> Vec3.
template <class Eval, class Point>
cad::CurveProjection newton_project_curve(const Eval& eval, const Point& point, const cad::Vec3& x, double t,
                                          const cad::Interval& full_range, double tol, double scale, double crease_t) {
  const bool has_crease = full_range.lo < crease_t && crease_t < full_range.hi;
  t = full_range.clamp(t);
  bool converged = false;
  for (int it = 0; it < kNewtonIterations; ++it) {
    cad::CurveDerivatives d = eval(t);
    cad::Interval range = full_range;
    if (has_crease) {
      if (t < crease_t) {
        range.hi = crease_t;
      } else if (t > crease_t) {
        range.lo = crease_t;
      } else if (d.d1.dot(d.p - x) < 0.0) {
        range.lo = crease_t;
      } else {
        const cad::CurveDerivatives left = eval(std::nextafter(crease_t, full_range.lo));
        if (left.d1.dot(left.p - x) > 0.0) {
          range.hi = crease_t;
          d = left;
        } else {
          range = cad::Interval{crease_t, crease_t};
        }
      }
    }
    const cad::Vec3 r = d.p - x;
    const double g = d.d1.dot(r), s = d.d1.squaredNorm();
    const bool hold = (t <= range.lo && g > 0.0) || (t >= range.hi && g < 0.0);
    if (hold || g * g <= tol * tol * s) { converged = true; break; }
    double h = s + d.d2.dot(r);
    const bool exact_hessian = h > 0.0;
    if (!exact_hessian) h = s;
    if (!(h > 0.0)) break;  // singular point
    double step = -g / h;
    const double length = std::abs(step) * std::sqrt(s);
    double next = range.clamp(t + step);
    if (exact_hessian && length <= kFinalStep * scale && next == t + step) {
      t = next;
      converged = true;
      break;
    }
    if (length > kTrustedStep * scale) {
      const double f_max = r.squaredNorm() + distance_noise(r.squaredNorm(), x);
      for (int ls = 0; ls < kLineSearchHalvings && (point(next) - x).squaredNorm() > f_max; ++ls) next = range.clamp(t + (step *= 0.5));
    }
    if (next == t) break;
    t = next;
  }
  cad::CurveProjection out;
  out.t = t;
  out.point = point(t);
  out.distance = (out.point - x).norm();
  out.converged = converged;
  return out;
}

}  // namespace semimesh::mock_cad::detail
