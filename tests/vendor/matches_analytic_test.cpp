// The adapter over the fake kernel reproduces the analytic model it wraps: same entities in the
// same order, same topology (after the kernel's id and sense conventions are translated back),
// the same points and derivatives, normals pointing the same way, the same projections.
#include "semimesh/vendor/vendor_backend.hpp"

#include "semimesh/mock_cad/naca.hpp"

#include <gtest/gtest.h>

#include <thread>

namespace semimesh::vendor {
namespace {

constexpr double kTol = 1e-12;

struct Case {
  const char* name;
  const char* path;  // what the fake kernel loads
  cad::Params naca;  // the same model for mock_cad
};

std::ostream& operator<<(std::ostream& out, const Case& c) { return out << c.name; }

class MatchesAnalytic : public ::testing::TestWithParam<Case> {
 protected:
  void SetUp() override {
    vendor_ = load_vendor({GetParam().path, {}});
    mock_ = mock_cad::load_naca({"", GetParam().naca});
  }
  std::unique_ptr<cad::Model> vendor_, mock_;
};

void expect_near(const cad::Vec3& a, const cad::Vec3& b, const char* what) {
  EXPECT_LE((a - b).norm(), kTol * std::max(1.0, b.norm())) << what << ": " << a.transpose() << " vs " << b.transpose();
}

TEST_P(MatchesAnalytic, SameCountsUnitsAndClosedness) {
  ASSERT_GT(mock_->num_surfaces(), 0);
  EXPECT_EQ(vendor_->num_vertices(), mock_->num_vertices());
  EXPECT_EQ(vendor_->num_curves(), mock_->num_curves());
  EXPECT_EQ(vendor_->num_surfaces(), mock_->num_surfaces());
  EXPECT_EQ(vendor_->is_closed(), mock_->is_closed());
  EXPECT_EQ(vendor_->tolerance(), mock_->tolerance());
  EXPECT_TRUE(vendor_->thread_safe());
  expect_near(vendor_->bbox().lo, mock_->bbox().lo, "bbox lo");
  expect_near(vendor_->bbox().hi, mock_->bbox().hi, "bbox hi");
}

TEST_P(MatchesAnalytic, SameTopologyAndNames) {
  ASSERT_EQ(vendor_->num_surfaces(), mock_->num_surfaces());
  for (int v = 0; v < mock_->num_vertices(); ++v) {
    EXPECT_EQ(vendor_->vertex(v).name, mock_->vertex(v).name);
    expect_near(vendor_->vertex(v).point, mock_->vertex(v).point, "vertex");
    EXPECT_EQ(vendor_->curves_of_vertex(v), mock_->curves_of_vertex(v)) << "vertex " << v;
  }
  for (int c = 0; c < mock_->num_curves(); ++c) {
    EXPECT_EQ(vendor_->curve(c).name(), mock_->curve(c).name());
    EXPECT_EQ(vendor_->curve_vertices(c), mock_->curve_vertices(c)) << "curve " << c;
    const auto& a = vendor_->surfaces_of_curve(c);
    const auto& b = mock_->surfaces_of_curve(c);
    ASSERT_EQ(a.size(), b.size()) << "curve " << c;
    for (size_t k = 0; k < a.size(); ++k) {
      EXPECT_EQ(a[k].surface, b[k].surface) << "curve " << c;
      EXPECT_EQ(a[k].forward, b[k].forward) << "curve " << c;
    }
  }
  for (int s = 0; s < mock_->num_surfaces(); ++s) {
    EXPECT_EQ(vendor_->surface(s).name(), mock_->surface(s).name());
    const auto& a = vendor_->loops(s);
    const auto& b = mock_->loops(s);
    ASSERT_EQ(a.size(), b.size()) << "surface " << s;
    for (size_t l = 0; l < a.size(); ++l) {
      ASSERT_EQ(a[l].uses.size(), b[l].uses.size()) << "surface " << s << " loop " << l;
      for (size_t k = 0; k < a[l].uses.size(); ++k) {
        EXPECT_EQ(a[l].uses[k].curve, b[l].uses[k].curve) << "surface " << s << " loop " << l << " use " << k;
        EXPECT_EQ(a[l].uses[k].forward, b[l].uses[k].forward) << "surface " << s << " loop " << l << " use " << k;
      }
    }
  }
}

TEST_P(MatchesAnalytic, CurvesEvaluateAndProjectTheSame) {
  for (int c = 0; c < mock_->num_curves(); ++c) {
    SCOPED_TRACE("curve " + std::to_string(c));
    const cad::Curve& a = vendor_->curve(c);
    const cad::Curve& b = mock_->curve(c);
    EXPECT_EQ(a.kind(), b.kind());
    ASSERT_EQ(a.bounds().lo, b.bounds().lo);
    ASSERT_EQ(a.bounds().hi, b.bounds().hi);
    for (int i = 0; i <= 8; ++i) {
      double t = b.bounds().lo + b.bounds().length() * i / 8.0;
      cad::CurveDerivatives da = a.derivatives(t), db = b.derivatives(t);
      expect_near(da.p, db.p, "C");
      expect_near(da.d1, db.d1, "dC/dt");
      expect_near(da.d2, db.d2, "d2C/dt2");
      expect_near(a.point(t), db.p, "point");
      // A point off the curve, projected without and with a guess.
      cad::Vec3 x = db.p + 0.01 * cad::Vec3(0.3, -0.2, 0.1);
      for (auto guess : {std::optional<double>{}, std::optional<double>{t}}) {
        cad::CurveProjection pa = a.project(x, guess), pb = b.project(x, guess);
        EXPECT_NEAR(pa.t, pb.t, kTol);
        EXPECT_NEAR(pa.distance, pb.distance, kTol);
        EXPECT_EQ(pa.converged, pb.converged);
        expect_near(pa.point, pb.point, "projected point");
      }
    }
  }
}

TEST_P(MatchesAnalytic, SurfacesEvaluateProjectAndPointNormalsTheSameWay) {
  for (int s = 0; s < mock_->num_surfaces(); ++s) {
    SCOPED_TRACE("surface " + std::to_string(s) + " '" + mock_->surface(s).name() + "'");
    const cad::Surface& a = vendor_->surface(s);
    const cad::Surface& b = mock_->surface(s);
    EXPECT_EQ(a.kind(), b.kind());
    EXPECT_EQ(a.orientation(), b.orientation());
    auto box = b.bounds();
    for (int k = 0; k < 2; ++k) {
      ASSERT_EQ(a.bounds()[k].lo, box[k].lo);
      ASSERT_EQ(a.bounds()[k].hi, box[k].hi);
    }
    for (int i = 0; i <= 4; ++i)
      for (int j = 0; j <= 4; ++j) {
        cad::Vec2 uv(box[0].lo + box[0].length() * (0.05 + 0.9 * i / 4.0),
                     box[1].lo + box[1].length() * (0.05 + 0.9 * j / 4.0));
        cad::SurfaceDerivatives da = a.derivatives(uv), db = b.derivatives(uv);
        expect_near(da.p, db.p, "S");
        expect_near(da.du, db.du, "dS/du");
        expect_near(da.dv, db.dv, "dS/dv");
        expect_near(da.duu, db.duu, "d2S/du2");
        expect_near(da.duv, db.duv, "d2S/dudv");
        expect_near(da.dvv, db.dvv, "d2S/dv2");
        EXPECT_GT(a.normal(uv).dot(b.normal(uv)), 1.0 - kTol);
        EXPECT_EQ(a.contains(uv), b.contains(uv));
        cad::Vec3 x = db.p + 0.02 * b.normal(uv);
        for (auto guess : {std::optional<cad::Vec2>{}, std::optional<cad::Vec2>{uv}}) {
          cad::SurfaceProjection pa = a.project(x, guess), pb = b.project(x, guess);
          EXPECT_LE((pa.uv - pb.uv).norm(), kTol);
          EXPECT_NEAR(pa.distance, pb.distance, kTol);
          EXPECT_EQ(pa.converged, pb.converged);
          EXPECT_EQ(pa.inside, pb.inside);
        }
      }
  }
}

// Queries are serialised inside the adapter, so concurrent callers get the serial answers.
TEST_P(MatchesAnalytic, ConcurrentQueriesGiveTheSerialAnswers) {
  auto sweep = [&](std::vector<cad::Vec3>& out) {
    for (int s = 0; s < vendor_->num_surfaces(); ++s) {
      auto box = vendor_->surface(s).bounds();
      for (int i = 0; i < 50; ++i) {
        cad::Vec2 uv(box[0].lo + box[0].length() * i / 49.0, box[1].lo + box[1].length() * (49 - i) / 49.0);
        out.push_back(vendor_->surface(s).point(uv));
      }
    }
  };
  std::vector<cad::Vec3> serial, first, second;
  sweep(serial);
  std::thread t1([&] { sweep(first); });
  std::thread t2([&] { sweep(second); });
  t1.join();
  t2.join();
  ASSERT_EQ(first.size(), serial.size());
  ASSERT_EQ(second.size(), serial.size());
  for (size_t k = 0; k < serial.size(); ++k) {
    EXPECT_EQ(first[k], serial[k]);
    EXPECT_EQ(second[k], serial[k]);
  }
}

INSTANTIATE_TEST_SUITE_P(
    Wings, MatchesAnalytic,
    ::testing::Values(Case{"naca0012_default", "naca:naca.code=0012", {{"naca.code", "0012"}}},
                      Case{"naca2412_sharp_tapered_swept", "naca:naca.code=2412;naca.span=2;naca.te=sharp;naca.taper=0.6;naca.sweep=20",
                           {{"naca.code", "2412"}, {"naca.span", "2"}, {"naca.te", "sharp"}, {"naca.taper", "0.6"},
                            {"naca.sweep", "20"}}},
                      Case{"naca0015_no_farfield", "naca:naca.code=0015;naca.farfield=false",
                           {{"naca.code", "0015"}, {"naca.farfield", "false"}}}),
    [](const ::testing::TestParamInfo<Case>& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace semimesh::vendor
