#include "fuselage_wall.hpp"
#include "constants.hpp"

#include <algorithm>
#include <cmath>

namespace semimesh::mock_cad::detail {
namespace {

// The point at angle phi on the circle of radius r about the axis at depth R, at station x.
cad::Vec3 on_circle(double x, double phi, double r, double R) {
  return cad::Vec3(x, -r * std::sin(phi), -R - r * std::cos(phi));
}

}  // namespace

double fuselage_angle(const cad::Vec3& x, double axis_depth, std::optional<double> near) {
  const double a = -x.y(), b = -(x.z() + axis_depth);  // (sin phi, cos phi) times the distance to the axis
  if (a == 0.0 && b == 0.0) return near.value_or(M_PI);
  double phi = std::atan2(a, b);
  if (phi < 0.0) phi += kTwoPi;
  // On the seam both ends of the range are the same point: the one nearer the guess.
  if (near && *near > M_PI && phi < 1e-12) phi = kTwoPi;
  return phi;
}

FuselageWall::FuselageWall(int id, std::string name, std::shared_ptr<const NacaWing> wing, double radius, double slope,
                           cad::Interval x_range, double tol)
    : cad::Surface(id, std::move(name), +1),
      wing_(std::move(wing)),
      radius_(radius),
      slope_(slope),
      x_range_(x_range),
      tol_(tol) {}

std::array<cad::Interval, 2> FuselageWall::bounds() const { return {x_range_, cad::Interval{0.0, kTwoPi}}; }

cad::SurfaceDerivatives FuselageWall::derivatives(const Vec2& uv) const {
  const double s = std::sin(uv.y()), c = std::cos(uv.y()), k = slope_, r = radius_ + k * uv.x();
  cad::SurfaceDerivatives d;
  d.p = on_circle(uv.x(), uv.y(), r, radius_);
  d.du = cad::Vec3(1.0, -k * s, -k * c);
  d.dv = cad::Vec3(0.0, -r * c, r * s);
  d.duu = cad::Vec3::Zero();
  d.duv = cad::Vec3(0.0, -k * c, k * s);
  d.dvv = cad::Vec3(0.0, r * s, r * c);
  return d;
}

cad::Vec3 FuselageWall::point(const Vec2& uv) const {
  return on_circle(uv.x(), uv.y(), radius_ + slope_ * uv.x(), radius_);
}

bool FuselageWall::contains(const Vec2& uv) const {
  const auto box = bounds();
  const double r = radius_ + slope_ * uv.x();
  if (!box[0].contains(uv.x(), tol_) || !box[1].contains(uv.y(), tol_ / r)) return false;
  // The root section lies near the crest (naca_validation): away from it (more than 60 degrees
  // round the fuselage), where the wing's map need not even be defined, is never in the hole.
  const cad::Vec3 p = point(uv);
  if (p.z() + radius_ < 0.5 * r) return true;
  const OutlineSide side = wing_->section().classify(wing_->to_section(p, p.z()), tol_ / wing_->chord_at(p.z()));
  return side != OutlineSide::Inside;
}

cad::SurfaceProjection FuselageWall::project(const cad::Vec3& x, std::optional<Vec2> guess) const {
  // In the half-plane of x through the axis the fuselage is the line rho = R + k x: the foot on it.
  const double rho = std::hypot(x.y(), x.z() + radius_), k = slope_;
  cad::SurfaceProjection out;
  out.uv = Vec2(x_range_.clamp((x.x() + k * (rho - radius_)) / (1.0 + k * k)),
                fuselage_angle(x, radius_, guess ? std::optional<double>(guess->y()) : std::nullopt));
  out.point = point(out.uv);
  out.distance = (out.point - x).norm();
  out.converged = true;
  out.inside = contains(out.uv);
  return out;
}

std::optional<double> FuselageWall::period(int direction) const {
  cad::Surface::period(direction);  // checks the direction
  if (direction == 1) return kTwoPi;
  return std::nullopt;
}

FuselageCircle::FuselageCircle(int id, std::string name, double x0, double radius, double axis_depth)
    : cad::Curve(id, std::move(name)), x0_(x0), radius_(radius), axis_depth_(axis_depth) {}

cad::Interval FuselageCircle::bounds() const { return {0.0, kTwoPi}; }

cad::CurveDerivatives FuselageCircle::derivatives(double t) const {
  const double s = std::sin(t), c = std::cos(t), r = radius_;
  return {on_circle(x0_, t, r, axis_depth_), cad::Vec3(0.0, -r * c, r * s), cad::Vec3(0.0, r * s, r * c)};
}

cad::Vec3 FuselageCircle::point(double t) const { return on_circle(x0_, t, radius_, axis_depth_); }

cad::CurveProjection FuselageCircle::project(const cad::Vec3& x, std::optional<double> guess) const {
  cad::CurveProjection out;
  out.t = fuselage_angle(x, axis_depth_, guess);
  out.point = point(out.t);
  out.distance = (out.point - x).norm();
  out.converged = true;
  return out;
}

}  // namespace semimesh::mock_cad::detail
