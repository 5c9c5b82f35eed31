// TetGen's boundary moved off its exact ties (untie_boundary), the check that a tet of its answer
// holds on the true points (first_unpositive_tet), and run_tetgen's use of both.
#include "semimesh/farfield/detail/untie_boundary.hpp"

#include "tetgen_volume.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>
#include <utility>

namespace semimesh::farfield {
namespace {

using Eigen::Vector3d;

// The unit cube's boundary with each face an n x n grid of squares, each split into two
// triangles: every square's corners are cocircular, every cell of the grid's points cospherical.
// `turned`: the cube turned about (1, 2, 3) by 0.5 radians (no face then lies in a plane x_k = c).
TetgenInput structured_cube(int n, bool turned = false) {
  TetgenInput input;
  std::vector<int> index((n + 1) * (n + 1) * (n + 1), -1);
  const auto at = [&](int i, int j, int k) {
    int& slot = index[(i * (n + 1) + j) * (n + 1) + k];
    if (slot < 0) {
      slot = static_cast<int>(input.points.size());
      input.points.emplace_back(double(i) / n, double(j) / n, double(k) / n);
    }
    return slot;
  };
  // Face by face: the axis it is normal to, its side (0 or n), the two axes along it.
  for (int axis = 0; axis < 3; ++axis)
    for (int side : {0, n})
      for (int a = 0; a < n; ++a)
        for (int b = 0; b < n; ++b) {
          const auto corner = [&](int da, int db) {
            int c[3];
            c[axis] = side;
            c[(axis + 1) % 3] = a + da;
            c[(axis + 2) % 3] = b + db;
            return at(c[0], c[1], c[2]);
          };
          input.triangles.push_back({corner(0, 0), corner(1, 0), corner(1, 1)});
          input.triangles.push_back({corner(0, 0), corner(1, 1), corner(0, 1)});
        }
  input.parts.emplace_back(input.triangles.size(), "the cube");
  if (turned) {
    const Eigen::Matrix3d turn = Eigen::AngleAxisd(0.5, Vector3d(1, 2, 3).normalized()).toRotationMatrix();
    for (Vector3d& p : input.points) p = turn * p;
  }
  return input;
}

// A box with no face in a plane x_k = c but its top and bottom (z = 0, 1): its base the rectangle
// (0, 0) (2, 1) (1, 3) (-1, 2). Its eight corners lie exactly on one sphere.
TetgenInput slanted_box() {
  TetgenInput input;
  for (double z : {0.0, 1.0})
    for (const auto& [x, y] : {std::pair{0.0, 0.0}, {2.0, 1.0}, {1.0, 3.0}, {-1.0, 2.0}})
      input.points.emplace_back(x, y, z);
  input.triangles = {{0, 2, 1}, {0, 3, 2}, {4, 5, 6}, {4, 6, 7}};  // bottom, top
  for (int k = 0; k < 4; ++k) {
    const int a = k, b = (k + 1) % 4;
    input.triangles.push_back({a, b, b + 4});
    input.triangles.push_back({a, b + 4, a + 4});
  }
  input.parts.emplace_back(input.triangles.size(), "the box");
  return input;
}

double volume6(const std::vector<Vector3d>& p, const std::array<int, 4>& t) {
  return (p[t[1]] - p[t[0]]).cross(p[t[2]] - p[t[0]]).dot(p[t[3]] - p[t[0]]);
}

// The insphere determinant of e against the sphere through a, b, c, d (zero: cospherical).
double insphere(const Vector3d& a, const Vector3d& b, const Vector3d& c, const Vector3d& d, const Vector3d& e) {
  Eigen::Matrix4d m;
  int row = 0;
  for (const Vector3d* p : {&a, &b, &c, &d}) {
    const Vector3d q = *p - e;
    m.row(row++) << q.x(), q.y(), q.z(), q.squaredNorm();
  }
  return m.determinant();
}

TEST(UntieBoundary, MovesEachBoundaryPointWithinItsShareOfItsShortestEdgeAndNoOtherPoint) {
  TetgenInput input = structured_cube(2, /*turned=*/true);
  const std::size_t boundary = input.points.size();
  input.points.emplace_back(0.4, 0.5, 0.6);  // an interior point: no triangle uses it
  const std::vector<Vector3d> moved = untie_boundary(input.points, input.triangles, 1e-3);
  ASSERT_EQ(moved.size(), input.points.size());
  for (std::size_t i = 0; i < boundary; ++i) {
    const Vector3d step = (moved[i] - input.points[i]).cwiseAbs();
    for (int axis = 0; axis < 3; ++axis) EXPECT_GT(step[axis], 0.0) << "point " << i << ", axis " << axis;
    EXPECT_LE(step.maxCoeff(), 1e-3 * 0.5 + 1e-15) << "point " << i;  // every edge at a point is >= 0.5
  }
  EXPECT_EQ(moved.back(), input.points.back());
  EXPECT_EQ(untie_boundary(input.points, input.triangles, 1e-3), moved);  // fixed: the same every call
}

TEST(UntieBoundary, KeepsThePointsOfATriangleInAPlaneXkEqualCOnThatPlane) {
  // The cube's faces lie in planes x_k = 0 or 1: a point inside a face moves in that face only, one
  // on an edge along the edge only, a corner not at all (four of a face's points moved off it
  // could make a tet of TetGen's flat on the true points).
  const TetgenInput input = structured_cube(2);
  const std::vector<Vector3d> moved = untie_boundary(input.points, input.triangles, 1e-3);
  int corners = 0;
  for (std::size_t i = 0; i < input.points.size(); ++i) {
    int on_planes = 0;
    for (int axis = 0; axis < 3; ++axis) {
      const double c = input.points[i][axis];
      if (c == 0.0 || c == 1.0) {
        ++on_planes;
        EXPECT_EQ(moved[i][axis], c) << "point " << i << ", axis " << axis;
      } else {
        EXPECT_NE(moved[i][axis], c) << "point " << i << ", axis " << axis;
      }
    }
    corners += on_planes == 3;
  }
  EXPECT_EQ(corners, 8);
}

TEST(UntieBoundary, NoFiveCornersOfABoxStayCospherical) {
  const TetgenInput input = slanted_box();  // its 8 corners: all on one sphere
  const std::vector<Vector3d> moved = untie_boundary(input.points, input.triangles, 1e-8);
  const std::vector<Vector3d>& p = input.points;
  int subsets = 0;
  for (int a = 0; a < 8; ++a)
    for (int b = a + 1; b < 8; ++b)
      for (int c = b + 1; c < 8; ++c)
        for (int d = c + 1; d < 8; ++d)
          for (int e = d + 1; e < 8; ++e) {
            ++subsets;
            ASSERT_LT(std::abs(insphere(p[a], p[b], p[c], p[d], p[e])), 1e-12);  // tied before (round-off)
            // After: decided far above double round-off, at the moves' scale (1e-8 of an edge).
            EXPECT_GT(std::abs(insphere(moved[a], moved[b], moved[c], moved[d], moved[e])), 1e-10)
                << a << " " << b << " " << c << " " << d << " " << e;
          }
  EXPECT_EQ(subsets, 56);
}

TEST(FirstUnpositiveTet, NamesTheFirstTetTurnedOverOrFlatAndNoneOfASoundMesh) {
  const std::vector<Vector3d> p = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0}};
  EXPECT_FALSE(first_unpositive_tet(p, {{0, 1, 2, 3}}).has_value());
  EXPECT_EQ(first_unpositive_tet(p, {{0, 1, 2, 3}, {0, 2, 1, 3}, {0, 1, 4, 2}}), std::optional<std::size_t>(1));
  EXPECT_EQ(first_unpositive_tet(p, {{0, 1, 2, 3}, {0, 1, 4, 2}}), std::optional<std::size_t>(1));  // flat
}

// What run_tetgen hands on: the true boundary points, every tet positive there, the cube filled.
void expect_sound_mesh_of_the_cube(const TetgenInput& input, const TetgenOutput& output) {
  ASSERT_GE(output.points.size(), input.points.size());
  for (std::size_t i = 0; i < input.points.size(); ++i) EXPECT_EQ(output.points[i], input.points[i]) << "point " << i;
  double volume = 0.0;
  for (const auto& t : output.tets) {
    EXPECT_GT(volume6(output.points, t), 0.0);
    volume += volume6(output.points, t) / 6.0;
  }
  EXPECT_NEAR(volume, 1.0, 1e-12);
}

TEST(RunTetgen, TakesTheMeshOfTheUntiedBoundaryOnTheTruePoints) {
  TetgenInput input = structured_cube(4);
  input.untie = 1e-8;
  const TetgenOutput output = run_tetgen(input, /*quiet=*/true);
  EXPECT_TRUE(output.untied);
  expect_sound_mesh_of_the_cube(input, output);
}

TEST(RunTetgen, MeshesTheTruePointsWhereTheUntiedMeshTurnsOverOnThem) {
  // The turned cube's points moved by a fifth of an edge in every direction: TetGen's mesh of
  // those points has tets that the true points turn over or flatten (a grid cell's four coplanar
  // corners), so TetGen runs again on the true ones.
  TetgenInput input = structured_cube(4, /*turned=*/true);
  input.untie = 0.2;
  const TetgenOutput output = run_tetgen(input, /*quiet=*/true);
  EXPECT_FALSE(output.untied);
  expect_sound_mesh_of_the_cube(input, output);
}

TEST(RunTetgen, WithoutUntyingMeshesTheTruePoints) {
  const TetgenInput input = structured_cube(4);
  const TetgenOutput output = run_tetgen(input, /*quiet=*/true);
  EXPECT_FALSE(output.untied);
  expect_sound_mesh_of_the_cube(input, output);
}

}  // namespace
}  // namespace semimesh::farfield
