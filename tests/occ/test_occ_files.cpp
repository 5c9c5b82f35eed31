// Loading third-party STEP files: counts, units, bounding box, fluid-side normals, projections.
#include "occ_test_support.hpp"
#include "semimesh/occ/occ_backend.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <thread>

namespace semimesh::occ::test {
namespace {

const std::string kNektar = testdata("nektar_3d_bl_wing_naca0012.stp");
const std::string kOnera = testdata("onera_m6_sharp_te.stp");

std::unique_ptr<cad::Model> load(const std::string& path, cad::Params params = {}) {
  return load_occ(cad::Source{path, params});
}

#define SKIP_WITHOUT(path) \
  if (!exists(path)) GTEST_SKIP() << "test data not found at " << (path)

// Every point sampled inside a face projects back onto itself, inside the face.
void expect_surface_round_trips(const cad::Model& model, double tolerance) {
  for (int s = 0; s < model.num_surfaces(); ++s) {
    const cad::Surface& surface = model.surface(s);
    const auto samples = inside_samples(surface, 5);
    ASSERT_FALSE(samples.empty()) << surface.name();
    for (const cad::Vec2& uv : samples) {
      const cad::Vec3 x = surface.point(uv);
      const cad::SurfaceProjection global = surface.project(x);
      EXPECT_LT(global.distance, tolerance) << surface.name() << " at " << uv.transpose();
      EXPECT_TRUE(global.inside) << surface.name() << " at " << uv.transpose();
      const cad::SurfaceProjection local = surface.project(x, uv + cad::Vec2(1e-3, -1e-3) * surface.bounds()[0].length());
      EXPECT_LT(local.distance, tolerance) << surface.name();
      EXPECT_TRUE(local.converged) << surface.name();
    }
  }
}

void expect_curve_round_trips(const cad::Model& model, double tolerance) {
  for (int c = 0; c < model.num_curves(); ++c) {
    const cad::Curve& curve = model.curve(c);
    const cad::Interval range = curve.bounds();
    for (double f : {0.0, 0.3, 0.77, 1.0}) {
      const double t = range.lo + f * range.length();
      const cad::CurveProjection p = curve.project(curve.point(t));
      EXPECT_LT(p.distance, tolerance) << curve.name() << " t=" << t;
      EXPECT_TRUE(range.contains(p.t)) << curve.name();
    }
  }
}

TEST(OccStep, NektarWingLoadsSewnInMillimetres) {
  SKIP_WITHOUT(kNektar);
  auto model = load(kNektar);
  EXPECT_EQ(model->num_surfaces(), 9);
  EXPECT_TRUE(model->is_closed()) << "the box faces should be sewn to the wall";
  EXPECT_EQ(model->units(), "mm");
  EXPECT_DOUBLE_EQ(model->scale_applied(), 1.0);
  // Box from the file's vertices: x in [-5625.779, 7785.421], y in [-0.399, 812.401], z in [0, 1219.2].
  EXPECT_NEAR(model->bbox().lo.x(), -5625.77901, 1e-3);
  EXPECT_NEAR(model->bbox().hi.x(), 7785.42099, 1e-3);
  EXPECT_NEAR(model->bbox().hi.y(), 812.4007196, 1e-3);
  EXPECT_NEAR(model->bbox().lo.z(), 0.0, 1e-3);
  EXPECT_NEAR(model->bbox().hi.z(), 1219.2, 1e-3);
}

TEST(OccStep, NektarWithoutSewingIsOpen) {
  SKIP_WITHOUT(kNektar);
  auto model = load(kNektar, {{"occ.sew", "false"}, {"occ.heal", "false"}});
  EXPECT_EQ(model->num_surfaces(), 9);
  EXPECT_FALSE(model->is_closed());
}

// The wing: the faces that neither lie on the box's x ends nor span most of it along x.
// Its extent along x is ~1.2 m: a 1219.2 mm (4 ft) chord at about 10 degrees of incidence gives
// 1219.2 cos(10 deg) = 1200.7 mm (plus a fraction of a millimetre from the thickness).
TEST(OccStep, NektarWingChordIsPlausible) {
  SKIP_WITHOUT(kNektar);
  auto model = load(kNektar);
  const cad::BBox& all = model->bbox();
  cad::BBox wing;
  int wing_faces = 0;
  for (int s = 0; s < model->num_surfaces(); ++s) {
    const cad::Surface& surface = model->surface(s);
    cad::BBox box;
    for (const cad::Vec2& uv : inside_samples(surface, 12)) box.add(surface.point(uv));
    const bool clear = box.lo.x() > all.lo.x() + 1 && box.hi.x() < all.hi.x() - 1 &&
                       box.hi.x() - box.lo.x() < 0.5 * (all.hi.x() - all.lo.x());
    if (!clear) continue;
    ++wing_faces;
    for (const cad::Loop& loop : model->loops(s))  // the extent from the exact boundary curves
      for (const cad::CurveUse& use : loop.uses) {
        const cad::Curve& curve = model->curve(use.curve);
        for (int i = 0; i <= 200; ++i) wing.add(curve.point(curve.bounds().lo + curve.bounds().length() * i / 200));
      }
  }
  EXPECT_EQ(wing_faces, 3);
  ASSERT_FALSE(wing.empty());
  EXPECT_GT(wing.hi.x() - wing.lo.x(), 1195.0);
  EXPECT_LT(wing.hi.x() - wing.lo.x(), 1210.0);
  EXPECT_LT(wing.hi.z(), 1219.2);  // the tip stays below the box top
}

TEST(OccStep, NektarNormalsPointIntoTheFluidInsideTheBox) {
  SKIP_WITHOUT(kNektar);
  auto model = load(kNektar);
  EXPECT_LT(position_flux(*model), 0.0) << "normals must point into the bounded fluid region";
  const cad::Vec3 centre = 0.5 * (model->bbox().lo + model->bbox().hi);
  int box_faces = 0;
  for (int s = 0; s < model->num_surfaces(); ++s) {
    const cad::Surface& surface = model->surface(s);
    for (const cad::Vec2& uv : inside_samples(surface, 3)) {
      const cad::Vec3 p = surface.point(uv), n = surface.normal(uv);
      const bool on_bbox = ((p - model->bbox().lo).cwiseAbs().minCoeff() < 1e-6) ||
                           ((p - model->bbox().hi).cwiseAbs().minCoeff() < 1e-6);
      if (!on_bbox) continue;
      ++box_faces;
      EXPECT_GT(n.dot(centre - p), 0.0) << surface.name() << " normal points out of the box";
    }
  }
  EXPECT_GT(box_faces, 0);
}

TEST(OccStep, NektarProjectionsRespectTrimming) {
  SKIP_WITHOUT(kNektar);
  auto model = load(kNektar);
  expect_surface_round_trips(*model, 1e-6);
  expect_curve_round_trips(*model, 1e-6);
  // The wall is the face with a hole (the root section): points above the hole project onto the
  // wall's plane outside the trimmed face.
  int wall = -1;
  for (int s = 0; s < model->num_surfaces(); ++s)
    if (model->loops(s).size() == 2) wall = s;
  ASSERT_GE(wall, 0);
  const cad::Surface& surface = model->surface(wall);
  const auto box = surface.bounds();
  int in_hole = 0;
  for (int i = 0; i < 400; ++i)
    for (int j = 0; j < 40; ++j) {
      cad::Vec2 uv(box[0].lo + box[0].length() * (i + 0.5) / 400, box[1].lo + box[1].length() * (j + 0.5) / 40);
      if (surface.contains(uv)) continue;
      ++in_hole;
      const cad::SurfaceProjection p = surface.project(surface.point(uv) + 5.0 * surface.normal(uv));
      EXPECT_FALSE(p.inside) << "a point over the root section's hole reported inside the wall";
      EXPECT_NEAR(p.distance, 5.0, 1e-6);
    }
  EXPECT_GT(in_hole, 0);
}

// project_near (no trimming test) against project with the same guess: the same foot, bit for bit,
// on every face, from points on and off the faces and their loops' curves, guesses near and far.
TEST(OccStep, NektarProjectNearIsTheGuidedProjectionsFoot) {
  SKIP_WITHOUT(kNektar);
  auto model = load(kNektar);
  int checked = 0;
  for (int s = 0; s < model->num_surfaces(); ++s) {
    const cad::Surface& surface = model->surface(s);
    const auto box = surface.bounds();
    std::vector<std::pair<cad::Vec3, cad::Vec2>> queries;  // (point, guess)
    for (int i = 0; i <= 6; ++i)
      for (int j = 0; j <= 6; ++j) {
        const cad::Vec2 uv(box[0].lo + box[0].length() * i / 6, box[1].lo + box[1].length() * j / 6);
        const cad::Vec3 x = surface.point(uv) + (i - 3) * 0.7 * surface.normal(uv);
        queries.push_back({x, uv});
        queries.push_back({x, uv + cad::Vec2(0.05 * box[0].length(), -0.05 * box[1].length())});
      }
    for (const cad::Loop& loop : model->loops(s))
      for (const cad::CurveUse& use : loop.uses) {
      const cad::Curve& c = model->curve(use.curve);
      for (int k = 0; k <= 4; ++k) {
        const cad::Vec3 x = c.point(c.bounds().lo + c.bounds().length() * k / 4);
        queries.push_back({x, cad::Vec2(box[0].lo, box[1].hi)});
      }
    }
    for (const auto& [x, guess] : queries) {
      const cad::SurfaceProjection full = surface.project(x, guess), near = surface.project_near(x, guess);
      ASSERT_EQ(near.uv, full.uv) << surface.name();
      ASSERT_EQ(near.point, full.point) << surface.name();
      ASSERT_EQ(near.distance, full.distance) << surface.name();
      ASSERT_EQ(near.converged, full.converged) << surface.name();
      EXPECT_FALSE(near.inside);
      ++checked;
    }
  }
  EXPECT_GT(checked, 800);
}

// Regression: on the wing skin (a surface of extrusion) OCC's extremum search stopped at u = 0,
// 3.07 mm away, for points of the trailing-edge curve edge_17, whose true foot is at u ~ 2488
// with distance ~1e-9 mm. Every point of a face's boundary curve lies on the face.
TEST(OccStep, NektarUnguidedProjectionFindsTheFootOnTheExtrusion) {
  SKIP_WITHOUT(kNektar);
  auto model = load(kNektar);
  ASSERT_GT(model->num_surfaces(), 8);
  const cad::Surface& skin = model->surface(8);
  ASSERT_EQ(skin.name(), "Join.13_8");
  ASSERT_EQ(skin.kind(), cad::SurfaceKind::Extrusion);
  int edge = -1;
  for (int c = 0; c < model->num_curves(); ++c)
    if (model->curve(c).name() == "edge_17") edge = c;
  ASSERT_GE(edge, 0);
  bool bounds_skin = false;
  for (const cad::SurfaceUse& use : model->surfaces_of_curve(edge)) bounds_skin = bounds_skin || use.surface == 8;
  ASSERT_TRUE(bounds_skin) << "edge_17 should be a boundary curve of Join.13_8";

  const cad::Curve& curve = model->curve(edge);
  for (int k = 0; k <= 8; ++k) {
    const double t = curve.bounds().lo + curve.bounds().length() * k / 8.0;
    const cad::SurfaceProjection p = skin.project(curve.point(t));
    EXPECT_LT(p.distance, 1e-6) << "t = " << t << " projected to uv = " << p.uv.transpose();
    EXPECT_NEAR(p.uv.x(), 2488.1, 0.01) << "t = " << t;
    EXPECT_TRUE(p.inside) << "t = " << t;
    EXPECT_TRUE(p.converged) << "t = " << t;
  }
}

TEST(OccStep, OneraM6LoadsAsClosedSolid) {
  SKIP_WITHOUT(kOnera);
  auto model = load(kOnera);
  EXPECT_EQ(model->num_surfaces(), 11);
  EXPECT_EQ(model->num_curves(), 21);
  EXPECT_TRUE(model->is_closed());
  EXPECT_EQ(model->units(), "mm");
  // Semi-span 1.196 m plus the rounded tip, swept root chord 0.806 m: x up to ~1.15 m.
  const cad::BBox& box = model->bbox();
  EXPECT_NEAR(box.hi.y() - box.lo.y(), 1218.5, 1.0);
  EXPECT_NEAR(box.hi.x() - box.lo.x(), 1146.6, 1.0);
  EXPECT_LT(box.hi.z() - box.lo.z(), 100.0);
  EXPECT_TRUE(model->thread_safe());
}

TEST(OccStep, OneraM6NormalsPointOutOfTheSolid) {
  SKIP_WITHOUT(kOnera);
  auto model = load(kOnera);
  EXPECT_GT(position_flux(*model), 0.0);
}

TEST(OccStep, OneraM6ProjectionsRoundTrip) {
  SKIP_WITHOUT(kOnera);
  auto model = load(kOnera);
  expect_surface_round_trips(*model, 1e-6);
  expect_curve_round_trips(*model, 1e-6);
}

TEST(OccStep, ScaleIsAppliedOnceAtLoad) {
  SKIP_WITHOUT(kOnera);
  auto mm = load(kOnera);
  auto m = load(kOnera, {{"occ.scale", "0.001"}, {"occ.units", "m"}});
  EXPECT_EQ(m->units(), "m");
  EXPECT_DOUBLE_EQ(m->scale_applied(), 0.001);
  EXPECT_NEAR((m->bbox().hi - 0.001 * mm->bbox().hi).norm(), 0.0, 1e-6);
  const cad::Vec2 uv = inside_samples(mm->surface(0), 3).front();
  EXPECT_NEAR((m->surface(0).point(uv) - 0.001 * mm->surface(0).point(uv)).norm(), 0.0, 1e-9);
}

// Concurrent queries give the same answers as serial ones (the model says it is thread-safe), on
// the M6's B-spline faces and on the NekMesh wing's extruded skin and revolved tip.
TEST(OccStep, ConcurrentQueriesMatchSerialOnes) {
  SKIP_WITHOUT(kOnera);
  SKIP_WITHOUT(kNektar);
  for (const std::string& file : {kOnera, kNektar}) {
  SCOPED_TRACE(file);
  auto model = load(file);
  ASSERT_TRUE(model->thread_safe());
  std::vector<cad::Vec3> points;
  for (int s = 0; s < model->num_surfaces(); ++s)
    for (const cad::Vec2& uv : inside_samples(model->surface(s), 1))
      points.push_back(model->surface(s).point(uv) + cad::Vec3(0.3, -0.2, 0.1));
  auto run = [&](std::vector<double>& out) {
    for (int s = 0; s < model->num_surfaces(); ++s)
      for (const cad::Vec3& x : points) {
        const auto p = model->surface(s).project(x);
        out.push_back(p.distance + (p.inside ? 1e6 : 0.0));
      }
  };
  std::vector<double> serial;
  run(serial);
  std::vector<std::vector<double>> results(3);
  std::vector<std::thread> threads;
  for (auto& r : results) threads.emplace_back(run, std::ref(r));
  for (auto& t : threads) t.join();
  for (const auto& r : results) EXPECT_EQ(r, serial);
  }
}

}  // namespace
}  // namespace semimesh::occ::test
