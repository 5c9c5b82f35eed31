#include "wing_entities.hpp"
#include "constants.hpp"

#include "newton_projection.hpp"

#include <algorithm>

namespace semimesh::mock_cad::detail {

WingSkin::WingSkin(int id, std::string name, std::shared_ptr<const NacaWing> wing, Side side, double tol,
                   std::shared_ptr<const FuselageRoot> root)
    : cad::Surface(id, std::move(name), side == Side::Upper ? -1 : +1),
      wing_(std::move(wing)),
      side_(side),
      tol_(tol),
      root_(std::move(root)) {}

bool WingSkin::contains(const Vec2& uv) const {
  const auto box = bounds();
  return box[0].contains(uv.x(), tol_) && box[1].contains(uv.y(), tol_);
}

double WingSkin::v_at(double u, double z) const {
  const Interval along = bounds()[1];
  return along.clamp(root_ ? root_->v_at(root_->root_height(part(), u).f, z) : z);
}

SurfaceProjection WingSkin::project(const Vec3& x, std::optional<Vec2> guess) const {
  const auto box = bounds();
  auto solve = [&](const Vec2& start) {
    return newton_project_surface([this](const Vec2& uv) { return derivatives(uv); },
                                  [this](const Vec2& uv) { return point(uv); }, x, start, box, tol_,
                                  wing_->root_chord(), wing_->section().crease_u());
  };
  Vec2 start = guess ? *guess : wing_->initial_guess(side_, x);
  if (!guess && root_) start.y() = v_at(start.x(), x.z());
  SurfaceProjection best = solve(start);
  // Deeper on the solid side of the skin than half the leading-edge radius (its smallest radius
  // of curvature), the distance can have several local minima: without a caller's guess, also
  // start from the other candidates and both edges, and keep the closest. Points on the fluid
  // side or near the skin (the usual case) pay nothing.
  if (!guess && best.distance > 0.5 * wing_->leading_edge_radius(best.uv.y()) &&
      (x - best.point).dot(normal(best.uv)) < 0.0) {
    const auto starts = wing_->start_candidates(side_, wing_->to_section(x, box[1].clamp(x.z())));
    for (double u : {starts[0], starts[1], 0.0, 1.0}) {
      SurfaceProjection other = solve(Vec2(u, v_at(u, x.z())));
      if (other.distance < best.distance) best = other;
    }
  }
  best.inside = contains(best.uv);
  return best;
}

TrailingEdgeBase::TrailingEdgeBase(int id, std::string name, std::shared_ptr<const NacaWing> wing, double tol,
                                   std::shared_ptr<const FuselageRoot> root)
    : cad::Surface(id, std::move(name), +1), wing_(std::move(wing)), tol_(tol), root_(std::move(root)) {}

SurfaceDerivatives TrailingEdgeBase::derivatives(const Vec2& uv) const {
  if (root_) return root_->eval(RootPart::Base, uv.x(), uv.y());
  return wing_->eval_base(uv.x(), uv.y());
}

Vec3 TrailingEdgeBase::point(const Vec2& uv) const {
  if (root_) return root_->point(RootPart::Base, uv.x(), uv.y());
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
    if (root_) start.y() = bounds()[1].clamp(root_->v_at(root_->root_height(RootPart::Base, start.x()).f, x.z()));
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

RootCurve::RootCurve(int id, std::string name, std::shared_ptr<const FuselageRoot> root, RootPart part, double tol)
    : cad::Curve(id, std::move(name)), root_(std::move(root)), part_(part), tol_(tol) {}

CurveDerivatives RootCurve::derivatives(double t) const {
  const SurfaceDerivatives d = root_->eval(part_, t, 0.0);
  return CurveDerivatives{d.p, d.du, d.duu};
}

CurveProjection RootCurve::project(const Vec3& x, std::optional<double> guess) const {
  const NacaWing& wing = root_->wing();
  double start = 0.0, crease = kNoCrease;
  if (guess) {
    start = *guess;
  } else if (part_ == RootPart::Base) {  // the foot on the trailing-edge segment at z = 0
    const Vec3 lower = wing.point(Side::Lower, 1.0, 0.0), across = wing.point(Side::Upper, 1.0, 0.0) - lower;
    start = (x - lower).dot(across) / across.squaredNorm();
  } else {
    start = wing.initial_u(part_ == RootPart::Upper ? Side::Upper : Side::Lower, wing.to_section(x, 0.0));
  }
  if (part_ != RootPart::Base) crease = wing.section().crease_u();
  return newton_project_curve([this](double t) { return derivatives(t); }, [this](double t) { return point(t); }, x,
                              start, bounds(), tol_, wing.root_chord(), crease);
}

}  // namespace semimesh::mock_cad::detail
