// The whole NACA model: every surface meshed, closed and conforming, and the count scaling.
#include "semimesh/surface/error.hpp"
#include "semimesh/surface/mesh_quality.hpp"
#include "semimesh/surface/model_surfaces.hpp"
#include "wing_fixture.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <iostream>
#include <map>
#include <set>

namespace semimesh::surface {
namespace {

using testing::naca_model;

using PointKey = std::array<double, 3>;
PointKey key(const Vec3& p) { return {p.x(), p.y(), p.z()}; }

// Independently of the library: glues all surfaces by exact 3D coordinates; every edge must be
// shared by exactly two triangles, and the boundary of the fluid region (a ball) is a sphere.
void expect_closed_sphere(const SurfaceMeshes& meshes) {
  std::map<PointKey, int> vertex_ids;
  std::map<std::pair<int, int>, int> edge_uses;
  std::set<std::array<int, 3>> faces;
  for (const auto& m : meshes.surfaces)
    for (const auto& t : m.triangles) {
      std::array<int, 3> ids;
      for (int i = 0; i < 3; ++i) ids[i] = vertex_ids.emplace(key(m.points[t[i]]), vertex_ids.size()).first->second;
      for (int i = 0; i < 3; ++i) ++edge_uses[std::minmax(ids[i], ids[(i + 1) % 3])];
      std::array<int, 3> sorted = ids;
      std::sort(sorted.begin(), sorted.end());
      EXPECT_TRUE(faces.insert(sorted).second) << "duplicate triangle";
    }
  int bad = 0;
  for (const auto& [edge, uses] : edge_uses) bad += uses != 2;
  EXPECT_EQ(bad, 0);
  const long euler = static_cast<long>(vertex_ids.size()) - static_cast<long>(edge_uses.size()) +
                     static_cast<long>(meshes.num_triangles());
  EXPECT_EQ(euler, 2);
}

TEST(ModelSurfaces, WholeWingIsClosedAndConforming) {
  auto model = naca_model();
  SizeParams p;
  p.max_size = 1.5;
  p.min_size = 0.01;
  p.curvature_segments = 2.0;
  p.gradation = 1.25;
  p.le_size = 0.02;
  p.te_size = 0.02;
  SizeField size(*model, p);
  const auto start = std::chrono::steady_clock::now();
  const SurfaceMeshes meshes = mesh_model_surfaces(*model, size);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::cout << meshes.num_triangles() << " triangles in " << seconds << " s ("
            << meshes.num_triangles() / seconds << " triangles/s), " << size.num_sources() << " size sources\n";
  ASSERT_EQ(static_cast<int>(meshes.surfaces.size()), model->num_surfaces());
  for (const auto& m : meshes.surfaces) {
    const cad::Surface& face = model->surface(m.surface);
    EXPECT_GT(m.triangles.size(), 0u) << face.name();
    int flipped = 0, off_surface = 0;
    for (const auto& t : m.triangles) {
      const Vec3 n = (m.points[t[1]] - m.points[t[0]]).cross(m.points[t[2]] - m.points[t[0]]);
      flipped += n.dot(face.normal((m.uv[t[0]] + m.uv[t[1]] + m.uv[t[2]]) / 3.0)) <= 0.0;
    }
    for (int v = 0; v < m.num_nodes(); ++v) off_surface += face.project(m.points[v], m.uv[v]).distance > 1e-9;
    EXPECT_EQ(flipped, 0) << face.name();
    EXPECT_EQ(off_surface, 0) << face.name();
  }

  EXPECT_TRUE(check_conformity(*model, meshes).empty());
  for (const auto& line : check_conformity(*model, meshes)) ADD_FAILURE() << line;

  expect_closed_sphere(meshes);
}

// The surfaces are meshed on every thread when the model is thread-safe: each mesh is the one a
// single thread makes (a model marked not thread-safe), point for point and element for element.
TEST(ModelSurfaces, ThreadsGiveTheOneThreadMeshes) {
  auto threaded = naca_model(), alone = naca_model();
  alone->set_thread_safe(false);
  SizeParams p;
  p.max_size = 1.5;
  p.min_size = 0.01;
  p.le_size = 0.02;
  p.te_size = 0.02;
  const SurfaceMeshes a = mesh_model_surfaces(*threaded, SizeField(*threaded, p));
  const SurfaceMeshes b = mesh_model_surfaces(*alone, SizeField(*alone, p));
  ASSERT_TRUE(threaded->thread_safe());
  ASSERT_EQ(a.surfaces.size(), b.surfaces.size());
  for (std::size_t s = 0; s < a.surfaces.size(); ++s) {
    SCOPED_TRACE(threaded->surface(static_cast<int>(s)).name());
    EXPECT_EQ(a.surfaces[s].surface, static_cast<int>(s));
    EXPECT_GT(a.surfaces[s].triangles.size(), 0u);
    EXPECT_EQ(a.surfaces[s].points, b.surfaces[s].points);
    EXPECT_EQ(a.surfaces[s].triangles, b.surfaces[s].triangles);
    EXPECT_EQ(a.surfaces[s].quads, b.surfaces[s].quads);
  }
}

TEST(ModelSurfaces, SharpTaperedSweptWing) {
  mock_cad::NacaWingParams params;
  params.code = "2412";
  params.sharp_te = true;
  params.taper = 0.5;
  params.sweep_deg = 25.0;
  params.box = {-3, -3, 0, 5, 3, 4};
  auto model = mock_cad::make_naca_wing(params);
  SizeParams p;
  p.max_size = 0.6;
  p.min_size = 0.01;
  p.curvature_segments = 2.0;
  p.te_size = 0.03;
  SizeField size(*model, p);
  const SurfaceMeshes meshes = mesh_model_surfaces(*model, size);
  for (const auto& line : check_conformity(*model, meshes)) ADD_FAILURE() << line;
  expect_closed_sphere(meshes);
  for (const char* name : {"upper", "lower", "tip", "wall"}) {
    const AngleStats stats = angle_statistics(meshes.surfaces[model->find_surface(name).value()], true);
    EXPECT_GE(stats.min_deg, 20.0) << name << ": " << stats.to_string();
  }
}

TEST(ModelSurfaces, StructuredTrailingEdgeBaseConformsWithItsNeighbours) {
  auto model = naca_model({-2, -2, 0, 3, 2, 4});
  SizeParams p;
  p.max_size = 0.4;
  p.min_size = 0.01;
  p.curvature_segments = 2.0;
  SizeField size(*model, p);
  ModelMeshOptions options;
  for (const char* name : {"te_upper", "te_lower"})
    options.curve_counts[testing::curve_named(*model, name)] = {20, {Bunching::Law::Cosine, 0.0}};
  for (const char* name : {"root_te", "tip_te"}) options.curve_counts[testing::curve_named(*model, name)] = {1, {}};
  const int te_base = testing::surface_named(*model, "te_base");
  options.structured_surfaces = {te_base};
  options.split_structured = true;
  const SurfaceMeshes meshes = mesh_model_surfaces(*model, size, options);
  EXPECT_EQ(meshes.surfaces[te_base].triangles.size(), 40u);
  for (const auto& line : check_conformity(*model, meshes)) ADD_FAILURE() << line;
  expect_closed_sphere(meshes);

  options.split_structured = false;
  const SurfaceMeshes with_quads = mesh_model_surfaces(*model, size, options);
  EXPECT_EQ(with_quads.num_quads(), 20);
  for (const auto& line : check_conformity(*model, with_quads)) ADD_FAILURE() << line;
}

// A tapered wing's base is thinner at the tip (0.3 x 2.5e-3 thick) than at the root (2.5e-3): at
// te_size 1e-3 the size field gives root_te 2 or more segments and tip_te 1 (the NekMesh wing's
// base got 1 and 2). The strip takes the root's count on both, and its neighbours (the wall and
// the tip) mesh the same curve meshes.
TEST(ModelSurfaces, StructuredStripTakesTheLargerCountOfItsOppositeCurves) {
  mock_cad::NacaWingParams params;
  params.taper = 0.3;
  params.box = {-2, -2, 0, 3, 2, 4};
  auto model = mock_cad::make_naca_wing(params);
  SizeParams p;
  p.max_size = 0.4;
  p.min_size = 1e-3;
  p.curvature_segments = 0.0;
  p.te_size = 1e-3;
  p.gradation = 2.0;  // coarse away from the trailing edge: a lean test
  SizeField size(*model, p);
  const int root_te = testing::curve_named(*model, "root_te"), tip_te = testing::curve_named(*model, "tip_te");
  const int at_root = discretise_curve(*model, root_te, size).segments();
  ASSERT_GE(at_root, 2);
  ASSERT_EQ(discretise_curve(*model, tip_te, size).segments(), 1);
  ModelMeshOptions options;
  for (const char* name : {"te_upper", "te_lower"}) options.curve_counts[testing::curve_named(*model, name)] = {12, {}};
  const int te_base = testing::surface_named(*model, "te_base");
  options.structured_surfaces = {te_base};
  const SurfaceMeshes meshes = mesh_model_surfaces(*model, size, options);
  EXPECT_EQ(meshes.curves.at(root_te).segments(), at_root);
  EXPECT_EQ(meshes.curves.at(tip_te).segments(), at_root);
  EXPECT_EQ(meshes.surfaces[te_base].quads.size(), 12u * at_root);
  for (const auto& line : check_conformity(*model, meshes)) ADD_FAILURE() << line;

  // A prescribed count imposes itself on the opposite free curve; two prescribed ones must agree.
  const std::map<int, CurveCount> tip{{tip_te, {3, {}}}};
  std::vector<CurveMesh> curves = discretise_all_curves(*model, size, tip).all();
  equalise_strip_counts(*model, size, {te_base}, tip, curves);
  EXPECT_EQ(curves[root_te].segments(), 3);
  const std::map<int, CurveCount> both{{tip_te, {3, {}}}, {root_te, {4, {}}}};
  curves = discretise_all_curves(*model, size, both).all();
  EXPECT_THROW(equalise_strip_counts(*model, size, {te_base}, both, curves), SurfaceMeshError);
}

TEST(ModelSurfaces, CountScalesWithTheInverseSquareOfTheSize) {
  auto model = naca_model({-2, -2, 0, 3, 2, 4});
  auto count = [&](double h) {
    SizeParams p;
    p.max_size = h;
    p.min_size = h;
    p.curvature_segments = 0.0;
    SizeField size(*model, p);
    return mesh_model_surfaces(*model, size).num_triangles();
  };
  const int coarse = count(0.25), fine = count(0.125);
  const double ratio = static_cast<double>(fine) / coarse;
  EXPECT_GT(ratio, 3.4) << coarse << " -> " << fine;
  EXPECT_LT(ratio, 4.6) << coarse << " -> " << fine;
}

TEST(ModelSurfaces, ConformityCheckFindsAMissingTriangle) {
  auto model = naca_model({-2, -2, 0, 3, 2, 4});
  SizeParams p;
  p.max_size = 0.5;
  p.curvature_segments = 0.0;
  SizeField size(*model, p);
  SurfaceMeshes meshes = mesh_model_surfaces(*model, size);
  ASSERT_TRUE(check_conformity(*model, meshes).empty());
  meshes.surfaces[0].triangles.pop_back();
  EXPECT_FALSE(check_conformity(*model, meshes).empty());
}

}  // namespace
}  // namespace semimesh::surface
