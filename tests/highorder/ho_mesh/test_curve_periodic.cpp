// CAD curving across a seam and at poles: a thin prism layer on the analytic body of revolution
// (naca.shape = revolution: one periodic face, its seam, a pole at the nose and at the tail),
// curved at P = 1..3. Element parameters must stay continuous across the seam cut and take the
// fan's parameter at a pole, else interpolated nodes land round the other side of the body.
#include "outward_prism.hpp"
#include "semimesh/ho/curving/curve_mesh.hpp"
#include "semimesh/ho/curving/geometric_error.hpp"
#include "semimesh/ho/mesh_validity.hpp"

#include "semimesh/mock_cad/naca.hpp"
#include "semimesh/surface/model_surfaces.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <array>
#include <cstdio>
#include <map>
#include <utility>
#include <vector>

namespace semimesh::ho {
namespace {

using Vec3 = Eigen::Vector3d;

std::unique_ptr<cad::Model> revolution_body() {
  return mock_cad::load_naca(cad::Source{
      "", {{"naca.shape", "revolution"}, {"naca.code", "0012"}, {"naca.te", "sharp"}, {"naca.farfield", "false"}}});
}

/// One outward layer of prisms of thickness `thickness` on the surface mesh of the whole body,
/// nodes merged by CAD origin (seam images and pole images are one node), body nodes attached.
mesh::Mesh body_layer(const cad::Model& model, double segments_per_radian, double thickness) {
  surface::SizeParams p;
  p.max_size = 0.25;
  p.min_size = 0.001;
  p.curvature_segments = segments_per_radian;
  p.gradation = 1.3;
  const surface::SurfaceMesh sm = surface::mesh_model_surfaces(model, surface::SizeField(model, p)).surfaces.at(0);
  const cad::Surface& s = model.surface(0);
  mesh::Mesh m(1);
  std::map<std::array<int, 3>, mesh::NodeId> merged;
  std::vector<mesh::NodeId> body(sm.num_nodes()), skin(sm.num_nodes());
  for (int i = 0; i < sm.num_nodes(); ++i) {
    const surface::NodeOrigin& o = sm.origin[i];
    const std::array<int, 3> key = o.vertex >= 0 ? std::array<int, 3>{0, o.vertex, 0}
                                   : o.on_boundary() ? std::array<int, 3>{1, o.curve, o.index}
                                                     : std::array<int, 3>{2, i, 0};
    auto found = merged.find(key);
    if (found != merged.end()) {
      body[i] = found->second;
      skin[i] = found->second + 1;
      continue;
    }
    mesh::CadAttachment a;
    if (o.vertex >= 0) a = {mesh::CadAttachment::Vertex, o.vertex, 0, 0};
    else if (o.on_boundary()) a = {mesh::CadAttachment::Curve, o.curve, o.t, 0};
    else a = {mesh::CadAttachment::Surface, 0, sm.uv[i](0), sm.uv[i](1)};
    // At a pole the normal is the limit along the axis (the body's x axis).
    Vec3 n = s.normal(sm.uv[i]);
    if (n.norm() < 0.5) n = (sm.points[i].x() < 0.5 ? -1.0 : 1.0) * Vec3::UnitX();
    body[i] = m.add_node(sm.points[i], a);
    skin[i] = m.add_node(sm.points[i] + thickness * n);
    merged[key] = body[i];
  }
  const int region = m.region_index("layer");
  for (const auto& t : sm.triangles) {
    m.add_element(Shape::Prism, {body[t[0]], body[t[1]], body[t[2]], skin[t[0]], skin[t[1]], skin[t[2]]}, region);
    m.add_boundary_face("body", Shape::Triangle, {body[t[0]], body[t[2]], body[t[1]]});
  }
  return m;
}

TEST(CurvePeriodic, GeometricErrorFallsWithOrderAcrossTheSeamAndAtThePoles) {
  const auto model = revolution_body();
  const mesh::Mesh linear = body_layer(*model, 2.0, 0.001);
  double previous = 0.0;
  for (int P = 1; P <= 3; ++P) {
    CurvingStats st;
    const mesh::Mesh curved = curve_mesh(linear, *model, {P, NodeSet::GLL, 50, 1e-10}, &st);
    const double error = geometric_error(curved, *model, 1.0, 6).max_rel;
    std::printf("revolution P = %d: max relative geometric error %.3e\n", P, error);
    for (std::size_t i = 0; i < curved.num_nodes(); ++i)
      if (curved.cad_attachment(mesh::NodeId(i)).kind != mesh::CadAttachment::None) {
        ASSERT_LT(model->surface(0).project(curved.node(mesh::NodeId(i))).distance, 1e-9) << "node " << i << " off the body";
      }
    // Measured: 3.2e-3, 4.1e-5, 1.7e-5. From P = 2 to 3 the error stalls at the sharp tail, a
    // cone's apex (not smooth: no order converges like h^(P+1) at it). Without the
    // continuity across the seam the error stayed at 3e-2 to 5e-2 at every order.
    if (P == 2) {
      EXPECT_LT(error, 0.05 * previous) << "P = " << P;
    }
    if (P == 3) {
      EXPECT_LE(error, previous) << "P = " << P;
    }
    previous = error;
  }
}

constexpr double kPi = 3.14159265358979323846;

/// An ellipsoid with three different semi-axes, S(u, w) = (a cos u, b sin u cos w, c sin u sin w),
/// u in [0, pi] (its poles at u = 0 and pi), w in [0, 2 pi] (period): smooth at its poles, unlike
/// the NACA body of revolution, whose nose x ~ r^2 + r^3 is C2 only there.
class Ellipsoid final : public cad::Surface {
 public:
  Ellipsoid() : cad::Surface(0, "ellipsoid") {}
  cad::SurfaceKind kind() const override { return cad::SurfaceKind::Analytic; }
  std::array<cad::Interval, 2> bounds() const override { return {cad::Interval{0.0, kPi}, cad::Interval{0.0, 2 * kPi}}; }
  cad::SurfaceDerivatives derivatives(const cad::Vec2& uv) const override {
    const double cu = std::cos(uv.x()), su = std::sin(uv.x()), cw = std::cos(uv.y()), sw = std::sin(uv.y());
    return {Vec3(a * cu, b * su * cw, c * su * sw),  Vec3(-a * su, b * cu * cw, c * cu * sw),
            Vec3(0, -b * su * sw, c * su * cw),      Vec3(-a * cu, -b * su * cw, -c * su * sw),
            Vec3(0, -b * cu * sw, c * cu * cw),      Vec3(0, -b * su * cw, -c * su * sw)};
  }
  bool contains(const cad::Vec2&) const override { return true; }
  std::optional<double> period(int direction) const override {
    cad::Surface::period(direction);
    return direction == 1 ? std::optional<double>(2 * kPi) : std::nullopt;
  }
  static constexpr double a = 0.6, b = 1.0, c = 0.8;
};

/// The seam w = 0 from the pole at u = 0 to the one at u = pi.
class EllipsoidSeam final : public cad::Curve {
 public:
  EllipsoidSeam() : cad::Curve(0, "seam") {}
  cad::CurveKind kind() const override { return cad::CurveKind::Analytic; }
  cad::Interval bounds() const override { return {0.0, kPi}; }
  cad::CurveDerivatives derivatives(double t) const override {
    const double a = Ellipsoid::a, b = Ellipsoid::b;
    return {Vec3(a * std::cos(t), b * std::sin(t), 0), Vec3(-a * std::sin(t), b * std::cos(t), 0),
            Vec3(-a * std::cos(t), -b * std::sin(t), 0)};
  }
};

class Pole final : public cad::Curve {
 public:
  Pole(int id, const Vec3& at) : cad::Curve(id, "pole"), at_(at) {}
  cad::CurveKind kind() const override { return cad::CurveKind::Analytic; }
  cad::Interval bounds() const override { return {0.0, 2 * kPi}; }
  cad::CurveDerivatives derivatives(double) const override { return {at_, Vec3::Zero(), Vec3::Zero()}; }
  bool is_degenerate() const override { return true; }

 private:
  Vec3 at_;
};

std::unique_ptr<cad::Model> ellipsoid() {
  auto m = std::make_unique<cad::Model>("test");
  const int north = m->add_vertex(Vec3(Ellipsoid::a, 0, 0), "north");
  const int south = m->add_vertex(Vec3(-Ellipsoid::a, 0, 0), "south");
  const int seam = m->add_curve(std::make_unique<EllipsoidSeam>(), north, south);
  const int pn = m->add_curve(std::make_unique<Pole>(1, m->vertex(north).point), north, north);
  const int ps = m->add_curve(std::make_unique<Pole>(2, m->vertex(south).point), south, south);
  m->add_surface(std::make_unique<Ellipsoid>(), {cad::Loop{{{pn, true}, {seam, true}, {ps, false}, {seam, false}}}});
  m->finalize();
  return m;
}

/// `rings` rings of triangles around the pole at u = 0 of model's surface 0, ring k at u = k h with
/// 6 k nodes, as one layer of prisms of thickness h / 10: the pole a node on CAD vertex 0, the
/// rings attached to the surface. Refining h keeps the shape (the elements span a fixed angle at the pole).
mesh::Mesh pole_rings(const cad::Model& model, double h, int rings, const Vec3& pole_normal) {
  const cad::Surface& s = model.surface(0);
  mesh::Mesh m(1);
  const auto add = [&](const mesh::CadAttachment& a, const cad::Vec2& uv) {
    Vec3 n = s.normal(uv);
    if (n.norm() < 0.5) n = pole_normal;
    const mesh::NodeId body = m.add_node(s.point(uv), a);
    m.add_node(s.point(uv) + 0.1 * h * n);
    return body;
  };
  std::vector<std::vector<mesh::NodeId>> ring(rings + 1);
  ring[0].push_back(add({mesh::CadAttachment::Vertex, 0, 0, 0}, {0.0, 0.0}));
  for (int k = 1; k <= rings; ++k)
    for (int j = 0; j < 6 * k; ++j) {
      const cad::Vec2 uv(k * h, 0.3 + 2 * kPi * j / (6 * k));
      ring[k].push_back(add({mesh::CadAttachment::Surface, 0, uv.x(), uv.y()}, uv));
    }
  const int region = m.region_index("layer");
  const auto triangle = [&](mesh::NodeId a, mesh::NodeId b, mesh::NodeId c) { add_outward_prism(m, a, b, c, region, "body"); };
  // Each sixth of the strip between rings k and k + 1: k + 1 triangles on the outer ring's
  // segments, k on the inner ring's.
  for (int k = 0; k < rings; ++k)
    for (int j = 0; j < 6; ++j) {
      const auto in = [&](int i) { return ring[k][k == 0 ? 0 : (j * k + i) % (6 * k)]; };
      const auto out = [&](int i) { return ring[k + 1][(j * (k + 1) + i) % (6 * (k + 1))]; };
      for (int i = 0; i <= k; ++i) triangle(in(i), out(i), out(i + 1));
      for (int i = 0; i < k; ++i) triangle(in(i), out(i + 1), in(i + 1));
    }
  return m;
}

/// Max geometric error of the pole fan at h, h / 2, h / 4, curved at order P; each curved fan valid.
std::vector<double> pole_errors(const cad::Model& model, const Vec3& pole_normal, double h, int P) {
  std::vector<double> e;
  for (double size : {h, h / 2, h / 4}) {
    const mesh::Mesh curved = curve_mesh(pole_rings(model, size, 2, pole_normal), model, {P, NodeSet::GLL, 50, 1e-10});
    e.push_back(geometric_error(curved, model, 1.0, 8).max_rel);
    EXPECT_EQ(certify_mesh(curved, 8).invalid, 0u) << "P = " << P << ", h = " << size;
  }
  std::printf("pole P = %d: max relative geometric error", P);
  for (double x : e) std::printf(" %.3e", x);
  std::printf("; rates");
  for (std::size_t k = 1; k < e.size(); ++k) std::printf(" %.2f", std::log2(e[k - 1] / e[k]));
  std::printf("\n");
  return e;
}

// At a pole the surface's parameters are polar: an element interpolated linearly in them is a
// polar patch spanning a fixed angle however small it is, and its error falls like h^2 at every
// order (measured before the pole chart: rates 2.0 at P = 2, 3, 4; now 2.0, 4.0, 4.0, 6.0 at
// P = 1..4). Expected here, as on the other faces (test_curve_mesh.cpp): max error ~ h^(P+1), every
// observed rate >= P + 0.5, on the fan of 30 triangles around a pole of a smooth surface.
TEST(CurvePeriodic, GeometricErrorConvergesAtAPoleUnderRefinement) {
  const auto model = ellipsoid();
  for (int P = 1; P <= 4; ++P) {
    const std::vector<double> e = pole_errors(*model, Vec3::UnitX(), 0.1, P);
    for (std::size_t k = 1; k < e.size(); ++k) EXPECT_GE(std::log2(e[k - 1] / e[k]), P + 0.5) << "P = " << P << " level " << k;
  }
}


// Five rings round the ellipsoid's pole at P = 4 with the default reach (3 sides): the reach's edge
// runs through the third and fourth rings. A face there with a side placed by parameters takes the
// parameters too. When it was projected from the straight-sided face instead, its interior nodes
// did not meet that side's: max error 1.8e-6, 4.4e-7, 1.1e-7 and min scaled Jacobian 0.49, 0.51,
// 0.51 at h = 0.04, 0.02, 0.01; now 5.4e-7, 1.3e-7, 3.4e-8 and 0.57, 0.64, 0.67 (pinned: error
// <= 1e-6 (h / 0.04)^2, scaled Jacobian >= 0.5). The error falls like h^2 only: beyond a reach
// counted in element sides the elements span a fixed angle at the pole in its polar parameters,
// whatever h (projecting every face: 3.7e-11, 5.7e-13, 1.6e-14). Pinned too: rate >= 1.8.
TEST(CurvePeriodic, AFaceAtThePoleReachsEdgeTakesTheChartOfItsSides) {
  const auto model = ellipsoid();
  std::vector<double> e;
  for (double h : {0.04, 0.02, 0.01}) {
    const mesh::Mesh curved = curve_mesh(pole_rings(*model, h, 5, Vec3::UnitX()), *model, {4, NodeSet::GLL, 50, 1e-10});
    const double sj = certify_mesh(curved, 8).min_scaled_jacobian;
    e.push_back(geometric_error(curved, *model, 1.0, 8).max_rel);
    std::printf("pole rings h = %g: min scaled Jacobian %.3f, max relative geometric error %.3e\n", h, sj, e.back());
    EXPECT_GE(sj, 0.5) << "h = " << h;
    EXPECT_LE(e.back(), 1e-6 * (h / 0.04) * (h / 0.04)) << "h = " << h;
  }
  for (std::size_t k = 1; k < e.size(); ++k) EXPECT_GE(std::log2(e[k - 1] / e[k]), 1.8) << "level " << k;
}

// The NACA body of revolution's nose pole is C2 only (x = X(u) = u^2 while the radius Y(u) has a u^2
// term, so x(r) has an r^3 term): no order converges like h^(P+1) there (measured now: rates 2.0,
// 4.4/2.5, 4.0, 3.3/3.0 at P = 1..4). Expected: every rate >= 2.4 above P = 1, where the polar
// parameters gave 2.0 at every P >= 2.
TEST(CurvePeriodic, GeometricErrorFallsAtTheNosePoleOfTheRevolutionBody) {
  const auto model = revolution_body();
  ASSERT_TRUE(model->curve(1).is_degenerate());  // the nose pole, at CAD vertex 0
  ASSERT_LT(model->vertex(0).point.norm(), 1e-12);
  for (int P = 1; P <= 4; ++P) {
    const std::vector<double> e = pole_errors(*model, -Vec3::UnitX(), 0.01, P);
    for (std::size_t k = 1; k < e.size(); ++k)
      EXPECT_GE(std::log2(e[k - 1] / e[k]), P == 1 ? 1.5 : 2.4) << "P = " << P << " level " << k;
  }
}

}  // namespace
}  // namespace semimesh::ho
