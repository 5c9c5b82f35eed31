// Generic Surface algorithms (projection, fluid normal, principal curvatures) on a sphere patch,
// a cylinder and a trimmed plane, whose answers are known in closed form.
#include "shapes.hpp"

#include <gtest/gtest.h>

using shapes::Cylinder;
using shapes::kPi;
using shapes::Plane;
using shapes::SpherePatch;
using shapes::Vec2;
using shapes::Vec3;

namespace {
Vec3 on_unit_sphere(double u, double v) { return Vec3(std::cos(v) * std::cos(u), std::cos(v) * std::sin(u), std::sin(v)); }

Plane unit_disc(int orientation = +1) {
  return Plane(0, Vec3(0, 0, 1), Vec3(1, 0, 0), Vec3(0, 1, 0), {semimesh::cad::Interval{-2, 2}, semimesh::cad::Interval{-2, 2}},
               [](const Vec2& uv) { return uv.squaredNorm() <= 1.0; }, orientation);
}
}  // namespace

TEST(Surface, ProjectOntoSphereRecoversParametersAndDistance) {
  SpherePatch sphere(0, 2.0, +1);
  for (Vec2 uv : {Vec2(0.3, 0.1), Vec2(1.2, -0.6), Vec2(0.8, 0.7)}) {
    for (double r : {2.5, 1.2}) {  // outside and inside the sphere
      auto p = sphere.project(r * on_unit_sphere(uv.x(), uv.y()));
      EXPECT_NEAR(p.uv.x(), uv.x(), 1e-10);
      EXPECT_NEAR(p.uv.y(), uv.y(), 1e-10);
      EXPECT_NEAR(p.distance, std::abs(r - 2.0), 1e-12);
      EXPECT_TRUE(p.converged);
      EXPECT_TRUE(p.inside);
    }
  }
}

TEST(Surface, ProjectWithGuess) {
  SpherePatch sphere(0, 1.0, +1);
  auto p = sphere.project(3.0 * on_unit_sphere(1.0, 0.2), Vec2(0.9, 0.1));
  EXPECT_NEAR(p.uv.x(), 1.0, 1e-10);
  EXPECT_NEAR(p.uv.y(), 0.2, 1e-10);
  EXPECT_NEAR(p.distance, 2.0, 1e-12);
}

TEST(Surface, ProjectNearIsProjectWithoutTheTrimmingTest) {
  Plane disc = unit_disc();
  SpherePatch sphere(0, 1.0, +1);
  for (const semimesh::cad::Surface* s : {static_cast<const semimesh::cad::Surface*>(&disc),
                                          static_cast<const semimesh::cad::Surface*>(&sphere)})
    for (const Vec3& x : {Vec3(0.2, 0.3, 0.5), Vec3(1.5, 0.1, -0.2), Vec3(0.9, 0.9, 2.0)}) {
      const auto full = s->project(x, Vec2(0.1, 0.1)), near = s->project_near(x, Vec2(0.1, 0.1));
      EXPECT_EQ(near.uv, full.uv);
      EXPECT_EQ(near.point, full.point);
      EXPECT_EQ(near.distance, full.distance);
      EXPECT_EQ(near.converged, full.converged);
      EXPECT_FALSE(near.inside);
    }
}

TEST(Surface, ProjectReportsWhetherTheFootIsInsideTheTrim) {
  Plane disc = unit_disc();
  auto in = disc.project(Vec3(0.3, -0.4, 2.0));
  EXPECT_TRUE(in.inside);
  EXPECT_NEAR(in.distance, 1.0, 1e-12);
  EXPECT_TRUE(in.uv.isApprox(Vec2(0.3, -0.4), 1e-12));
  auto out = disc.project(Vec3(1.5, 0.0, 0.0));
  EXPECT_FALSE(out.inside);
  EXPECT_NEAR(out.uv.x(), 1.5, 1e-12);
}

TEST(Surface, OrientationFlagFlipsTheNormal) {
  SpherePatch outward(0, 2.0, +1), inward(1, 2.0, -1);
  Vec3 radial = on_unit_sphere(0.4, 0.3);
  EXPECT_TRUE(outward.normal(Vec2(0.4, 0.3)).isApprox(radial, 1e-14));
  EXPECT_TRUE(inward.normal(Vec2(0.4, 0.3)).isApprox(-radial, 1e-14));
  EXPECT_EQ(outward.orientation(), +1);
  EXPECT_EQ(inward.orientation(), -1);
  EXPECT_TRUE(unit_disc(-1).normal(Vec2(0, 0)).isApprox(Vec3(0, 0, -1)));
}

TEST(Surface, SphereCurvaturesArePlusOneOverRadiusAgainstTheFluidNormal) {
  SpherePatch ball(0, 2.0, +1);    // solid inside the sphere: convex
  SpherePatch cavity(1, 2.0, -1);  // fluid inside the sphere: concave
  auto k = ball.curvatures(Vec2(0.5, 0.2));
  EXPECT_NEAR(k.k_min, 0.5, 1e-12);
  EXPECT_NEAR(k.k_max, 0.5, 1e-12);
  auto c = cavity.curvatures(Vec2(0.5, 0.2));
  EXPECT_NEAR(c.k_min, -0.5, 1e-12);
  EXPECT_NEAR(c.k_max, -0.5, 1e-12);
}

TEST(Surface, CylinderCurvaturesAndDirections) {
  Cylinder cylinder(0, 4.0);
  const double u = 0.7;
  auto k = cylinder.curvatures(Vec2(u, 1.0));
  EXPECT_NEAR(k.k_min, 0.0, 1e-14);
  EXPECT_NEAR(k.k_max, 0.25, 1e-14);
  EXPECT_NEAR(std::abs(k.dir_min.dot(Vec3(0, 0, 1))), 1.0, 1e-12);                       // along the axis
  EXPECT_NEAR(std::abs(k.dir_max.dot(Vec3(-std::sin(u), std::cos(u), 0))), 1.0, 1e-12);  // around it
  EXPECT_NEAR(k.mean(), 0.125, 1e-14);
  EXPECT_NEAR(k.gaussian(), 0.0, 1e-14);
}

TEST(Surface, PlaneIsFlat) {
  Plane disc = unit_disc();
  auto k = disc.curvatures(Vec2(0.2, 0.1));
  EXPECT_DOUBLE_EQ(k.k_min, 0.0);
  EXPECT_DOUBLE_EQ(k.k_max, 0.0);
  EXPECT_TRUE(disc.is_planar());
  EXPECT_FALSE(Cylinder(0, 1.0).is_planar());
}
