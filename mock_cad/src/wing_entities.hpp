// The CAD entities carried by the wing map: the upper and lower skins, the squared-off
// trailing-edge base between them, and the root and tip section curves.
#pragma once

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

/// One side of the wing: (u, v) in [0,1] x [0,span], u = sqrt(chordwise fraction), v = z.
/// du x dv points into the wing on the upper side and out of it on the lower side, hence the
/// orientation -1 / +1 so normal() always points into the fluid.
class WingSkin final : public cad::Surface {
 public:
  WingSkin(int id, std::string name, std::shared_ptr<const NacaWing> wing, Side side, double tol);

  SurfaceKind kind() const override { return SurfaceKind::Analytic; }
  std::array<Interval, 2> bounds() const override { return {Interval{0.0, 1.0}, Interval{0.0, wing_->span()}}; }
  SurfaceDerivatives derivatives(const Vec2& uv) const override { return wing_->eval(side_, uv.x(), uv.y()); }
  Vec3 point(const Vec2& uv) const override { return wing_->point(side_, uv.x(), uv.y()); }
  bool contains(const Vec2& uv) const override;
  SurfaceProjection project(const Vec3& x, std::optional<Vec2> guess = std::nullopt) const override;

 private:
  std::shared_ptr<const NacaWing> wing_;
  Side side_;
  double tol_;
};

/// The squared-off trailing-edge base: the ruled face S(s, v) = L(v) + s (U(v) - L(v)) between
/// the lower (s = 0) and upper (s = 1) trailing-edge lines, v = z. Planar, because U - L keeps
/// its direction along the span (it scales with the chord); the normal points downstream.
class TrailingEdgeBase final : public cad::Surface {
 public:
  TrailingEdgeBase(int id, std::string name, std::shared_ptr<const NacaWing> wing, double tol);

  SurfaceKind kind() const override { return SurfaceKind::Plane; }
  std::array<Interval, 2> bounds() const override { return {Interval{0.0, 1.0}, Interval{0.0, wing_->span()}}; }
  SurfaceDerivatives derivatives(const Vec2& uv) const override;
  Vec3 point(const Vec2& uv) const override;
  bool contains(const Vec2& uv) const override;
  SurfaceProjection project(const Vec3& x, std::optional<Vec2> guess = std::nullopt) const override;

 private:
  std::shared_ptr<const NacaWing> wing_;
  double tol_;
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

}  // namespace semimesh::mock_cad::detail
