// The OCC B-spline NACA wing against the analytic one (mock_cad): same surfaces in the same
// order, points within 1e-7 chord, normals on the same side, curves named by role as in the
// analytic model, a closed valid shell.
#include "occ_test_support.hpp"
#include "semimesh/mock_cad/naca.hpp"
#include "semimesh/occ/occ_backend.hpp"

#include <BRepCheck_Analyzer.hxx>
#include <BRep_Tool.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopoDS.hxx>
#include <gtest/gtest.h>

#include <map>
#include <set>
#include <string>

namespace semimesh::occ::test {
namespace {

struct Case {
  const char* label;
  cad::Params params;
};

class OccNaca : public ::testing::TestWithParam<Case> {};

TEST_P(OccNaca, MatchesTheAnalyticWing) {
  const cad::Params& params = GetParam().params;
  auto occ_model = load_occ(cad::Source{"", params});
  auto exact = mock_cad::load_naca(cad::Source{"", params});
  const double chord = mock_cad::naca_params_from(params).chord;

  ASSERT_EQ(occ_model->num_surfaces(), exact->num_surfaces());
  for (int s = 0; s < exact->num_surfaces(); ++s) EXPECT_EQ(occ_model->surface(s).name(), exact->surface(s).name());
  EXPECT_EQ(occ_model->num_curves(), exact->num_curves());
  EXPECT_EQ(occ_model->is_closed(), exact->is_closed());

  for (int s = 0; s < exact->num_surfaces(); ++s) {
    const cad::Surface& mine = occ_model->surface(s);
    const cad::Surface& reference = exact->surface(s);
    const auto samples = inside_samples(mine, 13);
    ASSERT_GT(samples.size(), 20u) << mine.name();
    double worst = 0.0;
    for (const cad::Vec2& uv : samples) {
      const cad::Vec3 x = mine.point(uv);
      const cad::SurfaceProjection p = reference.project(x, uv);  // same parametrisation: uv is a good start
      worst = std::max(worst, p.distance);
      EXPECT_TRUE(p.inside) << mine.name() << " at " << uv.transpose();
      EXPECT_GT(mine.normal(uv).dot(reference.normal(p.uv)), 0.999) << mine.name() << " at " << uv.transpose();
    }
    EXPECT_LT(worst, 1e-7 * chord) << mine.name();
  }
}

// The size field clusters by curve name (leading_edge, te_*), so each OCC curve must carry the
// analytic name of the curve it lies on.
TEST_P(OccNaca, CurvesCarryTheAnalyticNames) {
  const cad::Params& params = GetParam().params;
  auto occ_model = load_occ(cad::Source{"", params});
  auto exact = mock_cad::load_naca(cad::Source{"", params});
  const double chord = mock_cad::naca_params_from(params).chord;

  std::map<std::string, int> exact_curves;  // name -> id
  for (int c = 0; c < exact->num_curves(); ++c) exact_curves[exact->curve(c).name()] = c;
  std::set<std::string> seen;
  for (int c = 0; c < occ_model->num_curves(); ++c) {
    const cad::Curve& mine = occ_model->curve(c);
    EXPECT_TRUE(seen.insert(mine.name()).second) << "two OCC curves named " << mine.name();
    const auto match = exact_curves.find(mine.name());
    ASSERT_NE(match, exact_curves.end()) << "OCC curve " << c << " '" << mine.name() << "' is not an analytic curve";
    const cad::Interval t = mine.bounds();
    const cad::Vec3 midpoint = mine.point(0.5 * (t.lo + t.hi));
    EXPECT_LT(exact->curve(match->second).project(midpoint).distance, 1e-7 * chord)
        << mine.name() << ": midpoint " << midpoint.transpose() << " is off the analytic curve";
  }
  EXPECT_EQ(seen.size(), exact_curves.size());
}

INSTANTIATE_TEST_SUITE_P(
    Wings, OccNaca,
    ::testing::Values(Case{"default_0012", {}},
                      Case{"sharp_tapered_swept", {{"naca.te", "sharp"}, {"naca.taper", "0.5"}, {"naca.sweep", "25"}}},
                      Case{"cambered_2412", {{"naca.code", "2412"}, {"naca.chord", "2"}}},
                      Case{"cambered_sharp_no_farfield", {{"naca.code", "4415"}, {"naca.te", "sharp"}, {"naca.farfield", "false"}}}),
    [](const ::testing::TestParamInfo<Case>& info) { return std::string(info.param.label); });

// A symmetric untapered skin is exactly a degree (8, 1) B-spline in the analytic parametrisation.
TEST(OccNacaExact, SymmetricSkinSharesTheParametrisation) {
  auto occ_model = load_occ(cad::Source{"", {}});
  auto exact = mock_cad::load_naca(cad::Source{"", {}});
  for (const char* name : {"upper", "lower"}) {
    const cad::Surface& mine = occ_model->surface(*occ_model->find_surface(name));
    const cad::Surface& reference = exact->surface(*exact->find_surface(name));
    for (double u : {0.0, 0.01, 0.3, 0.9, 1.0})
      for (double v : {0.0, 1.3, 3.0}) {
        const cad::Vec2 uv(u, v);
        EXPECT_LT((mine.point(uv) - reference.point(uv)).norm(), 1e-13) << name << " at " << uv.transpose();
        EXPECT_LT((mine.derivatives(uv).du - reference.derivatives(uv).du).norm(), 1e-11) << name;
      }
  }
}

TEST(OccNacaExact, SewnShellIsClosedAndValid) {
  for (bool sharp : {false, true}) {
    mock_cad::NacaWingParams params;
    params.sharp_te = sharp;
    const TopoDS_Shape shell = make_naca_wing_shape(params);
    EXPECT_TRUE(BRepCheck_Analyzer(shell).IsValid());
    TopTools_IndexedDataMapOfShapeListOfShape edge_faces;
    TopExp::MapShapesAndAncestors(shell, TopAbs_EDGE, TopAbs_FACE, edge_faces);
    for (int i = 1; i <= edge_faces.Extent(); ++i)
      EXPECT_EQ(edge_faces.FindFromIndex(i).Extent(), 2) << "edge " << i << " is not shared by two faces";
    EXPECT_EQ(naca_wing_face_names(params).size(), sharp ? 9u : 10u);
  }
}

TEST(OccNacaExact, NormalsPointIntoTheFluid) {
  auto model = load_occ(cad::Source{"", {}});
  EXPECT_LT(position_flux(*model), 0.0);  // fluid inside the box, outside the wing
  const cad::Surface& upper = model->surface(*model->find_surface("upper"));
  EXPECT_GT(upper.normal(cad::Vec2(0.5, 1.5)).y(), 0.9);
  const cad::Surface& wall = model->surface(*model->find_surface("wall"));
  EXPECT_GT(wall.normal(cad::Vec2(5.0, 5.0)).z(), 0.999);
}

}  // namespace
}  // namespace semimesh::occ::test
