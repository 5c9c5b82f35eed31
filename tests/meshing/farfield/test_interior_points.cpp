// The far field's interior points: inside the region, clear of its boundary, spaced like the
// boundary next to it and growing away from it; the same on any thread count.
#include "semimesh/farfield/detail/interior_points.hpp"

#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>

namespace semimesh::farfield {
namespace {

using Eigen::Vector3d;

struct Surface {
  std::vector<Vector3d> points;
  std::vector<std::array<int, 3>> triangles;
};

// The surface of the cube [-half, half]^3, each face an n x n grid of squares cut in two,
// appended to `out`.
void add_cube(double half, int n, Surface& out) {
  for (int axis = 0; axis < 3; ++axis)
    for (int sign : {-1, 1}) {
      const int u = (axis + 1) % 3, v = (axis + 2) % 3;
      const int base = static_cast<int>(out.points.size());
      for (int i = 0; i <= n; ++i)
        for (int j = 0; j <= n; ++j) {
          Vector3d p;
          p[axis] = sign * half;
          p[u] = -half + 2 * half * i / n;
          p[v] = -half + 2 * half * j / n;
          out.points.push_back(p);
        }
      const auto at = [&](int i, int j) { return base + i * (n + 1) + j; };
      for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
          out.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
          out.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
        }
    }
}

// A box of half side 2 in squares of 0.5 round a cube of half side 0.25 in squares of 0.05 (the
// cube's face grids' corners and edges repeat points: the region does not care).
Surface box_round_cube() {
  Surface s;
  add_cube(2.0, 8, s);
  add_cube(0.25, 10, s);
  return s;
}

constexpr double kGrowth = 1.6;
constexpr double kMaxSpacing = 0.5;

// Distance from x to the surface of the cube [-half, half]^3.
double distance_to_cube(const Vector3d& x, double half) {
  const Vector3d outside = (x.cwiseAbs() - Vector3d::Constant(half)).cwiseMax(0.0);
  if (outside.squaredNorm() > 0) return outside.norm();
  return (Vector3d::Constant(half) - x.cwiseAbs()).minCoeff();
}

// The spacing the points follow, by brute force over the surface's vertices (the edges at a
// vertex: 0.05 on the cube, 0.5 on the box, the diagonals a little longer).
double spacing_reference(const Surface& s, const Vector3d& x) {
  double h = kMaxSpacing;
  for (const Vector3d& p : s.points) {
    const double at_vertex = p.cwiseAbs().maxCoeff() < 1.0 ? 0.05 : 0.5;
    h = std::min(h, at_vertex + (kGrowth - 1) * (x - p).norm());
  }
  return h;
}

TEST(InteriorPoints, LieInsideTheRegionClearOfItsBoundary) {
  const Surface s = box_round_cube();
  const auto points = interior_points(s.points, s.triangles, {kGrowth, kMaxSpacing});
  ASSERT_GT(points.size(), 500u);
  for (const Vector3d& x : points) {
    const double clearance = std::min(distance_to_cube(x, 2.0), distance_to_cube(x, 0.25));
    ASSERT_TRUE(x.cwiseAbs().maxCoeff() < 2.0 && x.cwiseAbs().maxCoeff() > 0.25) << x.transpose();
    // kClearance (0.6) of the spacing at the point's cell centre, which lies within 0.35 of a
    // spacing: 0.6 (1 - 0.35 * 0.6) h > 0.45 h at the point.
    ASSERT_GT(clearance, 0.45 * spacing_reference(s, x)) << x.transpose();
  }
}

TEST(InteriorPoints, SpacingFollowsTheBoundaryAndGrowsAwayFromIt) {
  const Surface s = box_round_cube();
  const auto points = interior_points(s.points, s.triangles, {kGrowth, kMaxSpacing});
  std::vector<double> near_ratio, far_gap;
  for (std::size_t i = 0; i < points.size(); ++i) {
    double nearest = 1e300;
    for (std::size_t j = 0; j < points.size(); ++j)
      if (j != i) nearest = std::min(nearest, (points[i] - points[j]).norm());
    const double h = spacing_reference(s, points[i]);
    // One point per cell of side between h/2 and h, moved by up to 0.2 side per axis.
    ASSERT_GT(nearest, 0.2 * h) << points[i].transpose();
    ASSERT_LT(nearest, 1.5 * h) << points[i].transpose();
    if (distance_to_cube(points[i], 0.25) < 0.1) near_ratio.push_back(nearest);
    if (distance_to_cube(points[i], 0.25) > 1.0) far_gap.push_back(nearest);
  }
  ASSERT_FALSE(near_ratio.empty());
  ASSERT_FALSE(far_gap.empty());
  const double near_max = *std::max_element(near_ratio.begin(), near_ratio.end());
  const double far_min = *std::min_element(far_gap.begin(), far_gap.end());
  EXPECT_LT(near_max, 0.15);  // h <= 0.05 + 0.6 * 0.1 next to the cube
  EXPECT_GT(far_min, 0.15);   // h >= 0.05 + 0.6 * 1.0 a unit away
}

TEST(InteriorPoints, TheSameOnOneThreadAndTwo) {
  const Surface s = box_round_cube();
  const int threads = omp_get_max_threads();
  omp_set_num_threads(1);
  const auto one = interior_points(s.points, s.triangles, {kGrowth, kMaxSpacing});
  omp_set_num_threads(2);
  const auto two = interior_points(s.points, s.triangles, {kGrowth, kMaxSpacing});
  omp_set_num_threads(threads);
  ASSERT_EQ(one.size(), two.size());
  for (std::size_t i = 0; i < one.size(); ++i) ASSERT_EQ(one[i], two[i]) << "point " << i;
}

// The ray test against the closed form, at random points and at points level with the grids'
// vertices, edges and faces (where a ray could pass through a vertex or along an edge).
TEST(InteriorPoints, InsideTestAgreesWithTheBoxes) {
  const Surface s = box_round_cube();
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> coordinate(-2.5, 2.5);
  std::vector<Vector3d> probes;
  for (int i = 0; i < 400; ++i) probes.emplace_back(coordinate(rng), coordinate(rng), coordinate(rng));
  for (double a : {-1.5, -0.25, -0.05, 0.0, 0.05, 0.5, 1.0})
    for (double b : {-1.0, 0.0, 0.1, 0.25, 1.5}) probes.emplace_back(a, b, 0.3), probes.emplace_back(0.0, a, b);
  for (const Vector3d& x : probes) {
    const double m = x.cwiseAbs().maxCoeff();
    if (std::abs(m - 2.0) < 1e-6 || std::abs(m - 0.25) < 1e-6) continue;  // on the boundary
    EXPECT_EQ(inside_boundary(s.points, s.triangles, x), m < 2.0 && m > 0.25) << x.transpose();
  }
}

TEST(InteriorPoints, RefusesAGrowthBelowOneAndNoSpacing) {
  const Surface s = box_round_cube();
  EXPECT_THROW(interior_points(s.points, s.triangles, {0.9, kMaxSpacing}), std::invalid_argument);
  EXPECT_THROW(interior_points(s.points, s.triangles, {kGrowth, 0.0}), std::invalid_argument);
}

}  // namespace
}  // namespace semimesh::farfield
