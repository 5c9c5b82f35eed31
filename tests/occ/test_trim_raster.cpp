// The trim raster that answers most point-in-face queries of the occ backend: on an analytic ring
// its answers agree with the closed-form test wherever it gives one, and on every face of the
// shared STEP wings and the OCC-built wing contains() agrees with OCC's classifier alone
// (contains_exactly, the slow reference) at random and at near-boundary points.
#include "occ_surface.hpp"
#include "occ_test_support.hpp"
#include "trim_raster.hpp"

#include "semimesh/cad/labels.hpp"
#include "semimesh/occ/occ_backend.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace semimesh::occ {
namespace {

// The ring 0.1 <= |uv - (0.5, 0.5)| <= 0.3 in the unit square.
bool in_ring(const cad::Vec2& uv) {
  const double r = (uv - cad::Vec2(0.5, 0.5)).norm();
  return r >= 0.1 && r <= 0.3;
}

std::vector<cad::Vec2> circle(double radius, double max_step) {
  const int n = static_cast<int>(std::ceil(2 * M_PI * radius / max_step)) + 1;
  std::vector<cad::Vec2> points;
  for (int k = 0; k <= n; ++k)
    points.emplace_back(0.5 + radius * std::cos(2 * M_PI * k / n), 0.5 + radius * std::sin(2 * M_PI * k / n));
  return points;
}

TEST(TrimRaster, AgreesWithTheExactTestOnARingAndClassifiesMostCells) {
  const std::array<cad::Interval, 2> box{cad::Interval{0.0, 1.0}, cad::Interval{0.0, 1.0}};
  TrimRaster raster(box, 64);
  const double step = 0.5 * raster.cell_size().minCoeff();
  raster.mark_loop(circle(0.3, step), 2);
  raster.mark_loop(circle(0.1, step), 2);
  int exact_calls = 0;
  raster.classify([&](const cad::Vec2& uv) {
    ++exact_calls;
    return in_ring(uv);
  });
  EXPECT_EQ(exact_calls, 3) << "outside, the ring, the hole: one call per region";
  const auto [near, inside, outside] = raster.census();
  EXPECT_GT(inside + outside, 3 * near);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int answered = 0;
  for (int k = 0; k < 200000; ++k) {
    const cad::Vec2 uv(unit(random), unit(random));
    if (const auto known = raster.lookup(uv)) {
      ++answered;
      ASSERT_EQ(*known, in_ring(uv)) << uv.transpose();
    }
  }
  EXPECT_GT(answered, 150000);
  EXPECT_FALSE(raster.lookup(cad::Vec2(1.5, 0.5)).has_value()) << "outside the box: the exact test answers";
}

TEST(TrimRaster, RefinedNearCellsAgreeWithTheExactTestAndLeaveAThinnerBand) {
  const std::array<cad::Interval, 2> box{cad::Interval{0.0, 1.0}, cad::Interval{0.0, 1.0}};
  constexpr int kSub = 8;
  TrimRaster coarse(box, 64), refined(box, 64);
  const double step = 0.5 * coarse.cell_size().minCoeff();
  std::vector<std::vector<cad::Vec2>> fine_loops{circle(0.3, step / kSub), circle(0.1, step / kSub)};
  for (TrimRaster* raster : {&coarse, &refined}) {
    raster->mark_loop(circle(0.3, step), 2);
    raster->mark_loop(circle(0.1, step), 2);
    raster->classify(in_ring);
  }
  int exact_calls = 0;
  ASSERT_TRUE(refined.refine(kSub, fine_loops, 2, [&](const cad::Vec2& uv) {
    ++exact_calls;
    return in_ring(uv);
  }));
  EXPECT_EQ(refined.refinement(), kSub);
  EXPECT_LT(exact_calls, 10) << "nearly every region of sub-cells touches a classified cell";
  EXPECT_EQ(refined.census(), coarse.census()) << "the cells stay as they were";
  const auto [near, inside, outside] = refined.sub_census();
  EXPECT_GT(inside + outside, 2 * near);
  // Points within two cells of the circles: the coarse raster answers none, the refined one most,
  // and every answer is the closed-form one.
  std::mt19937 random(5);
  std::uniform_real_distribution<double> angle(0.0, 2 * M_PI), offset(-2.0 * step * 2, 2.0 * step * 2);
  int coarse_answers = 0, refined_answers = 0;
  for (int k = 0; k < 100000; ++k) {
    const double r = (k % 2 ? 0.3 : 0.1) + offset(random), a = angle(random);
    const cad::Vec2 uv(0.5 + r * std::cos(a), 0.5 + r * std::sin(a));
    if (const auto known = coarse.lookup(uv)) {
      ++coarse_answers;
      ASSERT_EQ(*known, in_ring(uv)) << uv.transpose();
    }
    if (const auto known = refined.lookup(uv)) {
      ++refined_answers;
      ASSERT_EQ(*known, in_ring(uv)) << uv.transpose();
    }
  }
  EXPECT_GT(refined_answers, coarse_answers + 50000);
}

TEST(TrimRaster, RefineGivesUpWhenTheFineSamplesLeaveTheNearCells) {
  const std::array<cad::Interval, 2> box{cad::Interval{0.0, 1.0}, cad::Interval{0.0, 1.0}};
  TrimRaster raster(box, 64);
  const double step = 0.5 * raster.cell_size().minCoeff();
  raster.mark_loop(circle(0.3, step), 2);
  raster.classify(in_ring);
  const auto before = raster.lookup(cad::Vec2(0.5, 0.5));
  // A loop the cells were not marked for: refining on it would contradict the classification.
  EXPECT_FALSE(raster.refine(8, {circle(0.2, step / 8)}, 2, in_ring));
  EXPECT_EQ(raster.refinement(), 0);
  EXPECT_EQ(raster.sub_census(), (std::array<int, 3>{0, 0, 0}));
  EXPECT_EQ(raster.lookup(cad::Vec2(0.5, 0.5)), before);
}

// contains() (raster first) against contains_exactly() on every face of a model.
void expect_raster_agrees(const cad::Model& model) {
  std::mt19937 random(11);
  for (int s = 0; s < model.num_surfaces(); ++s) {
    const auto& face = dynamic_cast<const OccSurface&>(model.surface(s));
    ASSERT_NE(face.trim_raster(), nullptr) << cad::surface_label(model, s);
    const auto box = face.bounds();
    std::uniform_real_distribution<double> u(box[0].lo, box[0].hi), v(box[1].lo, box[1].hi);
    std::normal_distribution<double> jitter(0.0, 1.0);
    int disagreements = 0;
    for (int k = 0; k < 4000; ++k) {
      cad::Vec2 uv(u(random), v(random));
      if (k % 2 == 1) {  // near the loops: a random boundary-ish point, a few cells' worth off
        const cad::Vec2 cell = face.trim_raster()->cell_size();
        uv.x() = k % 4 == 1 ? box[0].lo : box[0].hi;
        uv += cad::Vec2(cell.x() * 3 * jitter(random), 0.0);
      }
      disagreements += face.contains(uv) != face.contains_exactly(uv);
    }
    // Within a few sub-cells of the box's sides (where a face whose loop runs along them has its
    // refined near cells) and exactly on them.
    const cad::Vec2 sub = face.trim_raster()->cell_size() / std::max(1, face.trim_raster()->refinement());
    for (int k = 0; k < 2000; ++k) {
      cad::Vec2 uv(u(random), v(random));
      const int side = k % 4, d = side / 2;
      uv[d] = (side % 2 ? box[d].hi : box[d].lo) + (k % 3 ? sub[d] * 4 * jitter(random) : 0.0);
      disagreements += face.contains(uv) != face.contains_exactly(uv);
    }
    EXPECT_EQ(disagreements, 0) << cad::surface_label(model, s);
    const auto [near, inside, outside] = face.trim_raster()->census();
    EXPECT_GT(inside + outside, 0) << cad::surface_label(model, s) << ": nothing classified";
    EXPECT_GT(face.trim_raster()->refinement(), 0) << cad::surface_label(model, s) << ": near cells not refined";
  }
}

TEST(TrimRaster, OccBuiltWingAgreesWithTheClassifier) {
  expect_raster_agrees(*load_occ(cad::Source{"", {{"naca.span", "2"}}}));
}

TEST(TrimRaster, SharedStepWingsAgreeWithTheClassifier) {
  for (const char* name : {"nektar_3d_bl_wing_naca0012.stp", "onera_m6_sharp_te.stp"}) {
    const std::string path = test::testdata(name);
    if (!test::exists(path)) GTEST_SKIP() << "test CAD file " << path << " not found (see shared/testdata/cad/README.md)";
    SCOPED_TRACE(name);
    expect_raster_agrees(*load_occ(cad::Source{path, {}}));
  }
}

}  // namespace
}  // namespace semimesh::occ
