// Exact values at known points, against published ordinates and the textbook formulas.
#include "naca_reference.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace {

using semimesh::cad::Vec2;
using semimesh::cad::Vec3;
using semimesh::mock_cad::NacaWingParams;

NacaWingParams code(const std::string& c, bool sharp = false) {
  NacaWingParams p;
  p.code = c;
  p.sharp_te = sharp;
  return p;
}

// NACA 0012 ordinates in percent of chord, Abbott & von Doenhoff (1959), Appendix I.
struct Ordinate {
  double station, half_thickness;
};
constexpr Ordinate kNaca0012Table[] = {{1.25, 1.894}, {2.5, 2.615}, {5.0, 3.555}, {7.5, 4.200}, {10, 4.683},
                                       {15, 5.345},   {20, 5.737},  {25, 5.941},  {30, 6.002},  {40, 5.803},
                                       {50, 5.294},   {60, 4.563},  {70, 3.664},  {80, 2.623},  {90, 1.448},
                                       {95, 0.807},   {100, 0.126}};

TEST(NacaValues, Naca0012MatchesPublishedOrdinates) {
  auto model = naca_test::wing(code("0012"));
  const auto& upper = model->surface(naca_test::surface_id(*model, "upper"));
  const auto& lower = model->surface(naca_test::surface_id(*model, "lower"));
  for (const Ordinate& o : kNaca0012Table) {
    const double x = o.station / 100.0;
    const Vec3 pu = upper.point(Vec2(std::sqrt(x), 1.0)), pl = lower.point(Vec2(std::sqrt(x), 1.0));
    EXPECT_NEAR(pu.x(), x, 1e-14);
    EXPECT_NEAR(pu.y(), o.half_thickness / 100.0, 1e-5) << "station " << o.station << "%";
    EXPECT_NEAR(pl.y(), -o.half_thickness / 100.0, 1e-5) << "station " << o.station << "%";
    EXPECT_DOUBLE_EQ(pu.z(), 1.0);
  }
  // The brief's reference value: half thickness 0.06002 at x = 0.3.
  EXPECT_NEAR(upper.point(Vec2(std::sqrt(0.3), 0.0)).y(), 0.06002, 5e-6);
}

TEST(NacaValues, BluntTrailingEdgeIsTwoTenthsPercentThick) {
  auto model = naca_test::wing(code("0012"));
  const Vec3 up = model->surface(naca_test::surface_id(*model, "upper")).point(Vec2(1.0, 0.0));
  const Vec3 lo = model->surface(naca_test::surface_id(*model, "lower")).point(Vec2(1.0, 0.0));
  // 2 * 5 * 0.12 * (0.2969 - 0.1260 - 0.3516 + 0.2843 - 0.1015) = 1.2 * 0.0021
  EXPECT_NEAR((up - lo).norm(), 0.00252, 1e-12);
  EXPECT_NEAR(up.x(), 1.0, 1e-15);
}

TEST(NacaValues, SharpTrailingEdgeCloses) {
  // 0.2969 - 0.1260 - 0.3516 + 0.2843 - 0.1036 = 0 exactly: the TE thickness is round-off only.
  for (const char* c : {"0012", "2412", "4415"}) {
    auto model = naca_test::wing(code(c, true));
    const Vec3 up = model->surface(naca_test::surface_id(*model, "upper")).point(Vec2(1.0, 2.0));
    const Vec3 lo = model->surface(naca_test::surface_id(*model, "lower")).point(Vec2(1.0, 2.0));
    EXPECT_LT((up - lo).norm(), 1e-15) << c;
    EXPECT_FALSE(model->find_surface("te_base").has_value());
  }
}

TEST(NacaValues, CamberedSectionMatchesTextbookFormulas) {
  auto model = naca_test::wing(code("2412"));
  const auto& upper = model->surface(naca_test::surface_id(*model, "upper"));
  const auto& lower = model->surface(naca_test::surface_id(*model, "lower"));
  for (double x : {0.001, 0.05, 0.2, 0.39, 0.41, 0.6, 0.9, 1.0}) {
    const Vec3 pu = upper.point(Vec2(std::sqrt(x), 0.0)), pl = lower.point(Vec2(std::sqrt(x), 0.0));
    const auto ru = naca_test::surface_point(0.02, 0.4, 0.12, x, true, false);
    const auto rl = naca_test::surface_point(0.02, 0.4, 0.12, x, false, false);
    EXPECT_NEAR(pu.x(), ru.x, 1e-14) << x;
    EXPECT_NEAR(pu.y(), ru.y, 1e-14) << x;
    EXPECT_NEAR(pl.x(), rl.x, 1e-14) << x;
    EXPECT_NEAR(pl.y(), rl.y, 1e-14) << x;
    // Upper above and lower below the camber line, which is their midpoint.
    const double yc = naca_test::camber(0.02, 0.4, x);
    EXPECT_NEAR(0.5 * (pu.y() + pl.y()), yc, 1e-15) << x;
    if (x < 1.0) {
      EXPECT_GT(pu.y(), yc) << x;
      EXPECT_LT(pl.y(), yc) << x;
    }
  }
  // Maximum camber 2% at 40% chord.
  EXPECT_NEAR(naca_test::camber(0.02, 0.4, 0.4), 0.02, 1e-15);
}

TEST(NacaValues, TaperAndSweepPlaceTheTip) {
  NacaWingParams p;
  p.chord = 2.0;
  p.span = 3.0;
  p.taper = 0.5;
  p.sweep_deg = 30.0;
  p.box = {-10, -10, 0, 12, 10, 10};
  auto model = naca_test::wing(p);
  const double x_le = 3.0 * std::tan(30.0 * M_PI / 180.0);
  const auto& le = model->curve(naca_test::curve_id(*model, "leading_edge"));
  EXPECT_LT((le.point(3.0) - Vec3(x_le, 0.0, 3.0)).norm(), 1e-14);
  EXPECT_LT((le.point(0.0) - Vec3(0.0, 0.0, 0.0)).norm(), 1e-15);
  // Tip chord 1 (taper 0.5 of 2): the symmetric section's TE is at x_le + 1.
  const auto& tip_upper = model->curve(naca_test::curve_id(*model, "tip_upper"));
  EXPECT_NEAR(tip_upper.point(1.0).x(), x_le + 1.0, 1e-14);
  EXPECT_NEAR(tip_upper.point(std::sqrt(0.3)).y(), 0.06002, 1e-5);  // scaled by the tip chord 1
  // Mid-span: chord 1.5, LE at half the tip offset.
  const auto& upper = model->surface(naca_test::surface_id(*model, "upper"));
  EXPECT_NEAR(upper.point(Vec2(1.0, 1.5)).x(), 0.5 * x_le + 1.5, 1e-14);
  for (int v = 0; v < model->num_vertices(); ++v)
    if (model->vertex(v).name == "tip_le") {
      EXPECT_LT((model->vertex(v).point - Vec3(x_le, 0, 3)).norm(), 1e-14);
    }
}

TEST(NacaValues, LeadingEdgeCurvatureMatchesTheLeadingEdgeRadius) {
  // r_LE = 1.1019 t^2 c (Abbott & von Doenhoff eq. 6.3).
  for (double chord : {1.0, 2.5}) {
    NacaWingParams p = code("0012");
    p.chord = chord;
    p.box = {-10, -10, 0, 14, 10, 10};
    auto model = naca_test::wing(p);
    const double radius = 1.1019 * 0.12 * 0.12 * chord;
    const auto& root_upper = model->curve(naca_test::curve_id(*model, "root_upper"));
    EXPECT_NEAR(root_upper.curvature(0.0) * radius, 1.0, 1e-4) << chord;
    const auto k = model->surface(naca_test::surface_id(*model, "upper")).curvatures(Vec2(0.0, 1.5));
    EXPECT_NEAR(k.k_max * radius, 1.0, 1e-4) << chord;  // convex: positive against the fluid normal
    EXPECT_NEAR(k.k_min, 0.0, 1e-9) << chord;            // straight along the span
  }
}

}  // namespace
