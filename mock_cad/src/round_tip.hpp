// The rounded (revolved) wing tip, naca.tip = round: the tip section's half thickness turned about
// its camber line through a half turn above the tip plane z = span, like the tip of the NekMesh test
// wing (a section revolved about its chord line):
//
//   T(u, phi) = C(u) + c y_t(u) (N(u) cos phi + W(u) sin phi),   u in [0, 1], phi in [0, pi]
//
// with, at the tip (c = c(span), x = u^2, y_c, theta of the section):
//   C(u) = (x_le(span) + c x, c y_c, span)          the camber line,
//   N(u) = (-sin theta, cos theta, 0)                its unit normal in the section's plane,
//   W(u) = (tan(sweep) + c' x, c' y_c, 1)            dC/dspan of the camber surface (c' = dc/dv).
// phi = 0 is the upper side's tip section (C + c y_t N), phi = pi the lower side's, exactly. Unswept
// and untapered W = +z and T is the section revolved about its camber line; a swept or tapered wing
// tilts the half turn along its span direction W so that at the trailing edge (u = 1) the arc lies
// in the plane of the trailing-edge base (spanned by N(1) and W(1)): the blunt base stays one plane,
// a rectangle (trapezoid) capped by a half disc in its affine coordinates, and its sides run into
// the arc tangentially when the wing is untapered (within c' y_t(1) otherwise).
// y_t(0) = 0: u = 0 is a pole (the tip's leading edge, a smooth point of the surface); with a sharp
// trailing edge y_t(1) = 0 too and u = 1 is a second pole (a conical point).
#pragma once

#include "naca_wing.hpp"

#include <memory>

namespace semimesh::mock_cad::detail {

class RoundTipMap {
 public:
  explicit RoundTipMap(std::shared_ptr<const NacaWing> wing) : wing_(std::move(wing)) {}

  const NacaWing& wing() const { return *wing_; }
  /// T(u, phi) and its first and second partial derivatives (u first, phi second).
  SurfaceDerivatives eval(double u, double phi) const;
  Vec3 point(double u, double phi) const { return eval(u, phi).p; }
  /// The trailing-edge base's plane: origin C(1) at the root (z = 0) and axes N(1), W(1); the
  /// base is {origin + a N(1) + b W(1)}: |a| <= c(b) y_t(1) for b <= span, the half disc
  /// a^2 + (b - span)^2 <= (c(span) y_t(1))^2 above.
  Vec3 base_origin() const;
  Vec3 base_across() const;
  Vec3 base_along() const;
  /// y_t(1) (zero for a sharp trailing edge).
  double trailing_edge_half_thickness() const;

 private:
  std::shared_ptr<const NacaWing> wing_;
};

}  // namespace semimesh::mock_cad::detail
