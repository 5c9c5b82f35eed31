// Curving on CAD whose parameters are kinked (highorder/src/curving/kinked_parameters.hpp): a
// quarter cylinder parametrised by pieces of different speeds, as CAD exporters write Bezier
// patches joined at knots of full multiplicity. The nodes placed on it must be those of its
// smooth parametrisation, and a smooth parametrisation is not taken for a kinked one.
#include "outward_prism.hpp"
#include "semimesh/ho/curving/curve_mesh.hpp"
#include "semimesh/ho/curving/geometric_error.hpp"
#include "semimesh/ho/mesh_validity.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <memory>
#include <vector>

namespace semimesh::ho {
namespace {

using Vec3 = Eigen::Vector3d;

constexpr double kRadius = 1.0, kAngle = 1.5;

/// phi(w): a piecewise linear map of [0, pieces] onto [0, kAngle], piece k of slope slopes[k]
/// (scaled to the total angle); one piece of slope kAngle is the smooth parametrisation.
class PiecewiseAngle {
 public:
  explicit PiecewiseAngle(std::vector<double> slopes) : slopes_(std::move(slopes)) {
    double sum = 0.0;
    for (double s : slopes_) sum += s;
    for (double& s : slopes_) s *= kAngle / sum;
  }
  double length() const { return static_cast<double>(slopes_.size()); }
  double slope(double w) const { return slopes_[piece(w)]; }
  double operator()(double w) const {
    const std::size_t k = piece(w);
    double phi = 0.0;
    for (std::size_t j = 0; j < k; ++j) phi += slopes_[j];
    return phi + slopes_[k] * (w - static_cast<double>(k));
  }
  double inverse(double phi) const {
    double w = 0.0;
    for (double s : slopes_) {
      if (phi <= s) return w + phi / s;
      phi -= s;
      w += 1.0;
    }
    return length();
  }

 private:
  std::size_t piece(double w) const {
    return std::min(slopes_.size() - 1, static_cast<std::size_t>(std::max(0.0, std::floor(w))));
  }
  std::vector<double> slopes_;
};

/// The quarter cylinder S(u, w) = (R cos phi(w), R sin phi(w), u), u in [0, 1].
class Cylinder final : public cad::Surface {
 public:
  explicit Cylinder(PiecewiseAngle phi) : cad::Surface(0, "cylinder"), phi_(std::move(phi)) {}
  cad::SurfaceKind kind() const override { return cad::SurfaceKind::Analytic; }
  std::array<cad::Interval, 2> bounds() const override { return {cad::Interval{0.0, 1.0}, cad::Interval{0.0, phi_.length()}}; }
  cad::SurfaceDerivatives derivatives(const cad::Vec2& uv) const override {
    const double p = phi_(uv.y()), s = phi_.slope(uv.y());
    const Vec3 radial(std::cos(p), std::sin(p), 0), tangent(-std::sin(p), std::cos(p), 0);
    return {kRadius * radial + uv.x() * Vec3::UnitZ(), Vec3::UnitZ(), kRadius * s * tangent, Vec3::Zero(), Vec3::Zero(), -kRadius * s * s * radial};
  }
  bool contains(const cad::Vec2&) const override { return true; }
  const PiecewiseAngle& phi() const { return phi_; }

 private:
  PiecewiseAngle phi_;
};

/// A curve t in [0, 1] -> f(t) (its derivatives by differences: only the surface's are used here).
class Edge final : public cad::Curve {
 public:
  Edge(int id, std::function<Vec3(double)> f, PiecewiseAngle t)
      : cad::Curve(id, "edge"), f_(std::move(f)), t_(std::move(t)) {}
  cad::CurveKind kind() const override { return cad::CurveKind::Analytic; }
  cad::Interval bounds() const override { return {0.0, t_.length()}; }
  cad::CurveDerivatives derivatives(double t) const override {
    const double s = t_(t) / kAngle, ds = t_.slope(t) / kAngle, h = 1e-6;
    return {f_(s), ds * (f_(s + h) - f_(s - h)) / (2 * h), Vec3::Zero()};
  }

 private:
  std::function<Vec3(double)> f_;
  PiecewiseAngle t_;
};

/// The quarter cylinder's model: its four sides as curves, its arcs parametrised by `phi` too.
std::unique_ptr<cad::Model> quarter_cylinder(const PiecewiseAngle& phi) {
  auto m = std::make_unique<cad::Model>("kinked");
  const auto at = [](double u, double angle) -> Vec3 { return Vec3(kRadius * std::cos(angle), kRadius * std::sin(angle), u); };
  const int v0 = m->add_vertex(at(0, 0)), v1 = m->add_vertex(at(0, kAngle)), v2 = m->add_vertex(at(1, kAngle)),
            v3 = m->add_vertex(at(1, 0));
  const PiecewiseAngle straight({1.0});
  const int bottom = m->add_curve(std::make_unique<Edge>(0, [at](double s) { return at(0, s * kAngle); }, phi), v0, v1);
  const int side = m->add_curve(std::make_unique<Edge>(1, [at](double s) { return at(s, kAngle); }, straight), v1, v2);
  const int top = m->add_curve(std::make_unique<Edge>(2, [at](double s) { return at(1, s * kAngle); }, phi), v3, v2);
  const int start = m->add_curve(std::make_unique<Edge>(3, [at](double s) { return at(s, 0); }, straight), v0, v3);
  m->add_surface(std::make_unique<Cylinder>(phi), {cad::Loop{{{bottom, true}, {side, true}, {top, false}, {start, false}}}});
  m->finalize();
  return m;
}

/// A layer of prisms (thickness 0.05, outward) on an n x n grid of the patch u in [0.1, 0.9],
/// phi in [0.1, 1.4], each quad cut into two triangles; the body nodes attached to the surface at
/// their parameters (phi's inverse), the same points whatever the parametrisation.
mesh::Mesh layer_on(const cad::Model& model, int n) {
  const auto& cylinder = dynamic_cast<const Cylinder&>(model.surface(0));
  mesh::Mesh m(1);
  std::vector<mesh::NodeId> body;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j) {
      const double u = 0.1 + 0.8 * i / n, angle = 0.1 + 1.3 * j / n, w = cylinder.phi().inverse(angle);
      const Vec3 x(kRadius * std::cos(angle), kRadius * std::sin(angle), u);
      body.push_back(m.add_node(x, {mesh::CadAttachment::Surface, 0, u, w}));
      m.add_node(x + 0.05 * Vec3(std::cos(angle), std::sin(angle), 0));
    }
  add_outward_prism_grid(m, body, n, m.region_index("layer"), "body");
  return m;
}

const PiecewiseAngle kKinked({0.4, 0.1, 0.8, 0.2}), kKinkedOtherwise({0.1, 0.4, 0.2, 0.8, 0.3}), kSmooth({1.0});

TEST(CurveKinkedParameters, FoundOnPiecewiseParametersNotOnSmoothOnes) {
  for (const auto* phi : {&kKinked, &kKinkedOtherwise, &kSmooth}) {
    const auto model = quarter_cylinder(*phi);
    CurvingStats stats;
    curve_mesh(layer_on(*model, 4), *model, {2, NodeSet::GLL, 50, 1e-10}, &stats);
    const int kinked = phi == &kSmooth ? 0 : 1;
    EXPECT_EQ(stats.kinked_surfaces, kinked);
    EXPECT_EQ(stats.kinked_curves, 2 * kinked);  // the two arcs
  }
}

// On a kinked surface the nodes are placed at fractions of its kink chart, which takes the kinks
// out: on this cylinder the chart is an affine image of the smooth angle, so the curved mesh is the
// one of the smoothly parametrised cylinder, whichever kinked parametrisation it is given (before,
// the edge and face nodes sat at fractions of each parametrisation's intervals: 1e-2 apart, error
// 1e-3 against 1e-6; projecting the straight-sided nodes instead made them agree but with 10-20x
// the error at P = 3 and 4). Valid, and the error falls like h^(P+1).
TEST(CurveKinkedParameters, NodesDoNotDependOnTheParametrisation) {
  const auto a = quarter_cylinder(kKinked), b = quarter_cylinder(kKinkedOtherwise), smooth = quarter_cylinder(kSmooth);
  for (int P = 2; P <= 4; ++P) {
    std::vector<double> errors;
    for (int n : {8, 16, 32}) {
      const CurvingParams params{P, NodeSet::GLL, 50, 1e-10};
      const mesh::Mesh on_a = curve_mesh(layer_on(*a, n), *a, params), on_b = curve_mesh(layer_on(*b, n), *b, params);
      const mesh::Mesh on_smooth = curve_mesh(layer_on(*smooth, n), *smooth, params);
      ASSERT_EQ(on_a.num_nodes(), on_b.num_nodes());
      ASSERT_EQ(on_a.num_nodes(), on_smooth.num_nodes());
      double apart = 0.0;
      for (std::size_t i = 0; i < on_a.num_nodes(); ++i) {
        const mesh::NodeId id(i);
        apart = std::max({apart, (on_a.node(id) - on_b.node(id)).norm(), (on_a.node(id) - on_smooth.node(id)).norm()});
      }
      EXPECT_LT(apart, 1e-10) << "P = " << P << ", n = " << n;
      EXPECT_EQ(certify_mesh(on_a, 8).invalid, 0u) << "P = " << P << ", n = " << n;
      errors.push_back(geometric_error(on_a, *a, 1.0, 8).max_rel);
      const double smooth_error = geometric_error(on_smooth, *smooth, 1.0, 8).max_rel;
      std::printf("P = %d, n = %d: nodes apart %.1e, geometric error %.3e (smooth parameters %.3e)\n", P, n, apart,
                  errors.back(), smooth_error);
    }
    for (std::size_t k = 1; k < errors.size(); ++k)
      EXPECT_GE(std::log2(errors[k - 1] / errors[k]), P + 0.5) << "P = " << P << " level " << k;
  }
}

}  // namespace
}  // namespace semimesh::ho
