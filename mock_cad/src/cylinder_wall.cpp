#include "cylinder_wall.hpp"

#include <algorithm>
#include <cmath>

namespace semimesh::mock_cad::detail {
namespace {

constexpr double kTwoPi = 2.0 * M_PI;

cad::Vec3 on_cylinder(double x, double phi, double radius) {
  return cad::Vec3(x, -radius * std::sin(phi), -radius * (1.0 + std::cos(phi)));
}

}  // namespace

double cylinder_angle(const cad::Vec3& x, double radius, std::optional<double> near) {
  const double a = -x.y(), b = -(x.z() + radius);  // (sin phi, cos phi) times the distance to the axis
  if (a == 0.0 && b == 0.0) return near.value_or(M_PI);
  double phi = std::atan2(a, b);
  if (phi < 0.0) phi += kTwoPi;
  // On the seam both ends of the range are the same point: the one nearer the guess.
  if (near && *near > M_PI && phi < 1e-12) phi = kTwoPi;
  return phi;
}

CylinderWall::CylinderWall(int id, std::string name, std::shared_ptr<const NacaWing> wing, double radius,
                           cad::Interval x_range, double tol)
    : cad::Surface(id, std::move(name), +1), wing_(std::move(wing)), radius_(radius), x_range_(x_range), tol_(tol) {}

std::array<cad::Interval, 2> CylinderWall::bounds() const { return {x_range_, cad::Interval{0.0, kTwoPi}}; }

cad::SurfaceDerivatives CylinderWall::derivatives(const Vec2& uv) const {
  const double s = std::sin(uv.y()), c = std::cos(uv.y()), r = radius_;
  cad::SurfaceDerivatives d;
  d.p = on_cylinder(uv.x(), uv.y(), r);
  d.du = cad::Vec3::UnitX();
  d.dv = cad::Vec3(0.0, -r * c, r * s);
  d.duu = cad::Vec3::Zero();
  d.duv = cad::Vec3::Zero();
  d.dvv = cad::Vec3(0.0, r * s, r * c);
  return d;
}

cad::Vec3 CylinderWall::point(const Vec2& uv) const { return on_cylinder(uv.x(), uv.y(), radius_); }

bool CylinderWall::contains(const Vec2& uv) const {
  const auto box = bounds();
  if (!box[0].contains(uv.x(), tol_) || !box[1].contains(uv.y(), tol_ / radius_)) return false;
  // The root section lies near the crest (|y| well below R, naca_validation): the lower half of the
  // fuselage, where the wing's map need not even be defined, is never in the hole.
  const cad::Vec3 p = point(uv);
  if (p.z() < -0.5 * radius_) return true;
  const OutlineSide side = wing_->section().classify(wing_->to_section(p, p.z()), tol_ / wing_->chord_at(p.z()));
  return side != OutlineSide::Inside;
}

cad::SurfaceProjection CylinderWall::project(const cad::Vec3& x, std::optional<Vec2> guess) const {
  cad::SurfaceProjection out;
  out.uv = Vec2(x_range_.clamp(x.x()), cylinder_angle(x, radius_, guess ? std::optional<double>(guess->y()) : std::nullopt));
  out.point = point(out.uv);
  out.distance = (out.point - x).norm();
  out.converged = true;
  out.inside = contains(out.uv);
  return out;
}

std::optional<double> CylinderWall::period(int direction) const {
  cad::Surface::period(direction);  // checks the direction
  if (direction == 1) return kTwoPi;
  return std::nullopt;
}

WallCircle::WallCircle(int id, std::string name, double x0, double radius)
    : cad::Curve(id, std::move(name)), x0_(x0), radius_(radius) {}

cad::Interval WallCircle::bounds() const { return {0.0, kTwoPi}; }

cad::CurveDerivatives WallCircle::derivatives(double t) const {
  const double s = std::sin(t), c = std::cos(t), r = radius_;
  return {on_cylinder(x0_, t, r), cad::Vec3(0.0, -r * c, r * s), cad::Vec3(0.0, r * s, r * c)};
}

cad::Vec3 WallCircle::point(double t) const { return on_cylinder(x0_, t, radius_); }

cad::CurveProjection WallCircle::project(const cad::Vec3& x, std::optional<double> guess) const {
  cad::CurveProjection out;
  out.t = cylinder_angle(x, radius_, guess);
  out.point = point(out.t);
  out.distance = (out.point - x).norm();
  out.converged = true;
  return out;
}

}  // namespace semimesh::mock_cad::detail
