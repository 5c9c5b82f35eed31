// The backend conformance suite: every check of the cadapi contract (docs/architecture.md, section 3) on
// every model of fixtures.hpp. A check that cannot apply to a model is skipped with the reason.
#include "fixtures.hpp"
#include "sampling.hpp"

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include <cctype>
#include <iostream>
#include <map>
#include <set>
#include <cmath>

namespace conformance {
namespace {

// One model of fixtures.hpp as a value: the suite is value-parameterised (TEST_P) rather than typed,
// so each check is compiled once for every model, not once per model.
struct ModelCase {
  std::string name;
  std::string (*skip_reason)();
  std::unique_ptr<cad::Model> (*load)();
  Expectations (*expect)();
};

// gtest prints a parameter in test listings; the name, not the struct's bytes.
void PrintTo(const ModelCase& c, std::ostream* os) { *os << c.name; }

template <class F>
ModelCase model_case() {
  return {F::kName, &F::skip_reason, &F::load, &F::expect};
}

std::vector<ModelCase> all_models() {
  return {model_case<NacaDefault>(), model_case<NacaBluntNoBox>(), model_case<NacaCamberedTaperedSweptSharp>(),
          model_case<NacaRevolution>(), model_case<NacaRoundTipBlunt>(), model_case<NacaRoundTipBluntTaperedSwept>(),
          model_case<NacaRoundTipCamberedTaperedSweptSharp>(), model_case<NacaOnCylinderBlunt>(),
          model_case<NacaOnCylinderCamberedTaperedSweptSharp>(), model_case<NacaOnCylinderCamberedTaperedSweptBlunt>(),
          model_case<NacaOnCylinderDihedral>(), model_case<NacaDihedralSharp>(), model_case<NacaOnConeSweptSharp>(),
          model_case<NacaOnConeCamberedBlunt>(),
#ifdef SEMIMESH_HAVE_OCC
          model_case<OccNaca>(), model_case<OccSphere>(), model_case<OccStepNektarWing>(),
          model_case<OccStepOneraM6>(), model_case<OccStepOneraM6OnWall>(), model_case<OccStepOneraM6InSphere>(),
#endif
#ifdef SEMIMESH_HAVE_VENDOR_FAKE
          model_case<VendorFake>(), model_case<VendorFakeRevolution>(),
#endif
  };
}

// Each model is loaded once per process and kept until the suite ends (CTest runs one check per
// process; a plain gtest run goes through every check of every model).
class Conformance : public ::testing::TestWithParam<ModelCase> {
 protected:
  static void TearDownTestSuite() { loaded().clear(); }
  void SetUp() override {
    const ModelCase& c = GetParam();
    const std::string skip = c.skip_reason();
    if (!skip.empty()) GTEST_SKIP() << c.name << ": " << skip;
    Loaded& slot = loaded()[c.name];
    if (!slot.model && slot.error.empty()) {
      try {
        slot.model = c.load();
      } catch (const std::exception& e) {
        slot.error = e.what();
      } catch (...) {
        // An exception escaping here would make gtest skip the test, which CTest counts as passed.
        slot.error = "an exception that is not a std::exception (an OCC Standard_Failure?)";
      }
    }
    ASSERT_TRUE(slot.model) << c.name << " failed to load: " << slot.error;
    model_ = slot.model.get();
  }

  const cad::Model& model() const { return *model_; }
  Expectations expect() const { return GetParam().expect(); }
  double diagonal() const { return model_->bbox().diagonal(); }

 private:
  struct Loaded {
    std::unique_ptr<cad::Model> model;
    std::string error;
  };
  static std::map<std::string, Loaded>& loaded() {
    static std::map<std::string, Loaded> models;
    return models;
  }
  const cad::Model* model_ = nullptr;
};

std::string model_name(const ::testing::TestParamInfo<ModelCase>& info) {
  std::string out;
  for (char c : info.param.name) out += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
  return out;
}

INSTANTIATE_TEST_SUITE_P(Models, Conformance, ::testing::ValuesIn(all_models()), model_name);

// Central differences of P give dP/dt; of dP/dt give d2P/dt2. Tolerances relative to the size of
// the derivatives: 1e-5 for first, 1e-3 for second derivatives (spline knots limit the latter);
// a wrong formula is off by O(1).
TEST_P(Conformance, CurveDerivativesMatchFiniteDifferences) {
  const cad::Model& m = this->model();
  for (int c = 0; c < m.num_curves(); ++c) {
    const cad::Curve& curve = m.curve(c);
    const auto range = curve.bounds();
    const double h = 1e-4 * range.length();
    for (int k = 0; k < 9; ++k) {
      const double t = range.lo + range.length() * (k + 0.618) / 10.0;  // off the usual knots
      const auto d = curve.derivatives(t), minus = curve.derivatives(t - h), plus = curve.derivatives(t + h);
      const Vec3 d1 = (plus.p - minus.p) / (2 * h), d2 = (plus.d1 - minus.d1) / (2 * h);
      const double scale1 = d.d1.norm() + this->diagonal() * 1e-6 / range.length();
      const double scale2 = d.d2.norm() + d.d1.norm() / range.length();
      EXPECT_LE((d1 - d.d1).norm(), 1e-5 * scale1) << "curve " << c << " '" << curve.name() << "' dC/dt at t = " << t;
      EXPECT_LE((d2 - d.d2).norm(), 1e-3 * scale2) << "curve " << c << " '" << curve.name() << "' d2C/dt2 at t = " << t;
    }
  }
}

TEST_P(Conformance, SurfaceDerivativesMatchFiniteDifferences) {
  const cad::Model& m = this->model();
  for (int s = 0; s < m.num_surfaces(); ++s) {
    const cad::Surface& surface = m.surface(s);
    const auto box = surface.bounds();
    const double hu = 1e-4 * box[0].length(), hv = 1e-4 * box[1].length();
    const Vec2 eu(hu, 0), ev(0, hv);
    for (const Vec2& uv : inside_samples(surface, 5, 0.02, 0.3819)) {  // off the usual knots
      const auto d = surface.derivatives(uv);
      const auto um = surface.derivatives(uv - eu), up = surface.derivatives(uv + eu);
      const auto vm = surface.derivatives(uv - ev), vp = surface.derivatives(uv + ev);
      const std::string where = "surface " + std::to_string(s) + " '" + surface.name() + "' at (" +
                                std::to_string(uv.x()) + ", " + std::to_string(uv.y()) + ")";
      const double s1 = d.du.norm() * box[0].length() + d.dv.norm() * box[1].length() + 1e-6 * this->diagonal();
      EXPECT_LE(((up.p - um.p) / (2 * hu) - d.du).norm() * box[0].length(), 1e-5 * s1) << where << " dS/du";
      EXPECT_LE(((vp.p - vm.p) / (2 * hv) - d.dv).norm() * box[1].length(), 1e-5 * s1) << where << " dS/dv";
      const double s2 = s1 + d.duu.norm() * std::pow(box[0].length(), 2) + d.dvv.norm() * std::pow(box[1].length(), 2) +
                        d.duv.norm() * box[0].length() * box[1].length();
      const double lu2 = std::pow(box[0].length(), 2), lv2 = std::pow(box[1].length(), 2), luv = box[0].length() * box[1].length();
      EXPECT_LE(((up.du - um.du) / (2 * hu) - d.duu).norm() * lu2, 1e-3 * s2) << where << " d2S/du2";
      EXPECT_LE(((vp.dv - vm.dv) / (2 * hv) - d.dvv).norm() * lv2, 1e-3 * s2) << where << " d2S/dv2";
      EXPECT_LE(((vp.du - vm.du) / (2 * hv) - d.duv).norm() * luv, 1e-3 * s2) << where << " d2S/dudv (from dS/du)";
      EXPECT_LE(((up.dv - um.dv) / (2 * hu) - d.duv).norm() * luv, 1e-3 * s2) << where << " d2S/dudv (from dS/dv)";
    }
  }
}

// Normals point into the fluid, checked in two steps that trust no normal.
// 1. Every loop runs counter-clockwise around its face's normal (docs/architecture.md, section 3 / model.hpp):
//    at a point of a bounding curve, stepping along n x T (T the tangent in the loop's direction)
//    lands on the face, and stepping the other way leaves it. With each curve walked once each way
//    by its two faces (AdjacencyAndOrientation), neighbouring faces' normals agree.
// 2. The winding number of the model (a surface integral of the geometry, sampling.hpp) at
//    q = P + eps n is the fluid's value (-1 when the model encloses the fluid, 0 around a body)
//    and one more at P - eps n. A flipped face or a flipped model changes these values.
TEST_P(Conformance, LoopsRunCounterClockwiseAroundTheNormal) {
  const cad::Model& m = this->model();
  for (int s = 0; s < m.num_surfaces(); ++s) {
    const cad::Surface& surface = m.surface(s);
    const auto box = surface.bounds();
    const double size = std::hypot(box[0].length(), box[1].length());
    for (const cad::Loop& loop : m.loops(s))
      for (const cad::CurveUse& use : loop.uses) {
        const cad::Curve& curve = m.curve(use.curve);
        if (curve.is_degenerate()) continue;  // a pole has no tangent (PeriodicFacesSeamsAndPoles)
        const auto range = curve.bounds();
        const bool seam = m.is_seam(s, use.curve);  // walked both ways by this face: both sides are on it
        for (int k = 1; k <= 3; ++k) {
          const double t = range.lo + range.length() * k / 4.0;
          const Vec3 tangent = (use.forward ? 1.0 : -1.0) * curve.tangent(t);
          const auto on = surface.project(curve.point(t));
          const auto d = surface.derivatives(on.uv);
          // n x T in parameter coordinates: solve [du dv] (a, b) = n x T in the least-squares sense.
          Eigen::Matrix<double, 3, 2> jac;
          jac << d.du, d.dv;
          const Vec3 left = surface.normal(on.uv).cross(tangent);
          Vec2 dir = jac.colPivHouseholderQr().solve(left);
          dir.normalize();
          // The face must lie on the left and not on the right at some small step (narrow faces
          // need small steps); a reversed loop has it on the right at every step.
          // On a seam the curve has two images one period apart; the use walks one of them.
          std::vector<Vec2> images{on.uv};
          for (int p = 0; p < 2 && seam; ++p)
            if (const auto period = surface.period(p))
              for (double sign : {-1.0, 1.0}) images.push_back(on.uv + sign * *period * Vec2::Unit(p));
          bool left_only = false;
          for (double step = 1e-3 * size; step > 1e-9 * size && !left_only; step *= 0.5)
            for (const Vec2& uv : images)
              left_only = left_only || (surface.contains(uv + step * dir) && (seam || !surface.contains(uv - step * dir)));
          EXPECT_TRUE(left_only) << "surface " << s << " '" << surface.name() << "', curve " << use.curve << " '"
                                 << curve.name() << "' at t = " << t << ": the face is not on the loop's left only";
        }
      }
  }
}

TEST_P(Conformance, NormalsPointIntoTheFluid) {
  if (!this->expect().closed) GTEST_SKIP() << "the winding number needs a closed model: " << this->expect().open_reason;
  const cad::Model& m = this->model();
  const double fluid = this->expect().fluid_encloses ? -1.0 : 0.0;
  const double eps = 1e-4 * this->diagonal();
  const int checked = this->expect().winding_surfaces > 0 ? std::min(this->expect().winding_surfaces, m.num_surfaces())
                                                         : m.num_surfaces();
  for (int s = 0; s < checked; ++s) {
    const cad::Surface& surface = m.surface(s);
    const Vec2 uv = central_sample(surface);
    const Vec3 p = surface.point(uv), n = surface.normal(uv);
    ASSERT_NEAR(n.norm(), 1.0, 1e-12) << "surface " << s;
    EXPECT_NEAR(winding_number(m, p + eps * n), fluid, 0.2) << "surface " << s << " '" << surface.name() << "': P + eps n";
    EXPECT_NEAR(winding_number(m, p - eps * n), fluid + 1.0, 0.2) << "surface " << s << " '" << surface.name() << "': P - eps n";
    auto back = surface.project(p + eps * n, uv);
    EXPECT_NEAR(back.distance, eps, 1e-6 * eps) << "surface " << s << " '" << surface.name() << "'";
  }
}

// Points on each face (inside the trim) project back onto themselves: distance ~0, the same
// point (parameters may differ across a periodic seam, so points are compared), inside = true.
TEST_P(Conformance, ProjectionOfPointsOnTheSurface) {
  const cad::Model& m = this->model();
  const double tol = 1e-9 * this->diagonal();
  for (int s = 0; s < m.num_surfaces(); ++s) {
    const cad::Surface& surface = m.surface(s);
    for (const Vec2& uv : inside_samples(surface, 4)) {
      const Vec3 p = surface.point(uv);
      auto r = surface.project(p);
      EXPECT_LE(r.distance, tol) << "surface " << s << " '" << surface.name() << "'";
      EXPECT_LE((r.point - p).norm(), tol) << "surface " << s << " '" << surface.name() << "'";
      EXPECT_TRUE(r.inside) << "surface " << s << " '" << surface.name() << "'";
    }
  }
}

// P + d n projects back to P with distance d (d = 1e-3 of the model size, small against every
// radius of curvature on the fluid side of these models).
TEST_P(Conformance, ProjectionOfPointsOffTheSurface) {
  const cad::Model& m = this->model();
  const double d = 1e-3 * this->diagonal(), tol = 1e-8 * this->diagonal();
  for (int s = 0; s < m.num_surfaces(); ++s) {
    const cad::Surface& surface = m.surface(s);
    for (const Vec2& uv : inside_samples(surface, 4, 0.05)) {
      const Vec3 p = surface.point(uv), n = surface.normal(uv);
      auto r = surface.project(p + d * n);
      EXPECT_NEAR(r.distance, d, tol) << "surface " << s << " '" << surface.name() << "'";
      EXPECT_LE((r.point - p).norm(), tol) << "surface " << s << " '" << surface.name() << "'";
      EXPECT_TRUE(r.converged) << "surface " << s << " '" << surface.name() << "'";
    }
  }
}

// A guess near the answer converges to it; curves likewise.
TEST_P(Conformance, ProjectionWithInitialGuess) {
  const cad::Model& m = this->model();
  const double tol = 1e-8 * this->diagonal();
  for (int s = 0; s < m.num_surfaces(); ++s) {
    const cad::Surface& surface = m.surface(s);
    const auto box = surface.bounds();
    const Vec2 nudge(0.01 * box[0].length(), -0.01 * box[1].length());
    for (const Vec2& uv : inside_samples(surface, 3, 0.05)) {
      const Vec3 p = surface.point(uv) + 1e-4 * this->diagonal() * surface.normal(uv);
      auto r = surface.project(p, uv + nudge);
      EXPECT_LE((r.point - surface.point(uv)).norm(), tol) << "surface " << s << " '" << surface.name() << "'";
    }
  }
  for (int c = 0; c < m.num_curves(); ++c) {
    const cad::Curve& curve = m.curve(c);
    if (curve.is_degenerate()) continue;  // every parameter is the answer
    const auto range = curve.bounds();
    for (int k = 1; k < 4; ++k) {
      const double t = range.lo + range.length() * k / 4.0;
      const Vec3 p = curve.point(t);
      auto free = curve.project(p);
      auto guessed = curve.project(p, t + 0.02 * range.length());
      EXPECT_LE(free.distance, tol) << "curve " << c << " '" << curve.name() << "' at t = " << t;
      EXPECT_LE(guessed.distance, tol) << "curve " << c << " '" << curve.name() << "' at t = " << t << " with a guess";
      EXPECT_NEAR(guessed.t, t, 1e-7 * range.length()) << "curve " << c << " '" << curve.name() << "'";
    }
  }
}

// Planar faces have zero curvature; where the LE radius is known, the upper skin's chordwise
// curvature at the LE is its inverse (convex: positive against the fluid normal).
TEST_P(Conformance, CurvaturesOnKnownCases) {
  const cad::Model& m = this->model();
  int planes = 0;
  for (int s = 0; s < m.num_surfaces(); ++s) {
    const cad::Surface& surface = m.surface(s);
    if (!surface.is_planar()) continue;
    ++planes;
    for (const Vec2& uv : inside_samples(surface, 3)) {
      auto k = surface.curvatures(uv);
      EXPECT_NEAR(k.k_min, 0.0, 1e-9 / this->diagonal()) << "planar surface " << s << " '" << surface.name() << "'";
      EXPECT_NEAR(k.k_max, 0.0, 1e-9 / this->diagonal()) << "planar surface " << s << " '" << surface.name() << "'";
    }
  }
  const auto expect = this->expect();
  if (!expect.le_radius) {
    if (planes == 0) GTEST_SKIP() << "no planar face and no known leading-edge radius";
    return;
  }
  auto upper = m.find_surface("upper");
  ASSERT_TRUE(upper.has_value()) << "a model with a known LE radius must name its upper skin 'upper'";
  const cad::Surface& surface = m.surface(*upper);
  const double z = surface.point(central_sample(surface)).z();  // mid-span
  auto le = surface.project(Vec3(0, 0, z));
  ASSERT_LE(le.distance, 1e-7 * this->diagonal()) << "the leading edge is not on the z axis";
  auto k = surface.curvatures(le.uv);
  EXPECT_NEAR(1.0 / k.k_max, *expect.le_radius, expect.le_radius_tolerance * *expect.le_radius);
  EXPECT_NEAR(k.k_min, 0.0, 1e-3 / *expect.le_radius);  // straight along the span
}

// Topology: loops are closed chains whose end points meet geometrically; each curve lies on the
// surfaces it bounds; on a closed model each curve is used once forward and once reversed.
TEST_P(Conformance, AdjacencyAndOrientation) {
  const cad::Model& m = this->model();
  const double tol = std::max(1e3 * m.tolerance(), 1e-7 * this->diagonal());
  for (int c = 0; c < m.num_curves(); ++c) {
    const cad::Curve& curve = m.curve(c);
    const auto ends = m.curve_vertices(c);
    const auto range = curve.bounds();
    EXPECT_LE((curve.point(range.lo) - m.vertex(ends[0]).point).norm(), tol) << "curve " << c << " start vertex";
    EXPECT_LE((curve.point(range.hi) - m.vertex(ends[1]).point).norm(), tol) << "curve " << c << " end vertex";
    for (const cad::SurfaceUse& use : m.surfaces_of_curve(c)) {
      const cad::Surface& surface = m.surface(use.surface);
      for (int k = 0; k <= 4; ++k) {
        auto r = surface.project(curve.point(range.lo + range.length() * k / 4.0));
        EXPECT_LE(r.distance, tol) << "curve " << c << " '" << curve.name() << "' off surface " << use.surface << " '"
                                   << surface.name() << "'";
      }
    }
  }
  for (int s = 0; s < m.num_surfaces(); ++s)
    for (const cad::Loop& loop : m.loops(s))
      for (size_t k = 0; k < loop.uses.size(); ++k) {
        const auto& a = loop.uses[k];
        const auto& b = loop.uses[(k + 1) % loop.uses.size()];
        const auto ra = m.curve(a.curve).bounds(), rb = m.curve(b.curve).bounds();
        const Vec3 end = m.curve(a.curve).point(a.forward ? ra.hi : ra.lo);
        const Vec3 start = m.curve(b.curve).point(b.forward ? rb.lo : rb.hi);
        EXPECT_LE((end - start).norm(), tol) << "surface " << s << ": curve " << a.curve << " then " << b.curve;
      }

  if (!this->expect().closed) {
    EXPECT_FALSE(m.is_closed());
    GTEST_SKIP() << "not a closed model: " << this->expect().open_reason;
  }
  EXPECT_TRUE(m.is_closed());
  for (int c = 0; c < m.num_curves(); ++c) {
    const auto& uses = m.surfaces_of_curve(c);
    if (m.curve(c).is_degenerate()) {
      EXPECT_EQ(uses.size(), 1u) << "degenerate curve " << c << " '" << m.curve(c).name() << "' bounds one face once";
      continue;
    }
    ASSERT_EQ(uses.size(), 2u) << "curve " << c << " '" << m.curve(c).name() << "'";
    EXPECT_NE(uses[0].forward, uses[1].forward) << "curve " << c << " '" << m.curve(c).name()
                                                << "' must be walked once each way by its two surfaces";
  }
}

// Simpson's error is O(h^4) for smooth |C'|, but O(h) where |C'| jumps (NACA camber lines have a
// curvature jump at the maximum-camber station; STEP splines may have C0 knots), hence the fine
// step and the 1e-5 tolerance; a wrong arc length is off by far more.
TEST_P(Conformance, ArcLengthMatchesSimpson) {
  const cad::Model& m = this->model();
  for (int c = 0; c < m.num_curves(); ++c) {
    const cad::Curve& curve = m.curve(c);
    const auto range = curve.bounds();
    if (curve.is_degenerate()) {
      EXPECT_EQ(curve.length(), 0.0) << "degenerate curve " << c << " '" << curve.name() << "'";
      continue;
    }
    const double expected = simpson_length(curve, range.lo, range.hi, 20000);
    EXPECT_NEAR(curve.arc_length(range.lo, range.hi), expected, 1e-5 * expected) << "curve " << c << " '" << curve.name() << "'";
    const double mid = 0.5 * (range.lo + range.hi);
    const double half = simpson_length(curve, range.lo, mid, 10000);
    EXPECT_NEAR(curve.arc_length(mid, range.lo), -half, 1e-5 * expected) << "curve " << c << " reversed half";
    EXPECT_NEAR(curve.parameter_at_length(range.lo, half), mid, 1e-5 * range.length()) << "curve " << c;
  }
}

// Periodic faces, seams and poles, the contract the surface mesher relies on (surface.hpp,
// curve.hpp, model.hpp):
//  - a period p of direction i is positive, the parameter box spans at most p, and the surface
//    closes on itself: S at the box's lower side equals S one period further;
//  - a seam (a curve one face walks once each way) lies where that face's box wraps: its points
//    project onto the lower or upper side of a periodic direction of the box;
//  - a degenerate curve is one point (zero derivatives, the same vertex at both ends, zero
//    length), used once by one face, and that face is singular there: du or dv vanishes at the
//    pole (relative to the other), so a whole side of the box maps onto it.
TEST_P(Conformance, PeriodicFacesSeamsAndPoles) {
  const cad::Model& m = this->model();
  const double tol = 1e-9 * this->diagonal();
  int seams = 0, poles = 0;
  for (int s = 0; s < m.num_surfaces(); ++s) {
    const cad::Surface& surface = m.surface(s);
    const auto box = surface.bounds();
    const std::string where = "surface " + std::to_string(s) + " '" + surface.name() + "'";
    for (int dir = 0; dir < 2; ++dir) {
      const std::optional<double> period = surface.period(dir);
      if (!period) continue;
      ASSERT_TRUE(*period > 0.0 && std::isfinite(*period)) << where << " direction " << dir;
      EXPECT_LE(box[dir].length(), *period * (1 + 1e-12)) << where << ": the box spans more than a period";
      for (int k = 0; k <= 6; ++k) {
        const int other = 1 - dir;
        Vec2 lo;
        lo[dir] = box[dir].lo;
        lo[other] = box[other].lo + box[other].length() * (k + 0.31) / 7.0;
        Vec2 shifted = lo;
        shifted[dir] += *period;
        EXPECT_LE((surface.point(shifted) - surface.point(lo)).norm(), tol)
            << where << ": S does not repeat after the period " << *period << " of direction " << dir;
      }
    }
    EXPECT_THROW(surface.period(2), cad::CadError);
    std::set<int> counted;
    for (const cad::Loop& loop : m.loops(s))
      for (const cad::CurveUse& use : loop.uses) {
        if (!m.is_seam(s, use.curve) || !counted.insert(use.curve).second) continue;
        ++seams;
        const cad::Curve& curve = m.curve(use.curve);
        ASSERT_TRUE(surface.period(0) || surface.period(1)) << where << " has seam curve " << use.curve << " '"
                                                            << curve.name() << "' but no periodic direction";
        const auto range = curve.bounds();
        for (int k = 1; k <= 3; ++k) {
          const Vec2 uv = surface.project(curve.point(range.lo + range.length() * k / 4.0)).uv;
          bool on_wrap = false;
          for (int dir = 0; dir < 2; ++dir)
            if (surface.period(dir))
              on_wrap = on_wrap || std::min(std::abs(uv[dir] - box[dir].lo), std::abs(uv[dir] - box[dir].hi)) <=
                                       1e-7 * box[dir].length();
          EXPECT_TRUE(on_wrap) << where << ": seam curve " << use.curve << " '" << curve.name()
                               << "' projects to (" << uv.x() << ", " << uv.y() << "), not onto a side of the box";
        }
      }
  }
  for (int c = 0; c < m.num_curves(); ++c) {
    const cad::Curve& curve = m.curve(c);
    if (!curve.is_degenerate()) continue;
    ++poles;
    const std::string where = "degenerate curve " + std::to_string(c) + " '" + curve.name() + "'";
    const auto ends = m.curve_vertices(c);
    EXPECT_EQ(ends[0], ends[1]) << where;
    const auto range = curve.bounds();
    EXPECT_GT(range.length(), 0.0) << where << ": a pole still spans a parameter interval";
    for (int k = 0; k <= 4; ++k) {
      const auto d = curve.derivatives(range.lo + range.length() * k / 4.0);
      EXPECT_LE((d.p - m.vertex(ends[0]).point).norm(), tol) << where;
      EXPECT_EQ(d.d1.norm(), 0.0) << where;
    }
    ASSERT_EQ(m.surfaces_of_curve(c).size(), 1u) << where;
    const cad::Surface& surface = m.surface(m.surfaces_of_curve(c).front().surface);
    const auto on = surface.project(m.vertex(ends[0]).point);
    const double vertex_tol = std::max(1e3 * m.tolerance(), 1e-7 * this->diagonal());  // as AdjacencyAndOrientation
    EXPECT_LE(on.distance, vertex_tol) << where << " is off its face '" << surface.name() << "'";
    const auto d = surface.derivatives(on.uv);
    EXPECT_LE(std::min(d.du.norm(), d.dv.norm()), 1e-6 * std::max(d.du.norm(), d.dv.norm()))
        << where << ": face '" << surface.name() << "' is not singular at the pole";
  }
  if (const auto expected = this->expect().seams) {
    EXPECT_EQ(seams, *expected) << "seam curves";
  }
  if (const auto expected = this->expect().poles) {
    EXPECT_EQ(poles, *expected) << "degenerate curves";
  }
  std::cout << "[ info ] " << seams << " seam curve(s), " << poles << " pole(s)\n";
}

// Near a pole, a projection started at the pole itself (the guess the curving of a pole's elements
// hands in) or without a guess reaches the point: a local solver stopped at the pole, where the
// surface does not move along one parameter, cannot turn towards it by itself.
TEST_P(Conformance, ProjectionLeavesAPole) {
  const cad::Model& m = this->model();
  const double tol = 1e-8 * this->diagonal();
  int checked = 0;
  for (int c = 0; c < m.num_curves(); ++c) {
    if (!m.curve(c).is_degenerate()) continue;
    const cad::Surface& surface = m.surface(m.surfaces_of_curve(c).front().surface);
    const Vec2 pole = surface.project(m.vertex(m.curve_vertices(c)[0]).point).uv;
    const auto d = surface.derivatives(pole);
    const int angle = d.du.norm() < d.dv.norm() ? 0 : 1, radial = 1 - angle;
    const auto box = surface.bounds();
    const double inward = pole[radial] - box[radial].lo < box[radial].hi - pole[radial] ? 1.0 : -1.0;
    for (double depth : {0.01, 0.03})
      for (int k = 0; k < 3; ++k) {
        Vec2 uv = pole;
        uv[radial] += inward * depth * box[radial].length();
        uv[angle] = box[angle].lo + (k + 0.4) / 3.0 * box[angle].length();
        const Vec3 p = surface.point(uv);
        const std::string where = "face '" + surface.name() + "' near pole '" + m.curve(c).name() + "' at (" +
                                  std::to_string(uv.x()) + ", " + std::to_string(uv.y()) + ")";
        EXPECT_LE(surface.project(p, pole).distance, tol) << where << ", started at the pole";
        EXPECT_LE(surface.project(p).distance, tol) << where << ", without a guess";
        ++checked;
      }
  }
  std::cout << "[ info ] " << checked << " point(s) near poles projected\n";
}

TEST_P(Conformance, BoundingBoxContainsAllSamples) {
  const cad::Model& m = this->model();
  const cad::BBox& box = m.bbox();
  ASSERT_FALSE(box.empty());
  const double tol = 1e-9 * this->diagonal();
  for (int c = 0; c < m.num_curves(); ++c) {
    const auto range = m.curve(c).bounds();
    for (int k = 0; k <= 50; ++k)
      EXPECT_TRUE(box.contains(m.curve(c).point(range.lo + range.length() * k / 50.0), tol)) << "curve " << c;
  }
  for (int s = 0; s < m.num_surfaces(); ++s)
    for (const Vec2& uv : inside_samples(m.surface(s), 9, 0.0))
      EXPECT_TRUE(box.contains(m.surface(s).point(uv), tol)) << "surface " << s << " '" << m.surface(s).name() << "'";
}

}  // namespace
}  // namespace conformance
