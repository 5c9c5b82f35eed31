// Curving on a CAD curve whose parameter is smooth but runs very unevenly (angle = A t^4 on an arc:
// its speed 0 at one end, as an intersection curve of OCCT's Booleans can run): an edge node at the
// node set's fraction of such a parameter interval sits far from its place along the edge (a tenth
// of the way instead of half: it folded a junction hex at a wing's root on a fuselage). Where the
// parameter midpoint lies farther than a tenth of the edge from the arc-length midpoint the edge's
// nodes go by arc length.
#include "outward_prism.hpp"
#include "semimesh/ho/curving/curve_mesh.hpp"
#include "semimesh/ho/mesh_validity.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

namespace semimesh::ho {
namespace {

using Vec3 = Eigen::Vector3d;

constexpr double kArcAngle = 1.5;

Vec3 on_unit_cylinder(double u, double angle) { return Vec3(std::cos(angle), std::sin(angle), u); }

/// The quarter cylinder of radius 1, S(u, a) = (cos a, sin a, u), u in [0, 1], a in [0, kArcAngle].
class UnitQuarterCylinder final : public cad::Surface {
 public:
  UnitQuarterCylinder() : cad::Surface(0, "cylinder") {}
  cad::SurfaceKind kind() const override { return cad::SurfaceKind::Analytic; }
  std::array<cad::Interval, 2> bounds() const override { return {cad::Interval{0.0, 1.0}, cad::Interval{0.0, kArcAngle}}; }
  cad::SurfaceDerivatives derivatives(const cad::Vec2& uv) const override {
    const double a = uv.y();
    const Vec3 radial(std::cos(a), std::sin(a), 0), tangent(-std::sin(a), std::cos(a), 0);
    return {on_unit_cylinder(uv.x(), a), Vec3::UnitZ(), tangent, Vec3::Zero(), Vec3::Zero(), -radial};
  }
  bool contains(const cad::Vec2&) const override { return true; }
};

/// The arc u = `u` from angle 0 to kArcAngle, its parameter t in [0, 1] at angle kArcAngle t^power.
class UnevenArc final : public cad::Curve {
 public:
  UnevenArc(int id, double u, int power) : cad::Curve(id, "arc"), u_(u), power_(power) {}
  cad::CurveKind kind() const override { return cad::CurveKind::Analytic; }
  cad::Interval bounds() const override { return {0.0, 1.0}; }
  cad::CurveDerivatives derivatives(double t) const override {
    const double a = kArcAngle * std::pow(t, power_), da = kArcAngle * power_ * std::pow(t, power_ - 1),
                 dda = kArcAngle * power_ * (power_ - 1) * std::pow(t, std::max(0, power_ - 2));
    const Vec3 radial(std::cos(a), std::sin(a), 0), tangent(-std::sin(a), std::cos(a), 0);
    return {on_unit_cylinder(u_, a), da * tangent, dda * tangent - da * da * radial};
  }
  double parameter_of(double angle) const { return std::pow(angle / kArcAngle, 1.0 / power_); }

 private:
  double u_;
  int power_;
};

/// A straight side at angle `angle`, u = t.
class StraightSide final : public cad::Curve {
 public:
  StraightSide(int id, double angle) : cad::Curve(id, "side"), angle_(angle) {}
  cad::CurveKind kind() const override { return cad::CurveKind::Analytic; }
  cad::Interval bounds() const override { return {0.0, 1.0}; }
  cad::CurveDerivatives derivatives(double t) const override { return {on_unit_cylinder(t, angle_), Vec3::UnitZ(), Vec3::Zero()}; }

 private:
  double angle_;
};

std::unique_ptr<cad::Model> uneven_quarter_cylinder(int power) {
  auto m = std::make_unique<cad::Model>("uneven");
  const int v0 = m->add_vertex(on_unit_cylinder(0, 0)), v1 = m->add_vertex(on_unit_cylinder(0, kArcAngle)),
            v2 = m->add_vertex(on_unit_cylinder(1, kArcAngle)), v3 = m->add_vertex(on_unit_cylinder(1, 0));
  const int bottom = m->add_curve(std::make_unique<UnevenArc>(0, 0.0, power), v0, v1);
  const int side = m->add_curve(std::make_unique<StraightSide>(1, kArcAngle), v1, v2);
  const int top = m->add_curve(std::make_unique<UnevenArc>(2, 1.0, 1), v3, v2);
  const int start = m->add_curve(std::make_unique<StraightSide>(3, 0.0), v0, v3);
  m->add_surface(std::make_unique<UnitQuarterCylinder>(),
                 {cad::Loop{{{bottom, true}, {side, true}, {top, false}, {start, false}}}});
  m->finalize();
  return m;
}

/// Prisms (thickness 0.05, outward) on an n x n grid over u in [0, 0.9], angle in [0.1, 1.4]: the
/// row u = 0 on the bottom arc (attached to it at its parameter), the rest on the surface.
mesh::Mesh layer_over_the_arc(const cad::Model& model, int n) {
  const auto& arc = dynamic_cast<const UnevenArc&>(model.curve(0));
  mesh::Mesh m(1);
  std::vector<mesh::NodeId> body;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j) {
      const double u = 0.9 * i / n, angle = 0.1 + 1.3 * j / n;
      const mesh::CadAttachment at = i == 0 ? mesh::CadAttachment{mesh::CadAttachment::Curve, 0, arc.parameter_of(angle), 0.0}
                                            : mesh::CadAttachment{mesh::CadAttachment::Surface, 0, u, angle};
      body.push_back(m.add_node(on_unit_cylinder(u, angle), at));
      m.add_node(on_unit_cylinder(u, angle) + 0.05 * Vec3(std::cos(angle), std::sin(angle), 0));
    }
  add_outward_prism_grid(m, body, n, m.region_index("layer"), "body");
  return m;
}

// At order 2 the edge nodes on the arc (z = 0, radius 1) lie at their edges' angle midpoints to
// within a tenth of the edge (exactly where the parameter runs unevenly): with t^4 the first edge's
// parameter midpoint is 13 % of the edge off. On an evenly running arc (power 1) every node is at
// the midpoint by either route. Valid at orders 2 to 4.
TEST(CurveUnevenParameter, EdgeNodesOnTheCurveStayNearTheirArcLengthPlace) {
  constexpr int n = 4;
  for (int power : {4, 1}) {
    const auto model = uneven_quarter_cylinder(power);
    const mesh::Mesh curved = curve_mesh(layer_over_the_arc(*model, n), *model, {2, NodeSet::GLL, 50, 1e-10});
    std::vector<double> angles;
    for (std::size_t i = 0; i < curved.num_nodes(); ++i) {
      const Vec3 x = curved.node(mesh::NodeId(i));
      if (std::abs(x.z()) < 1e-12 && std::abs(x.head<2>().norm() - 1.0) < 1e-12) angles.push_back(std::atan2(x.y(), x.x()));
    }
    std::sort(angles.begin(), angles.end());
    ASSERT_EQ(angles.size(), static_cast<std::size_t>(2 * n + 1)) << "the row's vertices and edge nodes";
    double worst = 0.0;
    for (int k = 0; k < n; ++k) {
      const double a0 = angles[2 * k], a1 = angles[2 * k + 2];
      worst = std::max(worst, std::abs(angles[2 * k + 1] - 0.5 * (a0 + a1)) / (a1 - a0));
    }
    EXPECT_LT(worst, power == 1 ? 1e-9 : 0.1) << "power " << power;
    for (int P = 2; P <= 4; ++P)
      EXPECT_EQ(certify_mesh(curve_mesh(layer_over_the_arc(*model, n), *model, {P, NodeSet::GLL, 50, 1e-10}), 8).invalid, 0u)
          << "power " << power << ", P = " << P;
  }
}

}  // namespace
}  // namespace semimesh::ho
