// Node normals on small hand-built bodies whose answers are known in closed form.
#include "semimesh/nearfield/error.hpp"
#include "semimesh/nearfield/node_normals.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <string>

namespace semimesh::nearfield {
namespace {

BodyMesh body_of(std::vector<Vec3> points, std::vector<std::array<int, 3>> triangles) {
  BodyMesh body;
  body.points = std::move(points);
  body.cad.resize(body.points.size());
  body.node_surface.assign(body.points.size(), 0);
  body.triangle_surface.assign(triangles.size(), 0);
  body.triangles = std::move(triangles);
  return body;
}

// The corner of the cube [-1,0]^3 at the origin: three faces with outward normals +x, +y, +z,
// each split into two triangles (fans of 2 triangles per face keep the angle weights equal).
BodyMesh cube_corner() {
  return body_of({{0, 0, 0}, {-1, 0, 0}, {0, -1, 0}, {0, 0, -1}, {-1, -1, 0}, {0, -1, -1}, {-1, 0, -1}},
                 {{0, 4, 2}, {0, 1, 4},    // face z = 0, normal +z
                  {0, 2, 5}, {0, 5, 3},    // face x = 0, normal +x
                  {0, 3, 6}, {0, 6, 1}});  // face y = 0, normal +y
}

TEST(NodeNormals, CubeCornerGetsTheDiagonal) {
  const BodyMesh body = cube_corner();
  NormalOptions options;
  options.smoothing_passes = 0;
  const auto n = node_normals(body, std::vector<Vec3>(body.num_nodes(), Vec3::Zero()), options);
  EXPECT_NEAR((n[0] - Vec3(1, 1, 1).normalized()).norm(), 0.0, 1e-12);
  for (const auto& v : n) EXPECT_NEAR(v.norm(), 1.0, 1e-12);
}

// The two vertical faces of the corner standing on the plane z = 0 (the root of a body on a wall):
// constrained to that plane, the corner's normal is the horizontal diagonal.
TEST(NodeNormals, PlaneConstraintKeepsTheNormalInThePlane) {
  BodyMesh body = cube_corner();
  body.triangles.erase(body.triangles.begin(), body.triangles.begin() + 2);
  body.triangle_surface.resize(body.triangles.size());
  std::vector<Vec3> plane(body.num_nodes(), Vec3::Zero());
  plane[0] = Vec3(0, 0, 1);
  NormalOptions options;
  options.smoothing_passes = 3;
  const auto n = node_normals(body, plane, options);
  EXPECT_EQ(n[0].z(), 0.0);
  EXPECT_NEAR((n[0] - Vec3(1, 1, 0).normalized()).norm(), 0.0, 1e-9);
}

// A sharp wedge edge of half-angle 8 degrees along z (like a sharp trailing edge), with unequal fans
// at node 0: 90 degrees of the upper face, 16.7 of the lower. The angle-weighted mean then leans so
// far toward the upper normal that it does not see the lower face; the node must still end up
// seeing both, best along the bisector +x, where n . f = sin(8 deg).
TEST(NodeNormals, SharpWedgeEdgeSeesBothFaces) {
  const double a = 8.0 * M_PI / 180.0;
  const Vec3 up(-std::cos(a), std::sin(a), 0), down(-std::cos(a), -std::sin(a), 0);
  const BodyMesh body = body_of({{0, 0, 0}, {0, 0, 1}, up, up + Vec3(0, 0, 1), down, down + Vec3(0, 0, 0.3)},
                                {{0, 3, 1}, {0, 2, 3},  // upper face, normal (sin a, cos a, 0)
                                 {0, 5, 4}});           // lower face, normal (sin a, -cos a, 0)
  const std::array<Vec3, 3> expected{Vec3(std::sin(a), std::cos(a), 0), Vec3(std::sin(a), std::cos(a), 0),
                                     Vec3(std::sin(a), -std::cos(a), 0)};
  for (int t = 0; t < 3; ++t) {
    const auto& v = body.triangles[t];
    const Vec3 f = (body.points[v[1]] - body.points[v[0]]).cross(body.points[v[2]] - body.points[v[0]]).normalized();
    ASSERT_NEAR((f - expected[t]).norm(), 0.0, 1e-12) << "test setup, triangle " << t;
  }
  const auto fans = node_triangles(body);
  NormalOptions options;
  options.smoothing_passes = 5;
  const auto n = node_normals(body, std::vector<Vec3>(body.num_nodes(), Vec3::Zero()), options);
  EXPECT_GT(min_visibility(body, fans, 0, n[0]), 0.99 * std::sin(a));
  EXPECT_NEAR(n[0].x(), 1.0, 1e-3);
}

// A fold: two triangles on one edge with nearly opposite normals leave no direction that sees
// both; that is an error naming the place.
TEST(NodeNormals, FoldThrowsWithThePlace) {
  const double a = 1e-5;
  const BodyMesh body = body_of({{0, 0, 0}, {0, 0, 1}, {-std::cos(a), std::sin(a), 1}, {-1, 1e-5, 0}},
                                {{0, 2, 1},    // normal about +y
                                 {0, 1, 3}});  // normal about -y, folded onto the first
  try {
    node_normals(body, std::vector<Vec3>(body.num_nodes(), Vec3::Zero()));
    FAIL() << "expected NearFieldError";
  } catch (const NearFieldError& e) {
    EXPECT_NE(std::string(e.what()).find("(0, 0, 0)"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace semimesh::nearfield
