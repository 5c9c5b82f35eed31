// The CAD entities of the rounded tip (round_tip.hpp): the tip face itself, its trailing-edge arc
// (blunt) and the trailing-edge base capped by a half disc that meets that arc.
#pragma once

#include "round_tip.hpp"

#include "semimesh/cad/curve.hpp"
#include "semimesh/cad/surface.hpp"

#include <memory>
#include <string>

namespace semimesh::mock_cad::detail {

/// The tip T(u, phi), (u, phi) in [0, 1] x [0, pi]: phi = 0 on the upper side's tip section,
/// phi = pi on the lower side's, u = 0 a pole (and u = 1 with a sharp trailing edge). du x dphi
/// points into the wing, hence orientation -1.
class RoundTipFace final : public cad::Surface {
 public:
  RoundTipFace(int id, std::string name, std::shared_ptr<const RoundTipMap> tip, double tol);

  cad::SurfaceKind kind() const override { return cad::SurfaceKind::Analytic; }
  std::array<cad::Interval, 2> bounds() const override;
  cad::SurfaceDerivatives derivatives(const Vec2& uv) const override { return tip_->eval(uv.x(), uv.y()); }
  bool contains(const Vec2& uv) const override;
  /// Newton from (u, phi) read off the point (u from the chordwise station, phi from the angle
  /// about the camber line), off a pole when it stalls there; a grid of starts when that start
  /// ends far from the tip (deep inside the wing).
  cad::SurfaceProjection project(const cad::Vec3& x, std::optional<Vec2> guess = std::nullopt) const override;

 private:
  Vec2 initial_guess(const cad::Vec3& x) const;
  cad::SurfaceProjection solve(const cad::Vec3& x, const Vec2& start) const;

  std::shared_ptr<const RoundTipMap> tip_;
  double tol_;
};

/// The tip's trailing-edge arc (blunt): T(1, pi - t), t in [0, pi], from the lower side's trailing
/// edge to the upper side's, as the flat tip's straight tip_te runs.
class TipArc final : public cad::Curve {
 public:
  TipArc(int id, std::string name, std::shared_ptr<const RoundTipMap> tip, double tol);

  cad::CurveKind kind() const override { return cad::CurveKind::Analytic; }
  cad::Interval bounds() const override;
  cad::CurveDerivatives derivatives(double t) const override;
  /// Newton from the nearest of a few samples.
  cad::CurveProjection project(const cad::Vec3& x, std::optional<double> guess = std::nullopt) const override;

 private:
  std::shared_ptr<const RoundTipMap> tip_;
  double tol_;
};

/// The blunt trailing-edge base under a rounded tip: the plane origin + a N(1) + b W(1) in its
/// affine coordinates (a, b) (round_tip.hpp), trimmed to the trapezoid |a| <= c(b) y_t(1),
/// 0 <= b <= span, capped by the half disc a^2 + (b - span)^2 <= (c(span) y_t(1))^2. a grows from
/// the lower side to the upper one and b along the span: the normal points downstream (+1).
class CappedTrailingEdgeBase final : public cad::Surface {
 public:
  CappedTrailingEdgeBase(int id, std::string name, std::shared_ptr<const RoundTipMap> tip, double tol);

  cad::SurfaceKind kind() const override { return cad::SurfaceKind::Plane; }
  std::array<cad::Interval, 2> bounds() const override;
  cad::SurfaceDerivatives derivatives(const Vec2& ab) const override;
  bool contains(const Vec2& ab) const override;
  /// Exact: the foot on the plane (a 2 x 2 solve), then Newton held to the parameter box.
  cad::SurfaceProjection project(const cad::Vec3& x, std::optional<Vec2> guess = std::nullopt) const override;

 private:
  std::shared_ptr<const RoundTipMap> tip_;
  double tol_;
  cad::Vec3 origin_, across_, along_;
  double half_width_root_, half_width_tip_, span_;
};

}  // namespace semimesh::mock_cad::detail
