// The entities of the analytic body of revolution (naca.shape = revolution): the symmetric NACA
// thickness distribution revolved a full turn about the chord line (a streamlined pod). Its one
// face is periodic, bounded by a seam (the meridian, walked once each way) and two poles (nose and
// tail, degenerate curves), so the seam and pole paths of the contract are testable without OCC.
//
//   S(u, w) = c (X(u), Y(u) cos w, Y(u) sin w),   u in [0, 1], w in [0, 2 pi] (period 2 pi)
//
// with (X, Y) the upper side of the section (X = u^2, Y = y_t(u^2)); Y(0) = Y(1) = 0 (sharp TE):
// u = 0 is the nose pole, u = 1 the tail pole. du x dw points into the body, hence orientation -1.
#pragma once

#include "naca_section.hpp"

#include "semimesh/cad/curve.hpp"
#include "semimesh/cad/surface.hpp"

#include <cmath>
#include <memory>
#include <string>

namespace semimesh::mock_cad::detail {

class RevolutionBody final : public cad::Surface {
 public:
  RevolutionBody(int id, std::string name, std::shared_ptr<const NacaSection> section, double chord, double tol);

  cad::SurfaceKind kind() const override { return cad::SurfaceKind::Revolution; }
  std::array<cad::Interval, 2> bounds() const override;
  cad::SurfaceDerivatives derivatives(const Vec2& uv) const override;
  bool contains(const Vec2& uv) const override;
  /// Newton from the analytic start u = sqrt(x / c), w = atan2(z, y) in [0, 2 pi), or the guess.
  cad::SurfaceProjection project(const cad::Vec3& x, std::optional<Vec2> guess = std::nullopt) const override;
  std::optional<double> period(int direction) const override;

 private:
  std::shared_ptr<const NacaSection> section_;
  double chord_;
  double tol_;
};

/// The seam: the meridian w = 0, C(t) = c (X(t), Y(t), 0), t in [0, 1] from nose to tail.
class MeridianCurve final : public cad::Curve {
 public:
  MeridianCurve(int id, std::string name, std::shared_ptr<const NacaSection> section, double chord);

  cad::CurveKind kind() const override { return cad::CurveKind::Analytic; }
  cad::Interval bounds() const override { return {0.0, 1.0}; }
  cad::CurveDerivatives derivatives(double t) const override;

 private:
  std::shared_ptr<const NacaSection> section_;
  double chord_;
};

/// A pole: the point `at` walked over t = w in `range` ([0, 2 pi] on the body of revolution,
/// [0, pi] on the rounded tip).
class PoleCurve final : public cad::Curve {
 public:
  PoleCurve(int id, std::string name, const cad::Vec3& at, cad::Interval range = {0.0, 2.0 * M_PI})
      : cad::Curve(id, std::move(name)), at_(at), range_(range) {}

  cad::CurveKind kind() const override { return cad::CurveKind::Analytic; }
  cad::Interval bounds() const override { return range_; }
  cad::CurveDerivatives derivatives(double) const override { return {at_, cad::Vec3::Zero(), cad::Vec3::Zero()}; }
  /// Every t is as near as any other: the guess (or the middle of the range) is the answer.
  cad::CurveProjection project(const cad::Vec3& x, std::optional<double> guess = std::nullopt) const override;
  bool is_degenerate() const override { return true; }

 private:
  cad::Vec3 at_;
  cad::Interval range_;
};

}  // namespace semimesh::mock_cad::detail
