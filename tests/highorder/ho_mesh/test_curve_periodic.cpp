// CAD curving across a seam and at poles: a thin prism layer on the analytic body of revolution
// (naca.shape = revolution: one periodic face, its seam, a pole at the nose and at the tail),
// curved at P = 1..3. Element parameters must stay continuous across the seam cut and take the
// fan's parameter at a pole, else interpolated nodes land round the other side of the body.
#include "semimesh/ho/curving/curve_mesh.hpp"
#include "semimesh/ho/curving/geometric_error.hpp"

#include "semimesh/mock_cad/naca.hpp"
#include "semimesh/surface/model_surfaces.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <array>
#include <cstdio>
#include <map>
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
    // Measured: 2.7e-3, 4.9e-5, 2.8e-5. From P = 2 to 3 the error stalls at the poles (the
    // sharp tail is a cone's apex): P + 1 convergence there is not reached yet. Without the
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

}  // namespace
}  // namespace semimesh::ho
