// The surface mesh must not depend on how a CAD backend describes the same geometry: curve ids,
// the direction and start of the loops, and (u, v) or points that differ by rounding noise
// (two backends agreeing to ~1e-13) all give the same mesh, node for node.
#include "semimesh/surface/curve_discretisation.hpp"
#include "semimesh/surface/surface_mesh.hpp"
#include "wing_fixture.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <vector>

namespace semimesh::surface {
namespace {

constexpr double kNoise = 1e-13;

// A curve of another model under a new id.
class RenumberedCurve : public cad::Curve {
 public:
  RenumberedCurve(int id, const cad::Curve& base) : cad::Curve(id, base.name()), base_(base) {}
  cad::CurveKind kind() const override { return base_.kind(); }
  cad::Interval bounds() const override { return base_.bounds(); }
  cad::CurveDerivatives derivatives(double t) const override { return base_.derivatives(t); }
  Vec3 point(double t) const override { return base_.point(t); }
  cad::CurveProjection project(const Vec3& x, std::optional<double> guess) const override { return base_.project(x, guess); }
  double arc_length(double a, double b) const override { return base_.arc_length(a, b); }
  double parameter_at_length(double t_start, double s) const override { return base_.parameter_at_length(t_start, s); }

 private:
  const cad::Curve& base_;
};

// A surface of another model whose points and projections are off by rounding-sized amounts.
class NoisySurface : public cad::Surface {
 public:
  explicit NoisySurface(const cad::Surface& base) : cad::Surface(base.id(), base.name(), base.orientation()), base_(base) {}
  cad::SurfaceKind kind() const override { return base_.kind(); }
  std::array<cad::Interval, 2> bounds() const override { return base_.bounds(); }
  cad::SurfaceDerivatives derivatives(const Vec2& uv) const override {
    cad::SurfaceDerivatives d = base_.derivatives(uv);
    d.p += noise(uv);
    return d;
  }
  Vec3 point(const Vec2& uv) const override { return base_.point(uv) + noise(uv); }
  bool contains(const Vec2& uv) const override { return base_.contains(uv); }
  cad::SurfaceProjection project(const Vec3& x, std::optional<Vec2> guess) const override {
    cad::SurfaceProjection p = base_.project(x, guess);
    p.uv += kNoise * Vec2(1.0 + p.uv.y(), 1.0 - p.uv.x());
    return p;
  }

 private:
  static Vec3 noise(const Vec2& uv) { return kNoise * Vec3(1.0 - uv.y(), uv.x(), 1.0 + uv.x() * uv.y()); }
  const cad::Surface& base_;
};

// The same geometry as `base`, with the curves numbered backwards, every loop walked the other
// way from another start, and noisy surfaces.
std::unique_ptr<cad::Model> redescribed(const cad::Model& base) {
  auto model = std::make_unique<cad::Model>("redescribed");
  for (int v = 0; v < base.num_vertices(); ++v) model->add_vertex(base.vertex(v).point, base.vertex(v).name);
  const int n = base.num_curves();
  for (int c = n - 1; c >= 0; --c) {
    const auto ends = base.curve_vertices(c);
    model->add_curve(std::make_unique<RenumberedCurve>(n - 1 - c, base.curve(c)), ends[0], ends[1]);
  }
  for (int s = 0; s < base.num_surfaces(); ++s) {
    std::vector<cad::Loop> loops;
    for (const cad::Loop& loop : base.loops(s)) {
      cad::Loop reversed;
      for (auto use = loop.uses.rbegin(); use != loop.uses.rend(); ++use)
        reversed.uses.push_back(cad::CurveUse{n - 1 - use->curve, !use->forward});
      std::rotate(reversed.uses.begin(), reversed.uses.begin() + 1, reversed.uses.end());
      loops.push_back(reversed);
    }
    model->add_surface(std::make_unique<NoisySurface>(base.surface(s)), std::move(loops));
  }
  model->set_units(base.units(), base.scale_applied());
  model->set_tolerance(base.tolerance());
  model->finalize();
  return model;
}

// Curve meshes of `base` under the curve ids of `redescribed(base)`.
CurveMeshes renumbered(const CurveMeshes& curves) {
  std::vector<CurveMesh> meshes(curves.all().rbegin(), curves.all().rend());
  for (int c = 0; c < static_cast<int>(meshes.size()); ++c) meshes[c].curve = c;
  return CurveMeshes(std::move(meshes));
}

TEST(BackendIndependence, RedescribedSurfacesGiveTheSameMeshNodeForNode) {
  const auto base = testing::naca_model({-2, -2, 0, 3, 2, 4});
  const auto other = redescribed(*base);
  SizeParams uniform;
  uniform.max_size = 0.15;
  const SizeField size(*base, uniform);
  const CurveMeshes curves = discretise_all_curves(*base, size);
  const CurveMeshes other_curves = renumbered(curves);
  for (const char* name : {"upper", "lower", "tip", "wall"}) {
    SCOPED_TRACE(name);
    const int s = testing::surface_named(*base, name);
    const SurfaceMesh a = mesh_surface(*base, s, curves, size);
    const SurfaceMesh b = mesh_surface(*other, s, other_curves, size);
    ASSERT_EQ(a.num_nodes(), b.num_nodes());
    ASSERT_EQ(a.triangles.size(), b.triangles.size());
    EXPECT_GT(a.num_nodes(), 40);
    double worst = 0.0;
    for (int i = 0; i < a.num_nodes(); ++i) worst = std::max(worst, (a.points[i] - b.points[i]).norm());
    EXPECT_LT(worst, 1e-9);
    EXPECT_EQ(a.triangles, b.triangles);
  }
}

}  // namespace
}  // namespace semimesh::surface
