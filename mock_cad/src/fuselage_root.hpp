// The wing's root on a fuselage about the streamwise axis (naca.wall = cylinder or cone,
// fuselage_wall.hpp): the curves where the skins and the trailing-edge base meet the body of
// revolution y^2 + (z + R)^2 = r(x)^2, r(x) = R + k x (k = tan of the cone's half angle, 0 for the
// cylinder), and those surfaces reparametrised so that their parameter box stays a rectangle with
// v = 0 on the root.
//
// Each of these surfaces is S(s, z) with x = x_le(z) + c(z) X(s), y = y_le(z) + c(z) Y(s) (a skin:
// (X, Y) the section at u = s; the base: (X, Y)(s) = L + s (U - L) between the lower and upper
// trailing edges L and U; naca_wing.hpp). Its root height z_r(s) solves
//   F(s, z) = y^2 + z (z + 2R) - k x (2R + k x) = 0
// (the fuselage's equation with R^2 cancelled by hand, so no round-off cancellation) on the sheet
// near the crest, by Newton from the closed form at fixed (x, y) of the section at z = 0, to
// machine precision. Its derivatives follow by implicit differentiation:
//   z_r' = -F_s / F_z,   z_r'' = -(F_ss + 2 F_sz z_r' + F_zz z_r'^2) / F_z.
// The surface is then P(s, v) = S(s, z(s, v)) with
//   z(s, v) = v + z_r(s) (1 - v / span),   v in [0, span],
// affine in v (spanwise lines stay straight, P_vv = 0), z = z_r at v = 0 and exactly z = span at
// the tip, and z = v where z_r = 0 (the leading edge, and a sharp trailing edge on a cylinder).
#pragma once

#include "naca_wing.hpp"

#include <memory>

namespace semimesh::mock_cad::detail {

/// The surfaces of the wing that reach the fuselage.
enum class RootPart { Upper, Lower, Base };

class FuselageRoot {
 public:
  /// `radius` R > 0 at x = 0, `slope` k = dr/dx; the root must stay near the crest (naca_validation).
  FuselageRoot(std::shared_ptr<const NacaWing> wing, double radius, double slope);

  const NacaWing& wing() const { return *wing_; }

  /// z_r(s) of one part (s = u on a skin, s across the base from its lower edge).
  ScalarPoint root_height(RootPart part, double s) const;

  /// The reparametrised part at (s, v), v in [0, span], with its first and second derivatives.
  SurfaceDerivatives eval(RootPart part, double s, double v) const;
  Vec3 point(RootPart part, double s, double v) const;

  /// The height z of (s, v) given z_r(s), and its inverse: the v at height z.
  double height_at(double root_z, double v) const { return v + root_z * (1.0 - v / wing_->span()); }
  double v_at(double root_z, double z) const { return (z - root_z) / (1.0 - root_z / wing_->span()); }

 private:
  // The part's S(s, z) with derivatives in (s, z) (dv, duv, dvv hold the z-derivatives).
  SurfaceDerivatives unlifted(RootPart part, double s, double z) const;
  ProfilePoint section_point(RootPart part, double s) const;
  // z_r of the section point q (chord units), and with its s-derivatives from q's.
  double solve(const Vec2& q) const;
  ScalarPoint height(const ProfilePoint& q) const;

  std::shared_ptr<const NacaWing> wing_;
  double radius_, slope_;
  Vec2 base_lower_, base_upper_;  // the lower and upper trailing edges (chord units)
};

}  // namespace semimesh::mock_cad::detail
