#include "wing_entities.hpp"

#include "newton_projection.hpp"

#include <algorithm>

namespace semimesh::mock_cad::detail {
namespace {
constexpr double kNoCrease = -1.0;  // outside every parameter range
}  // namespace

WingSkin::WingSkin(int id, std::string name, std::shared_ptr<const NacaWing> wing, Side side, double tol)
    : cad::Surface(id, std::move(name), side == Side::Upper ? -1 : +1), wing_(std::move(wing)), side_(side), tol_(tol) {}

bool WingSkin::contains(const Vec2& uv) const {
  const auto box = bounds();
  return box[0].contains(uv.x(), tol_) && box[1].contains(uv.y(), tol_);
}

SurfaceProjection WingSkin::project(const Vec3& x, std::optional<Vec2> guess) const {
  const auto box = bounds();
  auto solve = [&](const Vec2& start) {
    return newton_project_surface([this](const Vec2& uv) { return wing_->eval(side_, uv.x(), uv.y()); },
                                  [this](const Vec2& uv) { return wing_->point(side_, uv.x(), uv.y()); }, x, start, box, tol_,
                                  wing_->root_chord(), wing_->section().crease_u());
  };
  SurfaceProjection best = solve(guess ? *guess : wing_->initial_guess(side_, x));
  // Deeper on the solid side of the skin than half the leading-edge radius (its smallest radius
  // of curvature), the distance can have several local minima: without a caller's guess, also
  // start from the other candidates and both edges, and keep the closest. Points on the fluid
  // side or near the skin (the usual case) pay nothing.
  if (!guess && best.distance > 0.5 * wing_->leading_edge_radius(best.uv.y()) &&
      (x - best.point).dot(normal(best.uv)) < 0.0) {
    const double v = box[1].clamp(x.z());
    const auto starts = wing_->start_candidates(side_, wing_->to_section(x, v));
    for (double u : {starts[0], starts[1], 0.0, 1.0}) {
      SurfaceProjection other = solve(Vec2(u, v));
      if (other.distance < best.distance) best = other;
    }
  }
  best.inside = contains(best.uv);
  return best;
}

TrailingEdgeBase::TrailingEdgeBase(int id, std::string name, std::shared_ptr<const NacaWing> wing, double tol)
    : cad::Surface(id, std::move(name), +1), wing_(std::move(wing)), tol_(tol) {}

SurfaceDerivatives TrailingEdgeBase::derivatives(const Vec2& uv) const {
  const double s = uv.x(), v = uv.y();
  const SurfaceDerivatives lower = wing_->eval(Side::Lower, 1.0, v), upper = wing_->eval(Side::Upper, 1.0, v);
  SurfaceDerivatives d;
  d.p = lower.p + s * (upper.p - lower.p);
  d.du = upper.p - lower.p;
  d.dv = lower.dv + s * (upper.dv - lower.dv);
  d.duu = Vec3::Zero();
  d.duv = upper.dv - lower.dv;
  d.dvv = Vec3::Zero();  // the trailing-edge lines are straight
  return d;
}

Vec3 TrailingEdgeBase::point(const Vec2& uv) const {
  const Vec3 lower = wing_->point(Side::Lower, 1.0, uv.y()), upper = wing_->point(Side::Upper, 1.0, uv.y());
  return lower + uv.x() * (upper - lower);
}

bool TrailingEdgeBase::contains(const Vec2& uv) const {
  const auto box = bounds();
  return box[0].contains(uv.x(), tol_) && box[1].contains(uv.y(), tol_);
}

SurfaceProjection TrailingEdgeBase::project(const Vec3& x, std::optional<Vec2> guess) const {
  Vec2 start;
  if (guess) {
    start = *guess;
  } else {  // foot on the ruling at v = z: exact when the planform is untapered
    const double v = std::clamp(x.z(), 0.0, wing_->span());
    const Vec3 lower = wing_->point(Side::Lower, 1.0, v), across = wing_->point(Side::Upper, 1.0, v) - lower;
    start = Vec2(std::clamp((x - lower).dot(across) / across.squaredNorm(), 0.0, 1.0), v);
  }
  SurfaceProjection out = newton_project_surface([this](const Vec2& uv) { return derivatives(uv); },
                                                 [this](const Vec2& uv) { return point(uv); }, x, start, bounds(), tol_,
                                                 wing_->root_chord(), kNoCrease);
  out.inside = contains(out.uv);
  return out;
}

SectionCurve::SectionCurve(int id, std::string name, std::shared_ptr<const NacaWing> wing, Side side, double v, double tol)
    : cad::Curve(id, std::move(name)), wing_(std::move(wing)), side_(side), v_(v), tol_(tol) {}

CurveDerivatives SectionCurve::derivatives(double t) const {
  const SurfaceDerivatives d = wing_->eval(side_, t, v_);
  return CurveDerivatives{d.p, d.du, d.duu};
}

CurveProjection SectionCurve::project(const Vec3& x, std::optional<double> guess) const {
  const double start = guess ? *guess : wing_->initial_u(side_, wing_->to_section(x, v_));
  return newton_project_curve([this](double t) { return derivatives(t); }, [this](double t) { return point(t); }, x,
                              start, bounds(), tol_, wing_->root_chord(), wing_->section().crease_u());
}

}  // namespace semimesh::mock_cad::detail
