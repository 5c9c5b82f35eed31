// The CAD entities carried by the wing map: the upper and lower skins, the squared-off
// trailing-edge base between them, and the root and tip section curves. On a cylindrical wall
// (naca.wall = cylinder) the skins and the base start at their root on the cylinder, v = 0
// (fuselage_root.hpp), and the root curves are those intersections.
#pragma once

#include "fuselage_root.hpp"
#include "naca_wing.hpp"

#include "semimesh/cad/curve.hpp"
#include "semimesh/cad/surface.hpp"

#include <memory>
#include <string>

namespace semimesh::mock_cad::detail {

using cad::CurveDerivatives;
using cad::CurveKind;
using cad::CurveProjection;
using cad::Interval;
using cad::SurfaceKind;
using cad::SurfaceProjection;

/// One side of the wing: (u, v) in [0,1] x [0,span], u = sqrt(chordwise fraction), v = z (on a
/// cylinder: v = 0 on the root, z(u, v) of fuselage_root.hpp).
/// du x dv points into the wing on the upper side and out of it on the lower side, hence the
/// orientation -1 / +1 so normal() always points into the fluid.
class WingSkin final : public cad::Surface {
 public:
  WingSkin(int id, std::string name, std::shared_ptr<const NacaWing> wing, Side side, double tol,
           std::shared_ptr<const FuselageRoot> root = nullptr);

  SurfaceKind kind() const override { return SurfaceKind::Analytic; }
  std::array<Interval, 2> bounds() const override { return {Interval{0.0, 1.0}, Interval{0.0, wing_->span()}}; }
  SurfaceDerivatives derivatives(const Vec2& uv) const override {
    return root_ ? root_->eval(part(), uv.x(), uv.y()) : wing_->eval(side_, uv.x(), uv.y());
  }
  Vec3 point(const Vec2& uv) const override {
    return root_ ? root_->point(part(), uv.x(), uv.y()) : wing_->point(side_, uv.x(), uv.y());
  }
  bool contains(const Vec2& uv) const override;
  SurfaceProjection project(const Vec3& x, std::optional<Vec2> guess = std::nullopt) const override;

 private:
  RootPart part() const { return side_ == Side::Upper ? RootPart::Upper : RootPart::Lower; }
  /// The v of the point at chordwise u and height z, in the box.
  double v_at(double u, double z) const;

  std::shared_ptr<const NacaWing> wing_;
  Side side_;
  double tol_;
  std::shared_ptr<const FuselageRoot> root_;  // naca.wall = cylinder only
};

/// The squared-off trailing-edge base: the ruled face S(s, v) = L(v) + s (U(v) - L(v)) between
/// the lower (s = 0) and upper (s = 1) trailing-edge lines, v = z (on a cylinder: v = 0 on the
/// root, z(s, v) of fuselage_root.hpp). Planar, because U - L keeps its direction along the span
/// (it scales with the chord); the normal points downstream.
class TrailingEdgeBase final : public cad::Surface {
 public:
  TrailingEdgeBase(int id, std::string name, std::shared_ptr<const NacaWing> wing, double tol,
                   std::shared_ptr<const FuselageRoot> root = nullptr);

  SurfaceKind kind() const override { return SurfaceKind::Plane; }
  std::array<Interval, 2> bounds() const override { return {Interval{0.0, 1.0}, Interval{0.0, wing_->span()}}; }
  SurfaceDerivatives derivatives(const Vec2& uv) const override;
  Vec3 point(const Vec2& uv) const override;
  bool contains(const Vec2& uv) const override;
  SurfaceProjection project(const Vec3& x, std::optional<Vec2> guess = std::nullopt) const override;

 private:
  std::shared_ptr<const NacaWing> wing_;
  double tol_;
  std::shared_ptr<const FuselageRoot> root_;  // naca.wall = cylinder only
};

/// A section of one side at fixed height v: t = u in [0, 1], from the leading to the trailing edge.
class SectionCurve final : public cad::Curve {
 public:
  SectionCurve(int id, std::string name, std::shared_ptr<const NacaWing> wing, Side side, double v, double tol);

  CurveKind kind() const override { return CurveKind::Analytic; }
  Interval bounds() const override { return Interval{0.0, 1.0}; }
  CurveDerivatives derivatives(double t) const override;
  Vec3 point(double t) const override { return wing_->point(side_, t, v_); }
  CurveProjection project(const Vec3& x, std::optional<double> guess = std::nullopt) const override;

 private:
  std::shared_ptr<const NacaWing> wing_;
  Side side_;
  double v_;
  double tol_;
};

/// A root curve on the cylinder: v = 0 of a skin (t = u in [0, 1], leading to trailing edge) or of
/// the trailing-edge base (t = s in [0, 1], lower to upper trailing edge).
class RootCurve final : public cad::Curve {
 public:
  RootCurve(int id, std::string name, std::shared_ptr<const FuselageRoot> root, RootPart part, double tol);

  CurveKind kind() const override { return CurveKind::Analytic; }
  Interval bounds() const override { return Interval{0.0, 1.0}; }
  CurveDerivatives derivatives(double t) const override;
  Vec3 point(double t) const override { return root_->point(part_, t, 0.0); }
  /// Newton from the section's start (a skin) or the foot on the trailing-edge segment (the base).
  CurveProjection project(const Vec3& x, std::optional<double> guess = std::nullopt) const override;

 private:
  std::shared_ptr<const FuselageRoot> root_;
  RootPart part_;
  double tol_;
};

}  // namespace semimesh::mock_cad::detail
