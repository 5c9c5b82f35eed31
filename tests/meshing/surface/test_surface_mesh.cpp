// One surface at a time: orientation, nodes on the CAD, 3D quality, areas, structured strips.
#include "semimesh/surface/error.hpp"
#include "semimesh/surface/mesh_quality.hpp"
#include "semimesh/surface/surface_mesh.hpp"
#include "wing_fixture.hpp"

#include <gtest/gtest.h>

#include <iostream>
#include <map>
#include <string>
#include <vector>

namespace semimesh::surface {
namespace {

using testing::curve_named;
using testing::naca_model;
using testing::surface_named;

SizeParams wing_sizes() {
  SizeParams p;
  p.max_size = 1.0;
  p.min_size = 0.01;
  p.curvature_segments = 2.0;
  p.gradation = 1.25;
  return p;
}

double mesh_area(const SurfaceMesh& m) {
  double area = 0.0;
  for (const auto& t : m.triangles)
    area += 0.5 * (m.points[t[1]] - m.points[t[0]]).cross(m.points[t[2]] - m.points[t[0]]).norm();
  return area;
}

class WingSurface : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    model_ = naca_model().release();
    size_ = new SizeField(*model_, wing_sizes());
    curves_ = new CurveMeshes(discretise_all_curves(*model_, *size_));
  }
  static void TearDownTestSuite() {
    delete curves_;
    delete size_;
    delete model_;
  }
  static cad::Model* model_;
  static SizeField* size_;
  static CurveMeshes* curves_;
};
cad::Model* WingSurface::model_ = nullptr;
SizeField* WingSurface::size_ = nullptr;
CurveMeshes* WingSurface::curves_ = nullptr;

TEST_F(WingSurface, TrianglesFaceTheFluidAndNodesLieOnTheSurface) {
  for (const char* name : {"upper", "lower", "te_base", "tip", "wall"}) {
    const int s = surface_named(*model_, name);
    const SurfaceMesh m = mesh_surface(*model_, s, *curves_, *size_);
    const cad::Surface& face = model_->surface(s);
    ASSERT_GT(m.triangles.size(), 10u) << name;
    for (const auto& t : m.triangles) {
      const Vec3 n = (m.points[t[1]] - m.points[t[0]]).cross(m.points[t[2]] - m.points[t[0]]);
      const Vec2 uv = (m.uv[t[0]] + m.uv[t[1]] + m.uv[t[2]]) / 3.0;
      EXPECT_GT(n.normalized().dot(face.normal(uv)), 0.5) << name;
    }
    for (int v = 0; v < m.num_nodes(); ++v) {
      const auto proj = face.project(m.points[v], m.uv[v]);
      EXPECT_LT(proj.distance, 1e-9) << name << " node " << v;
      EXPECT_TRUE(proj.inside) << name << " node " << v;
      EXPECT_LT((face.point(m.uv[v]) - m.points[v]).norm(), 1e-9) << name << " node " << v;
    }
  }
}

TEST_F(WingSurface, BoundaryNodesAreTheCurveNodes) {
  const int s = surface_named(*model_, "wall");
  const SurfaceMesh m = mesh_surface(*model_, s, *curves_, *size_);
  int boundary = 0;
  for (int v = 0; v < m.num_nodes(); ++v) {
    if (!m.origin[v].on_boundary()) continue;
    ++boundary;
    const CurveMesh& cm = curves_->at(m.origin[v].curve);
    EXPECT_EQ(m.points[v], cm.points[m.origin[v].index]);
    EXPECT_EQ(m.origin[v].t, cm.t[m.origin[v].index]);
  }
  // Each loop node once: curve nodes minus the shared vertex ends.
  int expected = 0;
  for (const auto& loop : model_->loops(s))
    for (const auto& use : loop.uses) expected += curves_->at(use.curve).segments();
  EXPECT_EQ(boundary, expected);
}

TEST_F(WingSurface, MinimumAngleAwayFromTheBoundary) {
  for (const char* name : {"upper", "lower", "tip", "wall"}) {
    const SurfaceMesh m = mesh_surface(*model_, surface_named(*model_, name), *curves_, *size_);
    const AngleStats stats = angle_statistics(m, true);
    EXPECT_GT(stats.triangles, static_cast<int>(m.triangles.size()) / 3) << name;
    EXPECT_GE(stats.min_deg, 20.0) << name << ": " << stats.to_string();
    std::cout << name << ": " << stats.to_string() << "\n";
  }
}

TEST_F(WingSurface, EdgesFollowTheSizeInThreeDimensions) {
  // The upper skin maps u to x = u^2: a parameter-space mesh would be stretched near the LE.
  const int s = surface_named(*model_, "upper");
  const SurfaceMesh m = mesh_surface(*model_, s, *curves_, *size_);
  int long_edges = 0, edges = 0;
  for (const auto& t : m.triangles)
    for (int i = 0; i < 3; ++i) {
      const Vec3 &a = m.points[t[i]], &b = m.points[t[(i + 1) % 3]];
      ++edges;
      if ((b - a).norm() > 1.5 * (*size_)(0.5 * (a + b))) ++long_edges;
    }
  EXPECT_EQ(long_edges, 0) << "of " << edges;
}

// Area in the (x, y) plane of the closed polygon through the nodes of a wing section: upper
// curve LE -> TE, TE base lower -> upper reversed, lower curve TE -> LE (shoelace formula).
double section_polygon_area(const cad::Model& model, const CurveMeshes& curves, const std::string& level) {
  std::vector<Vec3> ring;
  const auto& upper = curves.at(curve_named(model, level + "_upper")).points;
  const auto& base = curves.at(curve_named(model, level + "_te")).points;
  const auto& lower = curves.at(curve_named(model, level + "_lower")).points;
  ring.insert(ring.end(), upper.begin(), upper.end());
  ring.insert(ring.end(), base.rbegin() + 1, base.rend());
  ring.insert(ring.end(), lower.rbegin() + 1, lower.rend() - 1);
  double twice = 0.0;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const Vec3 &a = ring[i], &b = ring[(i + 1) % ring.size()];
    twice += a.x() * b.y() - b.x() * a.y();
  }
  return 0.5 * std::abs(twice);
}

TEST_F(WingSurface, PlanarAreas) {
  const SurfaceMesh xmax = mesh_surface(*model_, surface_named(*model_, "box_xmax"), *curves_, *size_);
  EXPECT_NEAR(mesh_area(xmax), 20.0 * 10.0, 1e-9);
  // The trimmed faces cover exactly the box minus (wall) or inside of (tip) the polygon of the
  // section's curve nodes...
  const double root_polygon = section_polygon_area(*model_, *curves_, "root");
  const double tip_polygon = section_polygon_area(*model_, *curves_, "tip");
  const SurfaceMesh wall = mesh_surface(*model_, surface_named(*model_, "wall"), *curves_, *size_);
  EXPECT_NEAR(mesh_area(wall), 21.0 * 20.0 - root_polygon, 1e-9);
  const SurfaceMesh tip = mesh_surface(*model_, surface_named(*model_, "tip"), *curves_, *size_);
  EXPECT_NEAR(mesh_area(tip), tip_polygon, 1e-12);
  // ...which approaches the analytic section area from below, the error (circular segments,
  // about kappa h^3 / 12 each) falling like h^2 under uniform sizes.
  const double section = testing::naca_section_area(0.12);
  EXPECT_GT(section - tip_polygon, 0.0);
  EXPECT_LT(section - tip_polygon, 0.015 * section);
  auto uniform_tip_error = [&](double h) {
    SizeParams p;
    p.max_size = p.min_size = h;
    p.curvature_segments = 0.0;
    const SizeField uniform(*model_, p);
    const CurveMeshes curves = discretise_all_curves(*model_, uniform);
    return section - mesh_area(mesh_surface(*model_, surface_named(*model_, "tip"), curves, uniform));
  };
  const double coarse_error = uniform_tip_error(0.04), fine_error = uniform_tip_error(0.02);
  EXPECT_GT(fine_error, 0.0);
  EXPECT_GT(coarse_error / fine_error, 3.0) << coarse_error << " -> " << fine_error;
  EXPECT_LT(coarse_error / fine_error, 5.0) << coarse_error << " -> " << fine_error;
}

TEST_F(WingSurface, StructuredTrailingEdgeBase) {
  std::map<int, CurveCount> counts{{curve_named(*model_, "te_upper"), {12, {Bunching::Law::Tanh, 1.5}}},
                                   {curve_named(*model_, "te_lower"), {12, {Bunching::Law::Tanh, 1.5}}},
                                   {curve_named(*model_, "root_te"), {2, {}}},
                                   {curve_named(*model_, "tip_te"), {2, {}}}};
  const CurveMeshes curves = discretise_all_curves(*model_, *size_, counts);
  const int s = surface_named(*model_, "te_base");
  const cad::Surface& face = model_->surface(s);
  const SurfaceMesh quads = mesh_surface_structured(*model_, s, curves);
  EXPECT_EQ(quads.quads.size(), 24u);
  EXPECT_EQ(quads.num_nodes(), 3 * 13);
  for (const auto& q : quads.quads) {
    const Vec3 n = (quads.points[q[2]] - quads.points[q[0]]).cross(quads.points[q[3]] - quads.points[q[1]]);
    EXPECT_GT(n.normalized().dot(face.normal(quads.uv[q[0]])), 0.99);
  }
  // The strip covers the TE base: its height 2 y_t(1) (= 0.00252 for t = 0.12) times the span 3.
  const double base_height = 2.0 * testing::naca_half_thickness(0.12, 1.0);
  double area = 0.0;
  for (const auto& q : quads.quads)
    area += 0.5 * (quads.points[q[2]] - quads.points[q[0]]).cross(quads.points[q[3]] - quads.points[q[1]]).norm();
  EXPECT_NEAR(area, base_height * 3.0, 1e-9);

  const SurfaceMesh tris = mesh_surface_structured(*model_, s, curves, true);
  EXPECT_EQ(tris.triangles.size(), 48u);
  EXPECT_TRUE(tris.quads.empty());
  // Unequal opposite counts are refused with the counts in the message.
  counts[curve_named(*model_, "tip_te")] = {3, {}};
  EXPECT_THROW(mesh_surface_structured(*model_, s, discretise_all_curves(*model_, *size_, counts)), SurfaceMeshError);
  EXPECT_THROW(mesh_surface_structured(*model_, surface_named(*model_, "wall"), curves), SurfaceMeshError);
}

}  // namespace
}  // namespace semimesh::surface
