// The analytic backend "naca": a NACA 4-digit wing standing on a flat wall, optionally inside a
// far-field box, evaluated in closed form (exact first and second derivatives, no sampling or
// finite differences). It is the reference model for every test of the pipeline.
//
// Frame: x streamwise (root leading edge at x = 0), y cross-flow (thickness), z spanwise. The wall
// is the plane z = 0 (naca.wall = plane, the default; naca.wall = cylinder: below); the wing goes
// from z = 0 to z = span. Local chord and leading edge (sweep and dihedral shear the wing: its
// sections stay parallel to the wall):
//   c(z) = chord (1 - (1 - taper) z / span),   x_le(z) = z tan(sweep),   y_le(z) = z tan(dihedral).
// Section (Abbott & von Doenhoff 1959, sec. 6.4), with the chordwise station x = u^2 so that
// sqrt(x) = u and the skins are smooth at the leading edge:
//   y_t = 5 t (0.2969 u - 0.1260 u^2 - 0.3516 u^4 + 0.2843 u^6 + a4 u^8),
//   a4 = -0.1015 (squared-off TE of thickness 2 y_t(1) = 0.021 t) or -0.1036 (sharp TE),
//   camber y_c(x) per the MPTT parabolas, theta = atan(dy_c/dx),
//   upper: (x - y_t sin theta, y_c + y_t cos theta), lower: (x + y_t sin theta, y_c - y_t cos theta).
// The skins are smooth except, for a cambered code, along x = p (u = sqrt(p)): the camber line's
// curvature jumps there, which gives the standard 4-digit surface a small tangent kink (about
// 3e-4 rad for 2412). Derivatives there are the aft-side limits; projections handle the crease.
//
// Surfaces, in id order (normals point out of the solid into the fluid):
//   upper    (u, v) in [0,1] x [0,span]: S = (x_le(v) + c(v) X(u), y_le(v) + c(v) Y(u), v), u = 0 at the LE
//   lower    same parameters, lower side
//   te_base  (blunt only) (s, v) in [0,1] x [0,span]: lower TE line (s = 0) to upper TE line (s = 1)
//   tip      plane z = span, (u, v) = (x, y), trimmed to the tip section (normal +z)
//   wall     (farfield only) plane z = 0, (u, v) = (x, y) on the box's xy rectangle, with the root
//            section as a hole (normal +z)
//   box_xmin, box_xmax, box_ymin, box_ymax, box_zmax   (farfield only) planes with the two other
//            coordinates as (u, v) in axis order (x before y before z); normals point into the box
// Curves, in id order: leading_edge (t = z), root_upper, root_lower, tip_upper, tip_lower
// (t = u, LE -> TE), then blunt: te_upper, te_lower (t = z), root_te, tip_te (t = s, lower ->
// upper) or sharp: trailing_edge (t = z); then with farfield the 12 box edges, named by their two
// fixed coordinates (box_ymin_zmin runs along x, box_xmin_zmin along y, box_xmin_ymin along z)
// with t = the running coordinate. Vertices: root_le, tip_le, root_te_upper, root_te_lower,
// tip_te_upper, tip_te_lower (blunt) or root_te, tip_te (sharp), box_<x>_<y>_<z> corners.
// With farfield the model is watertight: every curve bounds exactly two surfaces.
//
// naca.tip = round replaces the flat tip cap by a rounded one (src/round_tip.hpp): the tip
// section's half thickness revolved about its camber line through a half turn above z = span,
//   tip  (u, phi) in [0,1] x [0,pi]: phi = 0 on tip_upper, phi = pi on tip_lower (normal outward),
// bounded by a pole at the tip's leading edge (curve tip_le_pole, degenerate, t = phi) and, blunt,
// by the arc tip_te (t in [0, pi], lower -> upper) or, sharp, a second pole tip_te_pole. The blunt
// te_base is then one plane in the affine coordinates (a, b) = (across the base, along its span):
// the trapezoid under z = span capped by a half disc whose rim is tip_te, so the base's sides run
// into the arc tangentially at tip_te_upper and tip_te_lower (its "flat corners", as on the
// NekMesh test wing). Curves in id order: as above with tip_te the arc, then tip_le_pole and,
// sharp, tip_te_pole. A swept or tapered wing tilts the half turn along its span (round_tip.hpp).
//
// naca.wall = cylinder or cone stands the wing on a fuselage (src/fuselage_root.hpp,
// src/fuselage_wall.hpp): the body of revolution y^2 + (z + R)^2 = r(x)^2 about the streamwise axis
// (y = 0, z = -R), R = naca.wall_radius, r(x) = R + k x with k = tan(naca.wall_angle), the cone's
// half angle (k = 0: the circular cylinder); its crest line (y = 0, z = k x) passes through the
// root's leading edge at the origin. The root curves root_upper, root_lower (t = u) and, blunt,
// root_te (t = s, lower -> upper) are the exact intersections of the skins and the base with the
// fuselage (Newton on the closed forms, machine precision); the leading edge stands on the crest at
// z = 0. The skins and the base keep their parameter rectangles [0,1] x [0,span], with the height
//   z(u, v) = v + z_r(u) (1 - v / span),   z_r(u) the root's height
// (v = 0 the root, v = span the tip; affine in v, so te_upper, te_lower, trailing_edge and
// leading_edge stay straight lines with t = v). With farfield the fuselage runs through the box:
//   wall  (x, phi) in [xmin, xmax] x [0, 2 pi], W = (x, -r(x) sin phi, -R - r(x) cos phi), period
//         2 pi in phi: phi = 0 and 2 pi the bottom line (the seam, the side pointing -z), pi / 2
//         the -y side, pi the crest; normal out of the fuselage; outer loop: seam, circle at xmax,
//         seam back, circle at xmin; the root section as a hole
//   box_xmin, box_xmax  hold the fuselage's circle (radius r(xmin), r(xmax)) as a hole; the box's
//         bottom is a face, box_zmin
// Surfaces in id order: the wing's, wall, box_xmin, box_xmax, box_ymin, box_ymax, box_zmin,
// box_zmax. Curves: the wing's, the 12 box edges, then wall_seam (t = x, along the bottom line),
// wall_xmin and wall_xmax (the circles, t = phi, closed at the seam). Vertices: the wing's, the box's,
// wall_xmin and wall_xmax (the seam's ends). Watertight: the seam bounds the wall twice.
// Checked: R > 4 times the root section's half thickness; the root within 1 - cos = 1/4 of the crest
// round the fuselage (R / 4 under it on a cylinder); taper < 1 + span / (2 R) (the planform extended
// down to the axis keeps half the root chord); naca.tip = flat; a cone: 0 < |angle| < 30 degrees
// (default 5) and a radius above R / 10 at the box's ends (its apex outside); the box holds the
// fuselage with 0.1 of its largest radius r_max to spare (zmin < -R - 1.1 r_max, |y| > 1.1 r_max) and
// the wing; default box {-10, -r_max - 10, -R - r_max - 10, 11, r_max + 10, 10}. Without farfield:
// the wing alone, open at its root on the fuselage.
//
// naca.shape = revolution builds instead a body of revolution: the section's thickness (a
// symmetric code, sharp TE) revolved a full turn about the chord line on the x axis, no wall and
// no box. One periodic surface "body" (u, w) in [0,1] x [0,2 pi], w the angle from +y towards +z,
// period 2 pi in w; curves: "meridian" (the seam w = 0, t = u, nose -> tail, walked once each way
// by the body's loop), "nose" and "tail" (degenerate curves, the poles u = 0 and u = 1, t = w);
// vertices "nose" and "tail". See src/revolution_entities.hpp.
#pragma once

#include "semimesh/cad/model.hpp"
#include "semimesh/cad/source.hpp"

#include <array>
#include <memory>
#include <string>

namespace semimesh::mock_cad {

struct NacaWingParams {
  std::string code = "0012";  ///< NACA 4-digit MPTT                                       (naca.code)
  double chord = 1.0;         ///< root chord                                               (naca.chord)
  double span = 3.0;          ///< semi-span: wing height above the wall z = 0              (naca.span)
  double taper = 1.0;         ///< tip chord / root chord, > 0                               (naca.taper)
  double sweep_deg = 0.0;     ///< leading-edge sweep angle in degrees, |sweep| < 80         (naca.sweep)
  double dihedral_deg = 0.0;  ///< dihedral in degrees, |dihedral| < 45: sections shifted by z tan  (naca.dihedral)
  bool sharp_te = false;      ///< false: squared-off TE with a te_base face; true: closed TE (naca.te)
  bool farfield = true;       ///< add the wall (root section as a hole) and the far-field box (naca.farfield)
  std::array<double, 6> box = {-10, -10, 0, 11, 10, 10};  ///< xmin,ymin,zmin,xmax,ymax,zmax; zmin = 0 on the plane (naca.box)
  std::string units = "chord";                            ///< unit label of all coordinates (naca.units)
  bool revolution = false;  ///< naca.shape = revolution: a body of revolution, not a wing (naca.shape)
  bool round_tip = false;   ///< naca.tip = round: the tip section revolved about its camber line (naca.tip)
  bool fuselage = false;       ///< naca.wall = cylinder or cone: a fuselage about the streamwise axis (naca.wall)
  double wall_radius = 1.5;    ///< its radius at x = 0; naca_params_from's default is 1.5 naca.chord (naca.wall_radius)
  double wall_angle_deg = 0.0; ///< the cone's half angle, radius growing downstream; 0: the cylinder (naca.wall_angle)
};

/// The far-field box of a fuselage when naca.box is not given: x as the plane's default, y and z
/// 10 beyond the fuselage's largest radius r_max in that x range,
/// {-10, -r_max - 10, -R - r_max - 10, 11, r_max + 10, 10} (a cylinder: r_max = R).
std::array<double, 6> fuselage_default_box(double wall_radius, double wall_angle_deg);

/// Reads the naca.* keys of `p` (unknown keys are errors) over the defaults and validates them.
/// Throws cad::CadError(BadParameter) naming the key, its value and what was expected.
NacaWingParams naca_params_from(const cad::Params& p);

/// Builds the finalized model. Throws cad::CadError(BadParameter) on invalid parameters.
std::unique_ptr<cad::Model> make_naca_wing(const NacaWingParams& params);

/// Registry factory of backend "naca": parameters only; a non-empty path is an error.
std::unique_ptr<cad::Model> load_naca(const cad::Source& source);

}  // namespace semimesh::mock_cad
