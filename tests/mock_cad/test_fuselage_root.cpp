// The wing's root on a streamwise cylinder (naca.wall = cylinder, src/fuselage_root.hpp): the root
// curves lie on the cylinder and on the wing's skins, checked against the independent textbook
// section (naca_reference.hpp) and the closed form of the untapered, unswept case; exact derivatives
// of the root curves and of the reparametrised surfaces against central differences; projections.
#include "central_differences.hpp"
#include "naca_reference.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace {

using semimesh::cad::Model;
using semimesh::cad::Vec2;
using semimesh::cad::Vec3;
using semimesh::mock_cad::NacaWingParams;


NacaWingParams on_cylinder(const std::string& code, bool sharp, double taper, double sweep, double radius,
                           double dihedral = 0.0, double cone_angle = 0.0) {
  NacaWingParams p;
  p.dihedral_deg = dihedral;
  p.wall_angle_deg = cone_angle;
  p.code = code;
  p.sharp_te = sharp;
  p.taper = taper;
  p.sweep_deg = sweep;
  p.span = 2.0;
  p.chord = 1.3;
  p.fuselage = true;
  p.wall_radius = radius;
  p.box = semimesh::mock_cad::fuselage_default_box(radius, cone_angle);
  return p;
}

// A cone of 12 degrees reaches its apex inside the default box: a short box.
NacaWingParams steep_cone() {
  NacaWingParams p = on_cylinder("4415", false, 0.8, -10.0, 2.0, 0.0, 12.0);
  p.box = {-2, -6, -10, 4, 6, 6};
  return p;
}

// The variants the checks run on: symmetric and cambered, blunt and sharp, tapered both ways, swept
// both ways, with dihedral both ways, radii from 0.6 to 15 root chords; cylinders and cones
// widening and narrowing downstream.
std::vector<NacaWingParams> variants() {
  return {on_cylinder("0012", false, 1.0, 0.0, 1.5),           on_cylinder("2412", true, 0.5, 25.0, 0.8),
          on_cylinder("4415", false, 1.4, -15.0, 0.8),         on_cylinder("0009", true, 0.3, 40.0, 20.0),
          on_cylinder("2412", false, 0.7, 10.0, 0.9, 20.0),    on_cylinder("0015", true, 1.0, 0.0, 1.2, -30.0),
          on_cylinder("0012", false, 1.0, 0.0, 1.5, 0.0, 4.0), on_cylinder("2412", true, 0.6, 20.0, 1.3, 10.0, -3.0),
          steep_cone()};
}

std::string describe(const NacaWingParams& p) {
  return p.code + (p.sharp_te ? " sharp" : " blunt") + " taper " + std::to_string(p.taper) + " sweep " +
         std::to_string(p.sweep_deg) + " dihedral " + std::to_string(p.dihedral_deg) + " R " + std::to_string(p.wall_radius) +
         " cone " + std::to_string(p.wall_angle_deg);
}

double chord_at(const NacaWingParams& p, double z) { return p.chord * (1.0 - (1.0 - p.taper) * z / p.span); }
double le_x_at(const NacaWingParams& p, double z) { return z * std::tan(p.sweep_deg * M_PI / 180.0); }
double le_y_at(const NacaWingParams& p, double z) { return z * std::tan(p.dihedral_deg * M_PI / 180.0); }

// Distance (radially) of x from the fuselage y^2 + (z + R)^2 = r(x)^2, r(x) = R + x tan(cone angle).
double off_fuselage(const NacaWingParams& p, const Vec3& x) {
  const double r = p.wall_radius + x.x() * std::tan(p.wall_angle_deg * M_PI / 180.0);
  return std::abs(std::hypot(x.y(), x.z() + p.wall_radius) - r);
}

// Distance of x, a point of the skin at chordwise station u^2, from the textbook section scaled and
// shifted to the height of x.
double off_skin(const NacaWingParams& p, double u, bool upper, const Vec3& x) {
  const double m = (p.code[0] - '0') / 100.0, pos = (p.code[1] - '0') / 10.0, t = std::stoi(p.code.substr(2)) / 100.0;
  const naca_test::Point2 s = naca_test::surface_point(m, pos, t, u * u, upper, p.sharp_te);
  const double c = chord_at(p, x.z());
  return std::hypot(x.x() - (le_x_at(p, x.z()) + c * s.x), x.y() - (le_y_at(p, x.z()) + c * s.y));
}

TEST(FuselageRoot, RootCurvesLieOnTheFuselageAndOnTheSkins) {
  for (const NacaWingParams& p : variants()) {
    auto model = naca_test::wing(p);
    for (const bool upper : {true, false}) {
      const auto& curve = model->curve(naca_test::curve_id(*model, upper ? "root_upper" : "root_lower"));
      for (int k = 0; k <= 200; ++k) {
        const double u = k / 200.0;
        const Vec3 x = curve.point(u);
        const std::string at = describe(p) + ", " + curve.name() + " at u = " + std::to_string(u);
        EXPECT_LE(off_fuselage(p, x), 1e-13 * p.chord) << at;
        EXPECT_LE(off_skin(p, u, upper, x), 1e-13 * p.chord) << at;
        if (p.wall_angle_deg == 0.0) {
          EXPECT_LE(x.z(), 0.0) << at << ": the root is under the crest";
        }
        EXPECT_LE((curve.derivatives(u).p - x).norm(), 1e-15) << at;
      }
    }
  }
}

// The blunt base's root runs across the base plane between the trailing-edge corners, on the fuselage.
TEST(FuselageRoot, BaseRootLiesOnTheFuselageAndTheBase) {
  for (const NacaWingParams& p : variants()) {
    if (p.sharp_te) continue;
    auto model = naca_test::wing(p);
    const auto& curve = model->curve(naca_test::curve_id(*model, "root_te"));
    const auto& base = model->surface(naca_test::surface_id(*model, "te_base"));
    const Vec3 lower = model->curve(naca_test::curve_id(*model, "root_lower")).point(1.0);
    const Vec3 upper = model->curve(naca_test::curve_id(*model, "root_upper")).point(1.0);
    EXPECT_LE((curve.point(0.0) - lower).norm(), 1e-15) << describe(p);
    EXPECT_LE((curve.point(1.0) - upper).norm(), 1e-15) << describe(p);
    // The base plane: through the trailing-edge corners at the tip and the root's lower corner.
    const Vec3 tip_lower = model->curve(naca_test::curve_id(*model, "tip_te")).point(0.0);
    const Vec3 tip_upper = model->curve(naca_test::curve_id(*model, "tip_te")).point(1.0);
    const Vec3 n = (tip_upper - tip_lower).cross(lower - tip_lower).normalized();
    for (int k = 0; k <= 50; ++k) {
      const double s = k / 50.0;
      const Vec3 x = curve.point(s);
      EXPECT_LE(off_fuselage(p, x), 1e-13 * p.chord) << describe(p) << " s = " << s;
      EXPECT_LE(std::abs((x - tip_lower).dot(n)), 1e-13 * p.chord) << describe(p) << " s = " << s;
      EXPECT_LE((base.point(Vec2(s, 0.0)) - x).norm(), 1e-15) << describe(p) << " s = " << s;
    }
  }
}

// Untapered and unswept, the section does not change with height: z_root = sqrt(R^2 - y^2) - R.
TEST(FuselageRoot, UntaperedRootHeightIsTheClosedForm) {
  for (double radius : {0.35, 1.5, 7.0}) {
    auto p = on_cylinder("0012", false, 1.0, 0.0, radius);
    auto model = naca_test::wing(p);
    const auto& curve = model->curve(naca_test::curve_id(*model, "root_upper"));
    for (int k = 0; k <= 100; ++k) {
      const double u = k / 100.0;
      const double y = p.chord * naca_test::surface_point(0, 0, 0.12, u * u, true, false).y;
      const Vec3 x = curve.point(u);
      EXPECT_NEAR(x.z(), std::sqrt(radius * radius - y * y) - radius, 2e-15 * radius) << "R = " << radius << ", u = " << u;
      EXPECT_NEAR(x.y(), y, 1e-15) << "R = " << radius << ", u = " << u;
    }
  }
}

// The leading edge and, sharp and without dihedral, the trailing edge stand on the crest line, where
// y = 0 (the dihedral shifts the sections by y_le(z) = z tan(dihedral), zero at the leading edge's z = 0).
TEST(FuselageRoot, EdgesStandOnTheCrest) {
  for (const NacaWingParams& p : variants()) {
    auto model = naca_test::wing(p);
    const auto& le = model->curve(naca_test::curve_id(*model, "leading_edge"));
    EXPECT_EQ(le.point(0.0), Vec3::Zero()) << describe(p);
    if (p.sharp_te && p.dihedral_deg == 0.0) {  // on the crest line, which a cone lifts by x tan(angle)
      const Vec3 te = model->curve(naca_test::curve_id(*model, "trailing_edge")).point(0.0);
      EXPECT_NEAR(te.y(), 0.0, 1e-16) << describe(p);
      EXPECT_NEAR(te.z(), te.x() * std::tan(p.wall_angle_deg * M_PI / 180.0), 1e-15) << describe(p);
    }
  }
}

// The dihedral shears the wing sideways: the tip section is the root's shifted by span tan(dihedral),
// on a plane wall as on the cylinder; and it is the wing's own shift, not a tilt of the root.
TEST(FuselageRoot, DihedralShiftsTheSectionsSideways) {
  for (const bool cylinder : {false, true}) {
    NacaWingParams p = on_cylinder("0012", false, 1.0, 0.0, 1.5, 25.0);
    p.fuselage = cylinder;
    if (!cylinder) p.box = NacaWingParams{}.box;
    auto model = naca_test::wing(p);
    const auto& le = model->curve(naca_test::curve_id(*model, "leading_edge"));
    EXPECT_LE((le.point(p.span) - Vec3(0.0, p.span * std::tan(25.0 * M_PI / 180.0), p.span)).norm(), 1e-14) << cylinder;
    const auto& tip = model->curve(naca_test::curve_id(*model, "tip_upper"));
    for (double u : {0.1, 0.5, 0.9}) EXPECT_LE(off_skin(p, u, true, tip.point(u)), 1e-14) << cylinder << " u = " << u;
    const auto& cap = model->surface(naca_test::surface_id(*model, "tip"));
    const Vec3 inside = 0.5 * (tip.point(0.5) + model->curve(naca_test::curve_id(*model, "tip_lower")).point(0.5));
    EXPECT_TRUE(cap.project(inside).inside) << cylinder;
    const Vec3 unshifted = inside - Vec3(0.0, p.span * std::tan(25.0 * M_PI / 180.0), 0.0);
    EXPECT_FALSE(cap.project(unshifted).inside) << cylinder << ": the section without dihedral";
  }
}

// Away from the camber crease (u^2 = p); a wrong implicit derivative is off by O(1).
TEST(FuselageRoot, RootCurveDerivativesMatchCentralDifferences) {
  constexpr double h = 1e-5;
  for (const NacaWingParams& p : variants()) {
    auto model = naca_test::wing(p);
    for (const char* name : {"root_upper", "root_lower", "root_te"}) {
      if (p.sharp_te && std::string(name) == "root_te") continue;
      const auto& curve = model->curve(naca_test::curve_id(*model, name));
      for (double t : {0.02, 0.13, 0.37, 0.5, 0.81, 0.98}) {
        const auto d = curve.derivatives(t), plus = curve.derivatives(t + h), minus = curve.derivatives(t - h);
        const std::string at = describe(p) + ", " + name + " at t = " + std::to_string(t);
        naca_test::expect_close(d.d1, (plus.p - minus.p) / (2 * h), 1e-8, "d1 " + at);
        naca_test::expect_close(d.d2, (plus.d1 - minus.d1) / (2 * h), 1e-6, "d2 " + at);
      }
    }
  }
}

TEST(FuselageRoot, ReparametrisedSurfacesMatchCentralDifferences) {
  constexpr double kStep = 1e-5;
  for (const NacaWingParams& p : variants()) {
    auto model = naca_test::wing(p);
    for (const char* name : {"upper", "lower", "te_base"}) {
      const auto id = model->find_surface(name);
      if (!id) continue;
      const auto& surf = model->surface(*id);
      const auto box = surf.bounds();
      for (double a : {0.03, 0.31, 0.5, 0.72, 0.97})
        for (double b : {0.0, 0.1, 0.5, 0.9, 1.0}) {
          const double hu = kStep * box[0].length(), hv = kStep * box[1].length();
          // One-sided stations stay inside the box: shift them inwards by one step.
          const Vec2 uv(box[0].lo + a * box[0].length(), std::clamp(box[1].lo + b * box[1].length(), box[1].lo + hv, box[1].hi - hv));
          const std::string at = describe(p) + ", " + name + " at (" + std::to_string(uv.x()) + ", " + std::to_string(uv.y()) + ")";
          naca_test::expect_surface_derivatives_match_differences(surf, uv, hu, hv, at);
        }
    }
  }
}

// v = 0 is the root curve and v = span the tip section, at every chordwise station.
TEST(FuselageRoot, SkinsRunFromTheRootToTheTip) {
  for (const NacaWingParams& p : variants()) {
    auto model = naca_test::wing(p);
    for (const bool upper : {true, false}) {
      const auto& skin = model->surface(naca_test::surface_id(*model, upper ? "upper" : "lower"));
      const auto& root = model->curve(naca_test::curve_id(*model, upper ? "root_upper" : "root_lower"));
      const auto& tip = model->curve(naca_test::curve_id(*model, upper ? "tip_upper" : "tip_lower"));
      for (double u : {0.0, 0.2, 0.55, 0.9, 1.0}) {
        EXPECT_LE((skin.point(Vec2(u, 0.0)) - root.point(u)).norm(), 1e-15) << describe(p) << " u = " << u;
        EXPECT_LE((skin.point(Vec2(u, p.span)) - tip.point(u)).norm(), 1e-15) << describe(p) << " u = " << u;
        EXPECT_EQ(skin.point(Vec2(u, p.span)).z(), p.span) << describe(p) << " u = " << u;
      }
    }
  }
}

// Points on and off the root curves and the skins near the root come back to their parameters,
// with and without a guess.
TEST(FuselageRoot, ProjectionsNearTheRoot) {
  for (const NacaWingParams& p : variants()) {
    auto model = naca_test::wing(p);
    for (const bool upper : {true, false}) {
      const auto& skin = model->surface(naca_test::surface_id(*model, upper ? "upper" : "lower"));
      const auto& root = model->curve(naca_test::curve_id(*model, upper ? "root_upper" : "root_lower"));
      for (double u : {0.05, 0.3, 0.6, 0.95}) {
        const auto c = root.project(root.point(u));
        EXPECT_NEAR(c.t, u, 1e-10) << describe(p) << " u = " << u;
        EXPECT_TRUE(c.converged);
        for (double v : {0.0, 0.01, 0.3}) {
          const Vec2 uv(u, v);
          const Vec3 x = skin.point(uv) + 1e-3 * p.chord * skin.normal(uv);
          for (const auto& r : {skin.project(x), skin.project(x, Vec2(u + 0.02, v + 0.02))}) {
            EXPECT_NEAR(r.distance, 1e-3 * p.chord, 1e-12) << describe(p) << " at (" << u << ", " << v << ")";
            EXPECT_LE((r.uv - uv).norm(), 1e-9) << describe(p) << " at (" << u << ", " << v << ")";
            EXPECT_TRUE(r.inside && r.converged) << describe(p) << " at (" << u << ", " << v << ")";
          }
        }
      }
    }
  }
}

}  // namespace
