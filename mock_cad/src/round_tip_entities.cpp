#include "round_tip_entities.hpp"
#include "constants.hpp"

#include "newton_projection.hpp"

#include <algorithm>
#include <cmath>

namespace semimesh::mock_cad::detail {

RoundTipFace::RoundTipFace(int id, std::string name, std::shared_ptr<const RoundTipMap> tip, double tol)
    : cad::Surface(id, std::move(name), -1), tip_(std::move(tip)), tol_(tol) {}

std::array<cad::Interval, 2> RoundTipFace::bounds() const { return {cad::Interval{0.0, 1.0}, cad::Interval{0.0, kPi}}; }

bool RoundTipFace::contains(const Vec2& uv) const {
  const auto box = bounds();
  return box[0].contains(uv.x(), tol_) && box[1].contains(uv.y(), tol_);
}

Vec2 RoundTipFace::initial_guess(const cad::Vec3& x) const {
  const NacaWing& w = tip_->wing();
  const double span = w.span(), c = w.chord_at(span), height = x.z() - span;
  // Undo the tilt along W (round_tip.hpp) at the chordwise station of x, then read u off the
  // station and phi off the angle about the camber line.
  const double u0 = std::sqrt(std::clamp(w.to_section(x, span).x(), 0.0, 1.0));
  const cad::Vec3 level = x - height * cad::Vec3(w.tan_sweep() + w.chord_slope() * u0 * u0, 0.0, 1.0);
  const Vec2 q = w.to_section(level, span);
  const double u = std::sqrt(std::clamp(q.x(), 0.0, 1.0));
  const Vec2 up = w.section().point(Side::Upper, u), lo = w.section().point(Side::Lower, u);
  const Vec2 gap = up - lo, normal = gap.norm() > 0.0 ? Vec2(gap.normalized()) : Vec2(0.0, 1.0);
  const double across = (q - 0.5 * (up + lo)).dot(normal);
  double phi = std::atan2(height / c, across);
  if (phi < 0.0) phi = across >= 0.0 ? 0.0 : kPi;  // below the tip plane: on the nearer side
  return Vec2(u, phi);
}

cad::SurfaceProjection RoundTipFace::solve(const cad::Vec3& x, const Vec2& start) const {
  const double chord = tip_->wing().root_chord(), crease = tip_->wing().section().crease_u();
  auto newton = [&](const Vec2& from) {
    return newton_project_surface([this](const Vec2& uv) { return tip_->eval(uv.x(), uv.y()); },
                                  [this](const Vec2& uv) { return tip_->point(uv.x(), uv.y()); }, x, from, bounds(), tol_,
                                  chord, crease);
  };
  return cad::leave_pole(*this, newton(start), newton);
}

cad::SurfaceProjection RoundTipFace::project(const cad::Vec3& x, std::optional<Vec2> guess) const {
  cad::SurfaceProjection best = solve(x, guess ? *guess : initial_guess(x));
  // On the solid side of the tip, deeper than its curvature, the distance can have several local
  // minima: without a caller's guess, also start from a grid and keep the closest. Points on the
  // fluid side or near the tip (the usual case) pay nothing.
  if (!guess && (!best.converged || (x - best.point).dot(normal(best.uv)) < -tol_)) {
    for (double u : {0.1, 0.3, 0.5, 0.7, 0.9})
      for (double phi : {kPi / 6.0, kPi / 2.0, 5.0 * kPi / 6.0}) {
        const cad::SurfaceProjection other = solve(x, Vec2(u, phi));
        if (other.distance < best.distance) best = other;
      }
  }
  best.inside = contains(best.uv);
  return best;
}

TipArc::TipArc(int id, std::string name, std::shared_ptr<const RoundTipMap> tip, double tol)
    : cad::Curve(id, std::move(name)), tip_(std::move(tip)), tol_(tol) {}

cad::Interval TipArc::bounds() const { return {0.0, kPi}; }

cad::CurveDerivatives TipArc::derivatives(double t) const {
  const cad::SurfaceDerivatives d = tip_->eval(1.0, kPi - t);
  return {d.p, -d.dv, d.dvv};
}

cad::CurveProjection TipArc::project(const cad::Vec3& x, std::optional<double> guess) const {
  double start = 0.0;
  if (guess) {
    start = *guess;
  } else {
    constexpr int kSamples = 16;
    double nearest = 1e300;
    for (int k = 0; k <= kSamples; ++k) {
      const double t = kPi * k / kSamples, d = (point(t) - x).squaredNorm();
      if (d < nearest) nearest = d, start = t;
    }
  }
  return newton_project_curve([this](double t) { return derivatives(t); }, [this](double t) { return point(t); }, x,
                              start, bounds(), tol_, tip_->wing().root_chord(), kNoCrease);
}

CappedTrailingEdgeBase::CappedTrailingEdgeBase(int id, std::string name, std::shared_ptr<const RoundTipMap> tip, double tol)
    : cad::Surface(id, std::move(name), +1),
      tip_(std::move(tip)),
      tol_(tol),
      origin_(tip_->base_origin()),
      across_(tip_->base_across()),
      along_(tip_->base_along()),
      half_width_root_(tip_->wing().chord_at(0.0) * tip_->trailing_edge_half_thickness()),
      half_width_tip_(tip_->wing().chord_at(tip_->wing().span()) * tip_->trailing_edge_half_thickness()),
      span_(tip_->wing().span()) {}

std::array<cad::Interval, 2> CappedTrailingEdgeBase::bounds() const {
  const double a = std::max(half_width_root_, half_width_tip_);
  return {cad::Interval{-a, a}, cad::Interval{0.0, span_ + half_width_tip_}};
}

cad::SurfaceDerivatives CappedTrailingEdgeBase::derivatives(const Vec2& ab) const {
  const cad::Vec3 zero = cad::Vec3::Zero();
  return {origin_ + ab.x() * across_ + ab.y() * along_, across_, along_, zero, zero, zero};
}

bool CappedTrailingEdgeBase::contains(const Vec2& ab) const {
  const auto box = bounds();
  if (!box[0].contains(ab.x(), tol_) || !box[1].contains(ab.y(), tol_)) return false;
  const double a = ab.x(), b = ab.y();
  if (b <= span_) {
    const double t = std::clamp(b / span_, 0.0, 1.0);
    return std::abs(a) <= half_width_root_ + t * (half_width_tip_ - half_width_root_) + tol_;
  }
  return std::hypot(a, b - span_) <= half_width_tip_ + tol_;
}

cad::SurfaceProjection CappedTrailingEdgeBase::project(const cad::Vec3& x, std::optional<Vec2>) const {
  const cad::Vec3 r = x - origin_;
  const double g11 = across_.squaredNorm(), g12 = across_.dot(along_), g22 = along_.squaredNorm();
  const double r1 = r.dot(across_), r2 = r.dot(along_), det = g11 * g22 - g12 * g12;
  const Vec2 foot((g22 * r1 - g12 * r2) / det, (g11 * r2 - g12 * r1) / det);
  cad::SurfaceProjection out = newton_project_surface([this](const Vec2& ab) { return derivatives(ab); },
                                                      [this](const Vec2& ab) { return derivatives(ab).p; }, x, foot,
                                                      bounds(), tol_, tip_->wing().root_chord(), kNoCrease);
  out.inside = contains(out.uv);
  return out;
}

}  // namespace semimesh::mock_cad::detail
