// The wing as a map (side, u, v) -> R^3: the NACA section scaled by the local chord and shifted
// by the leading-edge sweep and dihedral, at height z = v above the wall.
//
//   c(v)    = chord (1 - (1 - taper) v / span)       (linear taper)
//   x_le(v) = v tan(sweep),  y_le(v) = v tan(dihedral)
//   S(u, v) = (x_le(v) + c(v) X(u), y_le(v) + c(v) Y(u), v)    with (X, Y) the chord-normalised profile
//
// c, x_le and y_le are linear in v, so S_vv = 0 and the leading and trailing edges are straight
// lines. The dihedral, like the sweep, shears the wing: its sections stay parallel to the wall.
#pragma once

#include "naca_section.hpp"

#include "semimesh/cad/types.hpp"

#include <array>

namespace semimesh::mock_cad::detail {

using cad::SurfaceDerivatives;
using cad::Vec3;

class NacaWing {
 public:
  NacaWing(const NacaSection& section, double chord, double span, double taper, double sweep_deg,
           double dihedral_deg = 0.0);

  const NacaSection& section() const { return section_; }
  double root_chord() const { return chord_; }
  double span() const { return span_; }
  double chord_at(double v) const { return chord_ + dchord_ * v; }
  double leading_edge_x(double v) const { return tan_sweep_ * v; }
  double leading_edge_y(double v) const { return tan_dihedral_ * v; }
  /// dc/dv, dx_le/dv and dy_le/dv (all constant).
  double chord_slope() const { return dchord_; }
  double tan_sweep() const { return tan_sweep_; }
  double tan_dihedral() const { return tan_dihedral_; }
  /// Radius of curvature at the leading edge, (5 t a0)^2 / 2 c(v) (~1.1019 t^2 c).
  double leading_edge_radius(double v) const {
    const double slope = section_.leading_edge_slope();
    return 0.5 * slope * slope * chord_at(v);
  }

  /// S(u, v) on one side and its first and second partial derivatives.
  SurfaceDerivatives eval(Side side, double u, double v) const;
  Vec3 point(Side side, double u, double v) const;
  /// The ruled map between the lower (s = 0) and upper (s = 1) trailing edges at height v (the
  /// squared-off base), L(v) + s (U(v) - L(v)), and its derivatives in (s, v).
  SurfaceDerivatives eval_base(double s, double v) const;

  /// (X, Y) of x in the chord-normalised frame of the section at height v.
  Vec2 to_section(const Vec3& x, double v) const;
  /// Two starts u for the closest point of q (chord-normalised) on one side: from the chordwise
  /// station (u = sqrt(X)) and from the thickness (Y ~ +-5 t a0 u, right near the leading edge).
  std::array<double, 2> start_candidates(Side side, const Vec2& q) const;
  /// The candidate that lands closer to q.
  double initial_u(Side side, const Vec2& q) const;
  /// A start (u, v) for the closest point of x on one side: v from z, u from initial_u.
  Vec2 initial_guess(Side side, const Vec3& x) const;

 private:
  double shifted_y(double y, double v) const;

  NacaSection section_;
  double chord_, span_, dchord_, tan_sweep_, tan_dihedral_;
};

}  // namespace semimesh::mock_cad::detail
