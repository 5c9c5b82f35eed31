// The fuselage of naca.wall = cylinder (src/fuselage_wall.hpp): the model's faces and curves, its
// watertightness, the wall's periodic parameters, normals, trim and projections, and the box with
// the fuselage's circles as holes.
#include "surface_names.hpp"
#include "naca_reference.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace {

using semimesh::cad::Model;
using semimesh::cad::Params;
using semimesh::cad::Source;
using semimesh::cad::Vec2;
using semimesh::cad::Vec3;
using semimesh::mock_cad::load_naca;

constexpr double kRadius = 1.5;  // the default: 1.5 root chords

std::unique_ptr<Model> default_on_cylinder(const std::string& te = "blunt") {
  return load_naca(Source{"", Params{{"naca.wall", "cylinder"}, {"naca.te", te}}});
}

using naca_test::surface_names;

TEST(FuselageWall, FacesInTheDocumentedOrder) {
  const std::vector<std::string> blunt = {"upper",    "lower",    "te_base",  "tip",      "wall",    "box_xmin",
                                          "box_xmax", "box_ymin", "box_ymax", "box_zmin", "box_zmax"};
  EXPECT_EQ(surface_names(*default_on_cylinder()), blunt);
  auto sharp = blunt;
  sharp.erase(sharp.begin() + 2);
  EXPECT_EQ(surface_names(*default_on_cylinder("sharp")), sharp);
}

TEST(FuselageWall, DefaultsAndBox) {
  const auto p = semimesh::mock_cad::naca_params_from(Params{{"naca.wall", "cylinder"}, {"naca.chord", "2"}});
  EXPECT_TRUE(p.fuselage);
  EXPECT_EQ(p.wall_radius, 3.0);  // 1.5 root chords
  EXPECT_EQ(p.box, (std::array<double, 6>{-10, -13, -16, 11, 13, 10}));
  auto model = default_on_cylinder();
  const auto& box = model->bbox();
  EXPECT_NEAR(box.lo.z(), -2 * kRadius - 10, 1e-9);
  EXPECT_NEAR(box.hi.z(), 10, 1e-9);
}

// Every curve bounds two faces once each way; the seam bounds the wall twice.
TEST(FuselageWall, ModelIsWatertight) {
  for (const char* te : {"blunt", "sharp"}) {
    auto model = default_on_cylinder(te);
    EXPECT_TRUE(model->is_closed()) << te;
    const int wall = naca_test::surface_id(*model, "wall");
    for (int c = 0; c < model->num_curves(); ++c) {
      const auto& uses = model->surfaces_of_curve(c);
      ASSERT_EQ(uses.size(), 2u) << te << " curve " << model->curve(c).name();
      EXPECT_NE(uses[0].forward, uses[1].forward) << te << " curve " << model->curve(c).name();
    }
    const int seam = naca_test::curve_id(*model, "wall_seam");
    EXPECT_TRUE(model->is_seam(wall, seam));
    for (const char* root : {"root_upper", "root_lower"}) {
      const auto& uses = model->surfaces_of_curve(naca_test::curve_id(*model, root));
      EXPECT_TRUE(uses[0].surface == wall || uses[1].surface == wall) << root << " bounds the wall";
    }
    for (const char* circle : {"wall_xmin", "wall_xmax"}) {
      const int c = naca_test::curve_id(*model, circle);
      const auto ends = model->curve_vertices(c);
      EXPECT_EQ(ends[0], ends[1]) << circle << " is closed";
      EXPECT_EQ(model->vertex(ends[0]).point.z(), -2 * kRadius) << circle << " starts at the bottom";
    }
  }
}

TEST(FuselageWall, WallIsAPeriodicCylinderWithOutwardNormals) {
  auto model = default_on_cylinder();
  const auto& wall = model->surface(naca_test::surface_id(*model, "wall"));
  EXPECT_FALSE(wall.is_planar());
  ASSERT_TRUE(wall.period(1).has_value());
  EXPECT_EQ(*wall.period(1), 2 * M_PI);
  EXPECT_FALSE(wall.period(0).has_value());
  EXPECT_EQ(wall.bounds()[0].lo, -10.0);
  EXPECT_EQ(wall.bounds()[0].hi, 11.0);
  // Crest (phi = pi), -y side (pi / 2), bottom seam (0): on the cylinder, normal away from the axis.
  for (double phi : {0.0, 0.3, M_PI / 2, M_PI, 4.0, 2 * M_PI})
    for (double x : {-7.0, 5.0}) {
      const Vec3 p = wall.point(Vec2(x, phi));
      const Vec3 radial = Vec3(0, p.y(), p.z() + kRadius) / kRadius;
      EXPECT_NEAR(radial.norm(), 1.0, 1e-15) << "phi = " << phi;
      EXPECT_LE((wall.normal(Vec2(x, phi)) - radial).norm(), 1e-15) << "phi = " << phi;
      const auto k = wall.curvatures(Vec2(x, phi));
      EXPECT_NEAR(k.k_max, 1.0 / kRadius, 1e-13);  // convex fuselage: positive against the fluid normal
      EXPECT_NEAR(k.k_min, 0.0, 1e-13);
    }
  EXPECT_LE((wall.point(Vec2(1.0, M_PI)) - Vec3(1.0, 0.0, 0.0)).norm(), 1e-15);              // the crest
  EXPECT_LE((wall.point(Vec2(1.0, M_PI / 2)) - Vec3(1.0, -kRadius, -kRadius)).norm(), 1e-15);  // -y first
  EXPECT_LE((wall.point(Vec2(1.0, 0.0)) - Vec3(1.0, 0.0, -2 * kRadius)).norm(), 1e-15);      // the seam
}

// The root section is a hole of the wall; the rest of the cylinder is in the face.
TEST(FuselageWall, TrimHoldsTheRootSectionAsAHole) {
  for (const char* te : {"blunt", "sharp"}) {
    auto model = default_on_cylinder(te);
    const auto& wall = model->surface(naca_test::surface_id(*model, "wall"));
    EXPECT_FALSE(wall.contains(Vec2(0.3, M_PI))) << te;   // under the wing's thickest part
    EXPECT_FALSE(wall.contains(Vec2(0.95, M_PI))) << te;  // near the trailing edge, inside
    EXPECT_TRUE(wall.contains(Vec2(-0.01, M_PI))) << te;  // ahead of the leading edge
    EXPECT_TRUE(wall.contains(Vec2(1.02, M_PI))) << te;   // behind the trailing edge
    EXPECT_TRUE(wall.contains(Vec2(0.3, M_PI + 0.1))) << te;  // beside the section (y = 0.15 > 0.06)
    EXPECT_TRUE(wall.contains(Vec2(0.3, 0.2))) << te;    // the far side of the fuselage
    EXPECT_FALSE(wall.contains(Vec2(11.5, 1.0))) << te;  // beyond the box
    // Points of the root curves are on the boundary, which counts as inside.
    for (const char* root : {"root_upper", "root_lower"}) {
      const auto& curve = model->curve(naca_test::curve_id(*model, root));
      for (double u : {0.1, 0.5, 0.9}) {
        const auto r = wall.project(curve.point(u));
        EXPECT_LE(r.distance, 1e-15) << te << " " << root << " u = " << u;
        EXPECT_TRUE(r.inside) << te << " " << root << " u = " << u;
      }
    }
  }
}

// Exact projections: off the wall along the normal and back; on the seam, the guess picks its side.
TEST(FuselageWall, Projections) {
  auto model = default_on_cylinder();
  const auto& wall = model->surface(naca_test::surface_id(*model, "wall"));
  for (double phi : {0.4, 2.0, 3.5, 5.9})
    for (double d : {0.0, 0.01, 2.0}) {
      const Vec2 uv(4.0, phi);
      const Vec3 x = wall.point(uv) + d * wall.normal(uv);
      for (const auto& r : {wall.project(x), wall.project(x, Vec2(3.0, phi + 0.5))}) {
        EXPECT_NEAR(r.distance, d, 1e-14) << "phi = " << phi;
        EXPECT_NEAR(r.uv.y(), phi, 1e-14);
        EXPECT_TRUE(r.converged && r.inside);
      }
    }
  const Vec3 bottom(2.0, 0.0, -2 * kRadius - 1.0);
  EXPECT_EQ(wall.project(bottom).uv.y(), 0.0);
  EXPECT_EQ(wall.project(bottom, Vec2(2.0, 6.1)).uv.y(), 2 * M_PI);
  EXPECT_NEAR(wall.project(Vec3(15.0, 0.0, 0.5)).uv.x(), 11.0, 0);  // beyond the box: clamped
  for (const char* circle : {"wall_xmin", "wall_xmax"}) {
    const auto& c = model->curve(naca_test::curve_id(*model, circle));
    EXPECT_NEAR(c.length(), 2 * M_PI * kRadius, 1e-12);
    for (double t : {0.5, 3.0, 6.0}) {  // 10% out from the axis
      const Vec3 x = c.point(t), axis(x.x(), 0.0, -kRadius);
      EXPECT_NEAR(c.project(axis + 1.1 * (x - axis)).t, t, 1e-14) << circle;
    }
  }
}

// The box's ends hold the fuselage's section as a hole; its bottom is a face of its own below the
// fuselage.
TEST(FuselageWall, BoxEndsHaveTheFuselageAsAHole) {
  auto model = default_on_cylinder();
  for (const char* end : {"box_xmin", "box_xmax"}) {
    const int id = naca_test::surface_id(*model, end);
    const auto& face = model->surface(id);
    EXPECT_EQ(model->loops(id).size(), 2u) << end;
    EXPECT_FALSE(face.contains(Vec2(0.0, -kRadius))) << end;        // (y, z) on the axis
    EXPECT_FALSE(face.contains(Vec2(0.0, -0.01))) << end;           // just under the crest
    EXPECT_TRUE(face.contains(Vec2(0.0, 0.01))) << end;             // just above it
    EXPECT_TRUE(face.contains(Vec2(kRadius + 0.01, -kRadius))) << end;
  }
  const auto& bottom = model->surface(naca_test::surface_id(*model, "box_zmin"));
  EXPECT_TRUE(bottom.is_planar());
  EXPECT_LE((bottom.normal(Vec2(0, 0)) - Vec3::UnitZ()).norm(), 0.0);
  EXPECT_EQ(bottom.point(Vec2(0, 0)).z(), -2 * kRadius - 10);
}

// Without the far field the wing alone, its root open on the cylinder.
TEST(FuselageWall, WithoutFarFieldTheWingAlone) {
  auto model = load_naca(Source{"", Params{{"naca.wall", "cylinder"}, {"naca.farfield", "false"}}});
  EXPECT_EQ(surface_names(*model), (std::vector<std::string>{"upper", "lower", "te_base", "tip"}));
  EXPECT_FALSE(model->is_closed());
  EXPECT_LT(model->curve(naca_test::curve_id(*model, "root_upper")).point(0.5).z(), 0.0);
}

// naca.wall = plane is today's model: the same faces and the same numbers.
TEST(FuselageWall, PlaneWallIsUnchanged) {
  auto plain = load_naca(Source{}), explicit_plane = load_naca(Source{"", Params{{"naca.wall", "plane"}}});
  ASSERT_EQ(plain->num_surfaces(), explicit_plane->num_surfaces());
  ASSERT_EQ(plain->num_curves(), explicit_plane->num_curves());
  for (int s = 0; s < plain->num_surfaces(); ++s) {
    EXPECT_EQ(plain->surface(s).name(), explicit_plane->surface(s).name());
    EXPECT_EQ(plain->surface(s).point(Vec2(0.37, 0.41)), explicit_plane->surface(s).point(Vec2(0.37, 0.41)));
  }
  const auto& root = plain->curve(naca_test::curve_id(*plain, "root_upper"));
  EXPECT_EQ(root.point(0.5).z(), 0.0);
}

// The cone: radius R + x tan(angle) about the same axis, its crest through the root's leading edge;
// normals tilted by the half angle; exact projections; the box's end holes of the local radius.
TEST(FuselageWall, ConeWidensDownstream) {
  const double angle = 4.0, k = std::tan(angle * M_PI / 180.0);
  auto model = load_naca(Source{"", Params{{"naca.wall", "cone"}, {"naca.wall_angle", "4"}}});
  EXPECT_TRUE(model->is_closed());
  const auto& wall = model->surface(naca_test::surface_id(*model, "wall"));
  EXPECT_EQ(wall.kind(), semimesh::cad::SurfaceKind::Cone);
  EXPECT_FALSE(wall.is_planar());
  EXPECT_LE(wall.point(Vec2(0.0, M_PI)).norm(), 1e-15);  // the crest through the origin
  for (double x : {-8.0, 0.5, 9.0})
    for (double phi : {0.2, 2.0, M_PI, 5.0}) {
      const Vec2 uv(x, phi);
      const Vec3 p = wall.point(uv);
      EXPECT_NEAR(std::hypot(p.y(), p.z() + kRadius), kRadius + k * x, 1e-14) << x << " " << phi;
      const Vec3 expected = Vec3(-k, -std::sin(phi), -std::cos(phi)) / std::sqrt(1.0 + k * k);
      EXPECT_LE((wall.normal(uv) - expected).norm(), 1e-15) << x << " " << phi;
      for (double d : {0.0, 0.05, 1.0}) {
        const auto r = wall.project(p + d * wall.normal(uv));
        EXPECT_NEAR(r.distance, d, 1e-14) << x << " " << phi << " " << d;
        EXPECT_LE((r.uv - uv).norm(), 1e-13) << x << " " << phi << " " << d;
      }
    }
  const auto box = semimesh::mock_cad::naca_params_from(Params{{"naca.wall", "cone"}}).box;  // 5 degrees by default
  const double r_max = kRadius + 11.0 * std::tan(5.0 * M_PI / 180.0);
  EXPECT_NEAR(box[4], r_max + 10.0, 1e-14);
  EXPECT_NEAR(box[2], -kRadius - r_max - 10.0, 1e-14);
  for (const char* end : {"box_xmin", "box_xmax"}) {
    const double x = std::string(end) == "box_xmin" ? -10.0 : 11.0, r = kRadius + k * x;
    const auto& face = model->surface(naca_test::surface_id(*model, end));
    EXPECT_FALSE(face.contains(Vec2(0.0, -kRadius + r - 0.01))) << end;
    EXPECT_TRUE(face.contains(Vec2(0.0, -kRadius + r + 0.01))) << end;
    const auto& circle = model->curve(naca_test::curve_id(*model, std::string("wall_") + (end + 4)));
    EXPECT_NEAR(circle.length(), 2 * M_PI * r, 1e-12) << end;
  }
}

}  // namespace
