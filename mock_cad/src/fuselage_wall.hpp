// The fuselage of naca.wall = cylinder or cone: the body of revolution about the streamwise axis
// (y = 0, z = -R) with radius r(x) = R + k x (k = tan of the cone's half angle, 0 for the
// cylinder), whose crest line passes through the root's leading edge at the origin and runs under
// the wing's root (fuselage_root.hpp). With the far-field box it runs through the box from xmin to
// xmax:
//
//   W(x, phi) = (x, -r(x) sin phi, -R - r(x) cos phi),   x in [xmin, xmax], phi in [0, 2 pi] (period 2 pi)
//
// phi is the angle about the axis from the bottom line (y = 0, the seam, phi = 0 and 2 pi) through
// the -y side (phi = pi / 2) to the crest (phi = pi). W_x x W_phi = r (-k, -sin phi, -cos phi)
// points out of the fuselage, into the fluid: orientation +1. The face is bounded by the circles
// x = xmin and x = xmax and the seam, and holds the wing's root section as a hole.
#pragma once

#include "naca_wing.hpp"

#include "semimesh/cad/curve.hpp"
#include "semimesh/cad/surface.hpp"

#include <memory>
#include <string>

namespace semimesh::mock_cad::detail {

/// The angle phi of the point x about the axis (y = 0, z = -axis_depth), in [0, 2 pi); `near` (a
/// parameter of the caller's guess) picks phi = 2 pi over phi = 0 on the seam. On the axis itself:
/// `near`, else pi.
double fuselage_angle(const cad::Vec3& x, double axis_depth, std::optional<double> near);

class FuselageWall final : public cad::Surface {
 public:
  FuselageWall(int id, std::string name, std::shared_ptr<const NacaWing> wing, double radius, double slope,
               cad::Interval x_range, double tol);

  cad::SurfaceKind kind() const override { return slope_ == 0.0 ? cad::SurfaceKind::Cylinder : cad::SurfaceKind::Cone; }
  std::array<cad::Interval, 2> bounds() const override;
  cad::SurfaceDerivatives derivatives(const Vec2& uv) const override;
  cad::Vec3 point(const Vec2& uv) const override;
  /// In the parameter box and outside the wing's root section (within the tolerance counts inside).
  bool contains(const Vec2& uv) const override;
  /// Exact: phi read off the point (fuselage_angle), x the foot on the meridian line in that
  /// half-plane, clamped to the box.
  cad::SurfaceProjection project(const cad::Vec3& x, std::optional<Vec2> guess = std::nullopt) const override;
  std::optional<double> period(int direction) const override;

 private:
  std::shared_ptr<const NacaWing> wing_;
  double radius_, slope_;
  cad::Interval x_range_;
  double tol_;
};

/// A circle of the fuselage at x = x0, of radius r(x0): C(t) = W(x0, t), t in [0, 2 pi], closed at the seam.
class FuselageCircle final : public cad::Curve {
 public:
  FuselageCircle(int id, std::string name, double x0, double radius, double axis_depth);

  cad::CurveKind kind() const override { return cad::CurveKind::Circle; }
  cad::Interval bounds() const override;
  cad::CurveDerivatives derivatives(double t) const override;
  cad::Vec3 point(double t) const override;
  /// Exact: t read off the point (fuselage_angle).
  cad::CurveProjection project(const cad::Vec3& x, std::optional<double> guess = std::nullopt) const override;
  double arc_length(double a, double b) const override { return radius_ * (b - a); }
  double parameter_at_length(double t_start, double s) const override { return bounds().clamp(t_start + s / radius_); }

 private:
  double x0_, radius_, axis_depth_;
};

}  // namespace semimesh::mock_cad::detail
