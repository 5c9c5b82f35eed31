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

#include <algorithm>
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

// The points of a circle halfway in angle between consecutive points of circle(radius, max_step)
// (the curve's point halfway in parameter), from point `from` to point `to` (a part of the circle).
std::vector<cad::Vec2> circle_midpoints(double radius, double max_step, std::size_t from, std::size_t to) {
  const int n = static_cast<int>(std::ceil(2 * M_PI * radius / max_step)) + 1;
  std::vector<cad::Vec2> points;
  for (std::size_t k = from; k < to; ++k)
    points.emplace_back(0.5 + radius * std::cos(2 * M_PI * (k + 0.5) / n), 0.5 + radius * std::sin(2 * M_PI * (k + 0.5) / n));
  return points;
}

// The ring's raster refined, then given its circles' polylines, each circle as one edge or (split)
// as two arcs leaving a gap of `gap` radians at angle 0 of the outer circle.
struct RingWithPolylines {
  static constexpr int kSub = 8;
  TrimRaster raster{{cad::Interval{0.0, 1.0}, cad::Interval{0.0, 1.0}}, 64};
  double step = 0.5 * raster.cell_size().minCoeff();
  bool kept = false;
  explicit RingWithPolylines(double gap = 0.0, double tolerance = 1e-9) {
    raster.mark_loop(circle(0.3, step), 2);
    raster.mark_loop(circle(0.1, step), 2);
    raster.classify(in_ring);
    std::vector<std::vector<cad::Vec2>> loops{circle(0.3, step / kSub), circle(0.1, step / kSub)};
    std::vector<std::vector<cad::Vec2>> midpoints{circle_midpoints(0.3, step / kSub, 0, loops[0].size() - 1),
                                                  circle_midpoints(0.1, step / kSub, 0, loops[1].size() - 1)};
    EXPECT_TRUE(raster.refine(kSub, loops, 2, in_ring));
    if (gap > 0.0) {  // the outer circle as two arcs, the first without its last samples
      const auto n = static_cast<std::size_t>(std::ceil(gap / (2 * M_PI) * static_cast<double>(loops[0].size() - 1)));
      std::vector<cad::Vec2> arc(loops[0].begin(), loops[0].begin() + loops[0].size() / 2 + 1);
      std::vector<cad::Vec2> rest(loops[0].begin() + loops[0].size() / 2, loops[0].end() - n);
      std::vector<cad::Vec2> arc_mid(midpoints[0].begin(), midpoints[0].begin() + loops[0].size() / 2);
      std::vector<cad::Vec2> rest_mid(midpoints[0].begin() + loops[0].size() / 2, midpoints[0].end() - n);
      loops = {arc, rest, loops[1]};
      midpoints = {arc_mid, rest_mid, midpoints[1]};
    }
    kept = raster.keep_polylines(loops, midpoints, {tolerance, 0.0, 0.0});
  }
};

TEST(TrimRaster, PolylinesAnswerTheNearSubCellsAwayFromTheLoopsAsTheExactTest) {
  RingWithPolylines ring;
  ASSERT_TRUE(ring.kept);
  EXPECT_GT(ring.raster.polyline_band(), 0.0);
  EXPECT_LT(ring.raster.polyline_band(), 1e-5) << "1e-9 and the chords' deviation (~1e-6 at half a sub-cell)";
  TrimRaster refined_only(ring.raster);
  // Points within four sub-cells of the circles: every answer is the closed-form one, and nearly
  // all of them are answered (only those within the band of a circle are not).
  std::mt19937 random(5);
  const double sub = ring.step * 2 / RingWithPolylines::kSub;
  std::uniform_real_distribution<double> angle(0.0, 2 * M_PI), offset(-4 * sub, 4 * sub);
  int answered = 0;
  for (int k = 0; k < 100000; ++k) {
    const double r = (k % 2 ? 0.3 : 0.1) + offset(random), a = angle(random);
    const cad::Vec2 uv(0.5 + r * std::cos(a), 0.5 + r * std::sin(a));
    if (const auto known = ring.raster.lookup(uv)) {
      ++answered;
      ASSERT_EQ(*known, in_ring(uv)) << uv.transpose();
    }
  }
  EXPECT_GT(answered, 99000);
  // On a circle (within the band): left to the exact test.
  for (int k = 0; k < 1000; ++k) {
    const double a = angle(random);
    EXPECT_FALSE(ring.raster.lookup(cad::Vec2(0.5 + 0.3 * std::cos(a), 0.5 + 0.3 * std::sin(a))).has_value());
  }
}

TEST(TrimRaster, ARayThroughAGapBetweenTwoEdgesIsNotCounted) {
  // A gap of a third of a sub-cell: the two arcs' ends block the rays that pass it.
  const double sub = 0.5 / 64 / RingWithPolylines::kSub * 2;
  RingWithPolylines ring(sub / 3 / 0.3);
  ASSERT_TRUE(ring.kept);
  // Points on either side of the outer circle by up to three sub-cells, across the gap (angle
  // 0): the shortest ray of those nearest the circle runs along u across it, some through the gap.
  std::mt19937 random(3);
  std::uniform_real_distribution<double> side(0.05, 3.0), along(-0.5, 0.5);
  int answered = 0;
  for (int k = 0; k < 2000; ++k) {
    const double r = 0.3 + (k % 2 ? 1 : -1) * side(random) * sub, a = along(random) * sub / 0.3;
    const cad::Vec2 uv(0.5 + r * std::cos(a), 0.5 + r * std::sin(a));
    if (const auto known = ring.raster.lookup(uv)) {
      ++answered;
      ASSERT_EQ(*known, in_ring(uv)) << uv.transpose();
    }
  }
  EXPECT_GT(answered, 1000) << "the rays along v answer most of them";
  // A gap of a sub-cell or more: the polylines are not kept.
  EXPECT_FALSE(RingWithPolylines(1.5 * sub / 0.3).kept);
}

TEST(TrimRaster, PolylinesAreNotKeptWhenTheirBandReachesTheClassifiedSubCells) {
  const double sub = 0.5 / 64 / RingWithPolylines::kSub * 2;
  EXPECT_TRUE(RingWithPolylines(0.0, 1.4 * sub).kept) << "margin 2: classified sub-cells 1.5 sub-cells away";
  EXPECT_FALSE(RingWithPolylines(0.0, 1.6 * sub).kept);
  TrimRaster unrefined({cad::Interval{0.0, 1.0}, cad::Interval{0.0, 1.0}}, 64);
  unrefined.mark_loop(circle(0.3, 0.004), 2);
  unrefined.classify(in_ring);
  EXPECT_FALSE(unrefined.keep_polylines({circle(0.3, 0.0005)}, {{}}, {1e-9, 0.0, 0.0})) << "not refined";
}

TEST(TrimRaster, PointsWithinHalfTheCertainToleranceOfALoopAreOnIt) {
  // The face: the square [0.25, 0.75]^2 in the unit box, its four sides straight edges.
  const std::array<cad::Interval, 2> box{cad::Interval{0.0, 1.0}, cad::Interval{0.0, 1.0}};
  const auto in_square = [](const cad::Vec2& uv) { return uv.minCoeff() >= 0.25 && uv.maxCoeff() <= 0.75; };
  const std::array<cad::Vec2, 5> corners{cad::Vec2(0.25, 0.25), cad::Vec2(0.75, 0.25), cad::Vec2(0.75, 0.75),
                                         cad::Vec2(0.25, 0.75), cad::Vec2(0.25, 0.25)};
  TrimRaster raster(box, 64);
  const double cell = raster.cell_size().x(), sub = cell / 8;
  std::vector<std::vector<cad::Vec2>> coarse, fine, midpoints;
  for (int side = 0; side < 4; ++side) {
    coarse.emplace_back(), fine.emplace_back(), midpoints.emplace_back();
    for (int k = 0; k <= 128; ++k) coarse.back().push_back(corners[side] + (corners[side + 1] - corners[side]) * k / 128.0);
    for (int k = 0; k <= 1024; ++k) fine.back().push_back(corners[side] + (corners[side + 1] - corners[side]) * k / 1024.0);
    for (int k = 0; k < 1024; ++k)
      midpoints.back().push_back(corners[side] + (corners[side + 1] - corners[side]) * (k + 0.5) / 1024.0);
    raster.mark_loop(coarse.back(), 2);
  }
  raster.classify(in_square);
  ASSERT_TRUE(raster.refine(8, fine, 2, in_square));
  const double tolerance = 1e-6, certain = 1e-7;
  ASSERT_TRUE(raster.keep_polylines(fine, midpoints, {tolerance, 0.0, certain}));
  for (double v : {0.3, 0.5, 0.7}) {
    EXPECT_EQ(raster.lookup(cad::Vec2(0.75, v)), std::optional<bool>(true)) << "on the side";
    EXPECT_EQ(raster.lookup(cad::Vec2(0.75 + 0.4 * certain, v)), std::optional<bool>(true)) << "within half";
    EXPECT_EQ(raster.lookup(cad::Vec2(0.75 + 0.6 * certain, v)), std::nullopt) << "beyond half, in the band";
    EXPECT_EQ(raster.lookup(cad::Vec2(0.75 + 0.9 * tolerance, v)), std::nullopt) << "in the band";
    EXPECT_EQ(raster.lookup(cad::Vec2(0.75 + 1.1 * tolerance, v)), std::optional<bool>(false)) << "out of it";
    EXPECT_EQ(raster.lookup(cad::Vec2(0.75 - 1.1 * tolerance, v)), std::optional<bool>(true));
    EXPECT_EQ(raster.lookup(cad::Vec2(0.75 + 0.5 * sub, v)), std::optional<bool>(false));
  }
  // Near a corner, beyond the band of both sides: by the polylines, unless within a vertex's tolerance.
  const cad::Vec2 beyond_corner(0.75 + 1.5e-5, 0.75);
  EXPECT_EQ(raster.lookup(beyond_corner), std::optional<bool>(false));
  ASSERT_TRUE(raster.keep_polylines(fine, midpoints, {tolerance, 2e-5, certain}));
  EXPECT_EQ(raster.lookup(beyond_corner), std::nullopt) << "within the vertex's tolerance";
  EXPECT_EQ(raster.lookup(beyond_corner + cad::Vec2(1e-5, 0.0)), std::optional<bool>(false));
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
    // Around the face's edges: on them, within the classifier's tolerance, and up to a few
    // sub-cells off in random directions, where the kept polylines answer most queries.
    int raster_answers = 0, near_edges = 0;
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int c = 0; c < model.num_curves(); ++c) {
      const auto& uses = model.surfaces_of_curve(c);
      if (model.curve(c).is_degenerate() ||
          std::none_of(uses.begin(), uses.end(), [&](const cad::SurfaceUse& use) { return use.surface == s; }))
        continue;
      const cad::Interval range = model.curve(c).bounds();
      for (int k = 0; k < 300; ++k) {
        const cad::Vec2 on = face.project(model.curve(c).point(range.lo + range.length() * unit(random))).uv;
        const double angle = 2 * M_PI * unit(random), reach = k % 3 == 0 ? 0.0 : k % 3 == 1 ? 1e-8 : 4 * unit(random);
        const cad::Vec2 uv = on + reach * cad::Vec2(sub.x() * std::cos(angle), sub.y() * std::sin(angle));
        disagreements += face.contains(uv) != face.contains_exactly(uv);
        const bool within_box = uv.x() > box[0].lo && uv.x() < box[0].hi && uv.y() > box[1].lo && uv.y() < box[1].hi;
        if (k % 3 == 2 && within_box) near_edges += 1, raster_answers += face.trim_raster()->lookup(uv).has_value();
      }
    }
    // Where the band left to OCC is under a tenth of a sub-cell, the polylines answer nearly all.
    const double band = face.trim_raster()->polyline_band() / std::min(sub.x(), sub.y());
    if (band > 0.0 && band < 0.1) {
      EXPECT_GT(raster_answers, near_edges * 8 / 10) << cad::surface_label(model, s);
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
