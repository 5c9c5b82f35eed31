// Periodic faces with a seam and poles: the analytic body of revolution (naca.shape = revolution)
// meshed whole. Checked against what does not come from the mesher: the surface of revolution's
// area by 1D quadrature of 2 pi r ds from the NACA formula, and the topology of a sphere (the
// triangles, their nodes merged by CAD origin, close up with Euler characteristic 2).
#include "semimesh/surface/model_surfaces.hpp"

#include "semimesh/mock_cad/naca.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <set>

namespace semimesh::surface {
namespace {

constexpr double kChord = 2.0, kThickness = 0.12;

std::unique_ptr<cad::Model> revolution_body() {
  return mock_cad::load_naca(cad::Source{
      "", {{"naca.shape", "revolution"}, {"naca.code", "0012"}, {"naca.te", "sharp"}, {"naca.farfield", "false"}, {"naca.chord", "2"}}});
}

/// NACA 4-digit half thickness with the closed (sharp) TE coefficient (Abbott & von Doenhoff 1959).
double half_thickness(double x) {
  return 5.0 * kThickness * (0.2969 * std::sqrt(x) - 0.1260 * x - 0.3516 * x * x + 0.2843 * x * x * x - 0.1036 * x * x * x * x);
}

/// 2 pi int r ds over the meridian, x = u^2 (smooth in u at the nose), composite Simpson with
/// central-difference derivatives.
double area_of_revolution() {
  const int n = 20000;
  const double h = 1.0 / n, e = 1e-7;
  auto meridian = [](double u) { return Vec2(kChord * u * u, kChord * half_thickness(u * u)); };
  auto integrand = [&](double u) {
    const double a = std::max(0.0, u - e), b = std::min(1.0, u + e);
    return 2 * M_PI * meridian(u).y() * ((meridian(b) - meridian(a)) / (b - a)).norm();
  };
  double sum = integrand(0.0) + integrand(1.0);
  for (int i = 1; i < n; ++i) sum += (i % 2 ? 4.0 : 2.0) * integrand(i * h);
  return sum * h / 3.0;
}

double triangle_area(const SurfaceMesh& m, const std::array<int, 3>& t) {
  return 0.5 * (m.points[t[1]] - m.points[t[0]]).cross(m.points[t[2]] - m.points[t[0]]).norm();
}

/// Node key that merges a mesh's images of one point: the CAD vertex, or the curve node, or the
/// interior node itself.
std::array<int, 3> merged_key(const SurfaceMesh& m, int node) {
  const NodeOrigin& o = m.origin[node];
  if (o.vertex >= 0) return {0, o.vertex, 0};
  if (o.on_boundary()) return {1, o.curve, o.index};
  return {2, node, 0};
}

/// Sizes from the curvature (the body's radius shrinks to 0 at the poles): `segments` per radian.
SurfaceMeshes mesh_body(const cad::Model& model, double segments) {
  SizeParams p;
  p.max_size = 0.5;
  p.min_size = 0.002;
  p.curvature_segments = segments;
  p.gradation = 1.3;
  return mesh_model_surfaces(model, SizeField(model, p));
}

TEST(PeriodicSurface, BodyOfRevolutionIsAClosedSphereOfOutwardTriangles) {
  const auto model = revolution_body();
  const SurfaceMeshes meshes = mesh_body(*model, 2.0);
  EXPECT_TRUE(check_conformity(*model, meshes).empty());
  const SurfaceMesh& m = meshes.surfaces.at(0);
  ASSERT_GT(m.triangles.size(), 100u);
  const cad::Surface& body = model->surface(0);
  std::map<std::array<int, 3>, int> merged;
  std::map<std::pair<int, int>, int> directed;  // merged edge -> uses
  for (const auto& t : m.triangles) {
    std::array<int, 3> v;
    for (int k = 0; k < 3; ++k) v[k] = merged.emplace(merged_key(m, t[k]), static_cast<int>(merged.size())).first->second;
    ASSERT_TRUE(v[0] != v[1] && v[1] != v[2] && v[2] != v[0]) << "a triangle with two corners at one point";
    EXPECT_GT(triangle_area(m, t), 0.0);
    // Outward: along the fluid normal at the parameters' centroid (the parameter plane is cut
    // open along the seam, so a triangle's (u, v) do not wrap).
    const Vec2 uv = (m.uv[t[0]] + m.uv[t[1]] + m.uv[t[2]]) / 3.0;
    const Vec3 n = (m.points[t[1]] - m.points[t[0]]).cross(m.points[t[2]] - m.points[t[0]]);
    EXPECT_GT(n.dot(body.normal(uv)), 0.0) << "triangle at " << body.point(uv).transpose() << " faces the solid";
    for (int k = 0; k < 3; ++k) ++directed[{v[k], v[(k + 1) % 3]}];
  }
  int edges = 0;
  for (const auto& [e, uses] : directed) {
    EXPECT_EQ(uses, 1) << "edge used twice in one direction";
    EXPECT_EQ(directed.count({e.second, e.first}), 1u) << "open edge: the seam or a pole is not closed";
    if (e.first < e.second) ++edges;
  }
  const int vertices = static_cast<int>(merged.size()), faces = static_cast<int>(m.triangles.size());
  EXPECT_EQ(vertices - edges + faces, 2) << "V - E + F of a closed surface of genus 0";
  for (int i = 0; i < m.num_nodes(); ++i) EXPECT_LE(body.project(m.points[i]).distance, 1e-9);
}

// Linear triangles inscribed in a convex surface: the area error falls like h^2.
TEST(PeriodicSurface, BodyOfRevolutionAreaConvergesToTheQuadrature) {
  const auto model = revolution_body();
  const double exact = area_of_revolution();
  double previous_error = 0.0;
  for (double segments : {2.0, 4.0, 8.0}) {
    const SurfaceMesh m = mesh_body(*model, segments).surfaces.at(0);
    double area = 0.0;
    for (const auto& t : m.triangles) area += triangle_area(m, t);
    const double error = std::abs(area - exact) / exact;
 std::cout << "[ info ] " << segments << " segments per radian: " << m.triangles.size() << " triangles, area error " << error << "\n";
    EXPECT_LT(error, 0.02);
    if (previous_error > 0.0) {
      EXPECT_LT(error, 0.5 * previous_error) << segments << " segments per radian";
    }
    previous_error = error;
  }
}

}  // namespace
}  // namespace semimesh::surface
