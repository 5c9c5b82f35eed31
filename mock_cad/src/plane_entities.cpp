#include "plane_entities.hpp"

#include <algorithm>

namespace semimesh::mock_cad::detail {

LineCurve::LineCurve(int id, std::string name, const Vec3& a, const Vec3& b, Interval range)
    : cad::Curve(id, std::move(name)), a_(a), range_(range), velocity_((b - a) / range.length()) {}

CurveDerivatives LineCurve::derivatives(double t) const { return CurveDerivatives{point(t), velocity_, Vec3::Zero()}; }

CurveProjection LineCurve::project(const Vec3& x, std::optional<double>) const {
  CurveProjection out;
  out.t = range_.clamp(range_.lo + (x - a_).dot(velocity_) / velocity_.squaredNorm());
  out.point = point(out.t);
  out.distance = (out.point - x).norm();
  out.converged = true;
  return out;
}

double LineCurve::parameter_at_length(double t_start, double s) const {
  return range_.clamp(t_start + s / velocity_.norm());
}

PlaneFace::PlaneFace(int id, std::string name, int orientation, const Vec3& origin, const Vec3& e1, const Vec3& e2,
                     std::array<Interval, 2> box, double tol, std::optional<SectionTrim> trim,
                     std::optional<DiscHole> hole)
    : cad::Surface(id, std::move(name), orientation),
      origin_(origin),
      e1_(e1),
      e2_(e2),
      box_(box),
      tol_(tol),
      trim_(std::move(trim)),
      hole_(hole) {}

SurfaceDerivatives PlaneFace::derivatives(const Vec2& uv) const {
  return SurfaceDerivatives{point(uv), e1_, e2_, Vec3::Zero(), Vec3::Zero(), Vec3::Zero()};
}

bool PlaneFace::contains(const Vec2& uv) const {
  if (!box_[0].contains(uv.x(), tol_) || !box_[1].contains(uv.y(), tol_)) return false;
  if (hole_ && (uv - hole_->centre).norm() < hole_->radius - tol_) return false;
  if (!trim_) return true;
  const NacaWing& wing = *trim_->wing;
  const double chord = wing.chord_at(trim_->level);
  const OutlineSide side = wing.section().classify(wing.to_section(point(uv), trim_->level), tol_ / chord);
  if (side == OutlineSide::OnBoundary) return true;
  return (side == OutlineSide::Inside) == trim_->keep_inside;
}

SurfaceProjection PlaneFace::project(const Vec3& x, std::optional<Vec2>) const {
  const Vec3 r = x - origin_;
  SurfaceProjection out;
  out.uv = Vec2(box_[0].clamp(r.dot(e1_)), box_[1].clamp(r.dot(e2_)));
  out.point = point(out.uv);
  out.distance = (out.point - x).norm();
  out.converged = true;
  out.inside = contains(out.uv);
  return out;
}

}  // namespace semimesh::mock_cad::detail
