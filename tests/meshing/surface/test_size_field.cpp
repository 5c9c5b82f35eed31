#include "semimesh/surface/error.hpp"
#include "semimesh/surface/size_field.hpp"
#include "wing_fixture.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

namespace semimesh::surface {
namespace {

using testing::naca_model;

SizeParams no_curvature() {
  SizeParams p;
  p.max_size = 1.0;
  p.min_size = 0.001;
  p.curvature_segments = 0.0;
  p.le_size = 0.0;  // no sources unless a test adds them
  p.te_size = 0.0;
  return p;
}

TEST(SizeField, WithoutSourcesIsTheMaximum) {
  auto model = naca_model();
  SizeField size(*model, no_curvature());
  EXPECT_EQ(size.num_sources(), 0);
  EXPECT_DOUBLE_EQ(size(Vec3(0.3, 0.0, 1.0)), 1.0);
  EXPECT_DOUBLE_EQ(size(Vec3(-9, 9, 9)), 1.0);
}

TEST(SizeField, PointSourceGrowsWithTheGradation) {
  auto model = naca_model();
  SizeParams p = no_curvature();
  p.gradation = 1.2;
  p.point_sources.push_back({Vec3(2, 0, 1), 0.05});
  SizeField size(*model, p);
  EXPECT_NEAR(size(Vec3(2, 0, 1)), 0.05, 1e-12);
  EXPECT_NEAR(size(Vec3(2, 1, 1)), 0.05 + 0.2 * 1.0, 1e-12);
  EXPECT_NEAR(size(Vec3(2, 0, 4)), 0.05 + 0.2 * 3.0, 1e-12);
  EXPECT_NEAR(size(Vec3(8, 0, 1)), 1.0, 1e-12);  // capped by max_size
}

// The tree's query (nearer child first, boxes pruned) against the minimum over every source, on a
// field built from sources alone (no model: the far field's interior points use it so).
TEST(SizeField, TreeQueryIsTheMinimumOverEverySource) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  SizeParams p = no_curvature();
  p.gradation = 1.6;
  p.max_size = 2.0;
  for (int i = 0; i < 3000; ++i)  // a thin shell of sources round a sphere, sizes 0.01-0.1
    p.point_sources.push_back({Vec3(unit(rng) - 0.5, unit(rng) - 0.5, unit(rng) - 0.5).normalized(), 0.01 + 0.09 * unit(rng)});
  const SizeField size(p);
  EXPECT_EQ(size.num_sources(), 3000);
  for (int i = 0; i < 2000; ++i) {
    const Vec3 x = 4.0 * Vec3(unit(rng) - 0.5, unit(rng) - 0.5, unit(rng) - 0.5);
    double expected = p.max_size;
    for (const PointSource& s : p.point_sources) expected = std::min(expected, s.size + (p.gradation - 1.0) * (x - s.center).norm());
    ASSERT_EQ(size(x), std::clamp(expected, p.min_size, p.max_size)) << x.transpose();
  }
}

TEST(SizeField, BoxSourceIsConstantInsideAndGradedOutside) {
  auto model = naca_model();
  SizeParams p = no_curvature();
  p.gradation = 1.5;
  p.box_sources.push_back({Vec3(0, -1, 0), Vec3(2, 1, 3), 0.1});
  SizeField size(*model, p);
  EXPECT_NEAR(size(Vec3(1, 0, 2)), 0.1, 1e-12);
  EXPECT_NEAR(size(Vec3(3, 0, 2)), 0.1 + 0.5 * 1.0, 1e-12);
}

TEST(SizeField, SizesBelowTheMinimumAreNamedInAWarning) {
  SizeParams p = no_curvature();
  p.min_size = 0.03;
  EXPECT_TRUE(size_warnings(p).empty());  // le/te sizes off
  p.le_size = 0.05, p.te_size = 0.02;
  p.curve_sources.push_back({"tip_upper", 0.01});
  const auto w = size_warnings(p);
  ASSERT_EQ(w.size(), 2u);
  EXPECT_NE(w[0].find("sizing.te_size = 0.02 is below sizing.min_size = 0.03"), std::string::npos) << w[0];
  EXPECT_NE(w[1].find("'tip_upper'"), std::string::npos) << w[1];
}

TEST(SizeField, MinSizeBoundsEverySource) {
  auto model = naca_model();
  SizeParams p = no_curvature();
  p.min_size = 0.02;
  p.point_sources.push_back({Vec3(0, 0, 0), 1e-6});
  SizeField size(*model, p);
  EXPECT_NEAR(size(Vec3(0, 0, 0)), 0.02, 1e-12);
}

TEST(SizeField, LeadingEdgeCurvatureGivesRadiusOverSegments) {
  auto model = naca_model();
  SizeParams p;
  p.max_size = 1.0;
  p.min_size = 1e-4;
  p.curvature_segments = 2.0;
  SizeField size(*model, p);
  // NACA 4-digit leading-edge radius 1.1019 t^2 c (Abbott & von Doenhoff, sec. 6.4).
  const double radius = 1.1019 * 0.12 * 0.12;
  EXPECT_NEAR(size(Vec3(0, 0, 1.5)), radius / 2.0, 0.05 * radius / 2.0);
  // Far from the wing the size grows back to the maximum.
  EXPECT_DOUBLE_EQ(size(Vec3(-9, 9, 9)), 1.0);
}

TEST(SizeField, LeadingEdgeSourceFollowsTheNamedCurve) {
  auto model = naca_model();
  SizeParams p = no_curvature();
  p.le_size = 0.01;
  SizeField size(*model, p);
  for (double z : {0.0, 0.77, 1.5, 2.9}) EXPECT_LE(size(Vec3(0, 0, z)), 0.01 * 1.01) << z;
  EXPECT_GT(size(Vec3(1.0, 0, 1.5)), 0.1);
}

TEST(SizeField, RejectsBadParameters) {
  auto model = naca_model();
  SizeParams p = no_curvature();
  p.max_size = -1.0;
  EXPECT_THROW(SizeField(*model, p), SurfaceMeshError);
  p = no_curvature();
  p.gradation = 0.9;
  EXPECT_THROW(SizeField(*model, p), SurfaceMeshError);
  p = no_curvature();
  p.curve_sources.push_back({"no_such_curve", 0.1});
  try {
    SizeField field(*model, p);
    FAIL() << "expected an error";
  } catch (const SurfaceMeshError& e) {
    EXPECT_NE(std::string(e.what()).find("no_such_curve"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace semimesh::surface
