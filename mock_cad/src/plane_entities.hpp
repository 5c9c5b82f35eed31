// Flat entities: straight-line curves and planar faces with orthonormal, affine parameters,
// optionally trimmed by a wing section (the tip cap keeps the inside of the tip section, the wall
// keeps the outside of the root section) or with a round hole (where the fuselage of
// naca.wall = cylinder passes through the box's ends).
#pragma once

#include "naca_wing.hpp"

#include "semimesh/cad/curve.hpp"
#include "semimesh/cad/surface.hpp"

#include <memory>
#include <optional>
#include <string>

namespace semimesh::mock_cad::detail {

using cad::CurveDerivatives;
using cad::CurveKind;
using cad::CurveProjection;
using cad::Interval;
using cad::SurfaceKind;
using cad::SurfaceProjection;

/// Segment from a (at t = range.lo) to b (at t = range.hi), affine in t.
class LineCurve final : public cad::Curve {
 public:
  LineCurve(int id, std::string name, const Vec3& a, const Vec3& b, Interval range);

  CurveKind kind() const override { return CurveKind::Line; }
  Interval bounds() const override { return range_; }
  CurveDerivatives derivatives(double t) const override;
  Vec3 point(double t) const override { return a_ + (t - range_.lo) * velocity_; }
  CurveProjection project(const Vec3& x, std::optional<double> guess = std::nullopt) const override;
  double arc_length(double a, double b) const override { return (b - a) * velocity_.norm(); }
  double parameter_at_length(double t_start, double s) const override;

 private:
  Vec3 a_;
  Interval range_;
  Vec3 velocity_;  // dP/dt
};

/// A wing section used as a trimming outline of a plane z = level, in the plane's (x, y) parameters.
struct SectionTrim {
  std::shared_ptr<const NacaWing> wing;
  double level = 0.0;        ///< z of the section (v of the wing map)
  bool keep_inside = true;   ///< true: the face is the section; false: the section is a hole
};

/// A disc cut out of a plane, in the plane's (u, v) parameters.
struct DiscHole {
  Vec2 centre;
  double radius = 0.0;
};

/// S(u, v) = origin + u e1 + v e2 with e1, e2 orthonormal, on the parameter box `box`.
class PlaneFace final : public cad::Surface {
 public:
  PlaneFace(int id, std::string name, int orientation, const Vec3& origin, const Vec3& e1, const Vec3& e2,
            std::array<Interval, 2> box, double tol, std::optional<SectionTrim> trim = std::nullopt,
            std::optional<DiscHole> hole = std::nullopt);

  SurfaceKind kind() const override { return SurfaceKind::Plane; }
  std::array<Interval, 2> bounds() const override { return box_; }
  SurfaceDerivatives derivatives(const Vec2& uv) const override;
  Vec3 point(const Vec2& uv) const override { return origin_ + uv.x() * e1_ + uv.y() * e2_; }
  /// Inside the box, outside the hole and, when trimmed, inside (tip) or outside (wall) the
  /// section; within the tolerance of a boundary counts as inside.
  bool contains(const Vec2& uv) const override;
  /// Exact: the orthogonal foot, clamped to the parameter box.
  SurfaceProjection project(const Vec3& x, std::optional<Vec2> guess = std::nullopt) const override;

 private:
  Vec3 origin_, e1_, e2_;
  std::array<Interval, 2> box_;
  double tol_;
  std::optional<SectionTrim> trim_;
  std::optional<DiscHole> hole_;
};

}  // namespace semimesh::mock_cad::detail
