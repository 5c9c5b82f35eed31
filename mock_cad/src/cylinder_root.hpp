// The wing's root on a streamwise circular cylinder (naca.wall = cylinder, cylinder_wall.hpp): the
// curves where the skins and the trailing-edge base meet the cylinder y^2 + (z + R)^2 = R^2, and
// those surfaces reparametrised so that their parameter box stays a rectangle with v = 0 on the root.
//
// Each of these surfaces is S(s, z) with y = y_le(z) + c(z) Y(s) (a skin: Y the section's ordinate
// at u = s; the base: Y(s) = Y_L + s (Y_U - Y_L) between the lower and upper trailing edges; y_le
// the dihedral's shift, naca_wing.hpp). Its root height z_r(s) solves
//   F(s, z) = y(s, z)^2 + z (z + 2R) = 0
// (the cylinder's equation, written without the cancellation of (z + R)^2 - R^2) on the sheet near
// the crest, z > -R, by Newton from the untapered closed form z = -y^2 / (R + sqrt(R^2 - y^2)), to
// machine precision. Its derivatives follow by implicit differentiation:
//   z_r' = -F_s / F_z,   z_r'' = -(F_ss + 2 F_sz z_r' + F_zz z_r'^2) / F_z.
// The surface is then P(s, v) = S(s, z(s, v)) with
//   z(s, v) = v + z_r(s) (1 - v / span),   v in [0, span],
// affine in v (spanwise lines stay straight, P_vv = 0), z = z_r at v = 0 and exactly z = span at
// the tip, and z = v where z_r = 0 (the leading edge, and a sharp trailing edge).
#pragma once

#include "naca_wing.hpp"

#include <memory>

namespace semimesh::mock_cad::detail {

/// The surfaces of the wing that reach the cylinder.
enum class RootPart { Upper, Lower, Base };

class CylinderRoot {
 public:
  /// `radius` > 0 and large enough that every root ordinate |y| stays well below it (naca_validation).
  CylinderRoot(std::shared_ptr<const NacaWing> wing, double radius);

  const NacaWing& wing() const { return *wing_; }
  double radius() const { return radius_; }

  /// z_r and its s-derivatives for a surface whose ordinate is `ordinate` (Y, Y', Y'' in s).
  ScalarPoint height(const ScalarPoint& ordinate) const;
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
  ScalarPoint ordinate(RootPart part, double s) const;

  std::shared_ptr<const NacaWing> wing_;
  double radius_;
  double base_lower_, base_upper_;  // Y of the lower and upper trailing edges (chord units)
};

}  // namespace semimesh::mock_cad::detail
