// Names, ids, watertightness and loop orientation (material on the left seen from the fluid).
#include "surface_names.hpp"
#include "naca_reference.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace {

using semimesh::cad::Vec2;
using semimesh::cad::Vec3;
using semimesh::mock_cad::NacaWingParams;

NacaWingParams variant(bool sharp, bool farfield) {
  NacaWingParams p;
  p.code = "4415";
  p.taper = 0.4;
  p.sweep_deg = 35.0;
  p.sharp_te = sharp;
  p.farfield = farfield;
  return p;
}

using naca_test::surface_names;

TEST(NacaTopology, SurfacesInTheDocumentedOrder) {
  using V = std::vector<std::string>;
  EXPECT_EQ(surface_names(*naca_test::wing(variant(false, true))),
            (V{"upper", "lower", "te_base", "tip", "wall", "box_xmin", "box_xmax", "box_ymin", "box_ymax", "box_zmax"}));
  EXPECT_EQ(surface_names(*naca_test::wing(variant(true, true))),
            (V{"upper", "lower", "tip", "wall", "box_xmin", "box_xmax", "box_ymin", "box_ymax", "box_zmax"}));
  EXPECT_EQ(surface_names(*naca_test::wing(variant(false, false))), (V{"upper", "lower", "te_base", "tip"}));
  EXPECT_EQ(surface_names(*naca_test::wing(variant(true, false))), (V{"upper", "lower", "tip"}));
}

TEST(NacaTopology, FarFieldModelIsWatertight) {
  for (bool sharp : {false, true}) {
    auto model = naca_test::wing(variant(sharp, true));
    EXPECT_TRUE(model->is_closed());
    EXPECT_EQ(model->num_curves(), (sharp ? 6 : 9) + 12);
    EXPECT_EQ(model->num_vertices(), (sharp ? 4 : 6) + 8);
    for (int c = 0; c < model->num_curves(); ++c) {
      const auto& uses = model->surfaces_of_curve(c);
      ASSERT_EQ(uses.size(), 2u) << model->curve(c).name();
      EXPECT_NE(uses[0].surface, uses[1].surface) << model->curve(c).name();
      EXPECT_NE(uses[0].forward, uses[1].forward) << model->curve(c).name() << ": not consistently oriented";
    }
    // Euler characteristic of the fluid's boundary, a sphere (box, wall and wing are one closed
    // surface): V - E + F - H = 2, where the wall's hole H = 1 makes that face an annulus.
    EXPECT_EQ(model->num_vertices() - model->num_curves() + model->num_surfaces() - 1, 2);
  }
}

TEST(NacaTopology, CurveEndsAreTheirVertices) {
  auto model = naca_test::wing(variant(false, true));
  for (int c = 0; c < model->num_curves(); ++c) {
    const auto& curve = model->curve(c);
    const auto ends = model->curve_vertices(c);
    EXPECT_LT((curve.point(curve.bounds().lo) - model->vertex(ends[0]).point).norm(), 1e-14) << curve.name();
    EXPECT_LT((curve.point(curve.bounds().hi) - model->vertex(ends[1]).point).norm(), 1e-14) << curve.name();
  }
  EXPECT_EQ(model->loops(naca_test::surface_id(*model, "wall")).size(), 2u);  // box rectangle + root hole
}

TEST(NacaTopology, LoopsKeepTheFaceOnTheirLeft) {
  // At the middle of each curve use: one small step to the left (normal x walking tangent) lands
  // on the face, one to the right leaves it (off the parameter box or into a hole).
  for (bool sharp : {false, true}) {
    auto model = naca_test::wing(variant(sharp, true));
    for (int s = 0; s < model->num_surfaces(); ++s) {
      const auto& surf = model->surface(s);
      for (const auto& loop : model->loops(s))
        for (const auto& use : loop.uses) {
          const auto& curve = model->curve(use.curve);
          const double t = 0.5 * (curve.bounds().lo + curve.bounds().hi);
          const Vec3 p = curve.point(t);
          const Vec3 walk = (use.forward ? 1.0 : -1.0) * curve.tangent(t);
          const auto foot = surf.project(p);
          ASSERT_LT(foot.distance, 1e-12) << curve.name() << " on " << surf.name();
          const Vec3 left = surf.normal(foot.uv).cross(walk).normalized();
          const double eps = 1e-5;
          const auto in = surf.project(p + eps * left), out = surf.project(p - eps * left);
          const std::string what = curve.name() + " in a loop of " + surf.name();
          EXPECT_TRUE(in.inside && in.distance < 0.01 * eps) << what;
          EXPECT_TRUE(!out.inside || out.distance > 0.5 * eps) << what;
        }
    }
  }
}

TEST(NacaTopology, BoundingBoxIsTheFarFieldBox) {
  auto model = naca_test::wing(variant(false, true));
  EXPECT_LT((model->bbox().lo - Vec3(-10, -10, 0)).norm(), 1e-12);
  EXPECT_LT((model->bbox().hi - Vec3(11, 10, 10)).norm(), 1e-12);
}

}  // namespace
