// The locator of self-crossings of a triangulated boundary (used in TetGen error messages).
#include "semimesh/farfield/detail/boundary_crossing.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace semimesh::farfield {
namespace {

using Eigen::Vector3d;

TEST(BoundaryCrossing, FindsAnEdgeThroughAnotherTriangle) {
  // triangle 0 in z = 0; triangle 1 stands in the plane x = y through it: they cross along a segment
  // of the line x = y, z = 0 (edge 3-4 at (0.2, 0.2, 0), edge 1-2 at (0.5, 0.5, 0))
  const std::vector<Vector3d> points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.2, 0.2, -1}, {0.2, 0.2, 1}, {2, 2, 0.5}};
  const auto crossing = find_crossing(points, {{0, 1, 2}, {3, 4, 5}});
  ASSERT_TRUE(crossing.has_value());
  EXPECT_EQ(crossing->edge_triangle + crossing->pierced_triangle, 1);
  EXPECT_NE(crossing->edge_triangle, crossing->pierced_triangle);
  const Vector3d& x = crossing->point;
  EXPECT_NEAR(x.z(), 0.0, 1e-12);
  EXPECT_NEAR(x.x(), x.y(), 1e-12);
  EXPECT_TRUE(std::abs(x.x() - 0.2) < 1e-12 || std::abs(x.x() - 0.5) < 1e-12) << x.transpose();
}

TEST(BoundaryCrossing, NeighboursAndSeparateTrianglesDoNotCross) {
  const std::vector<Vector3d> points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {0, 0, 2}, {1, 0, 2}, {0, 1, 2}};
  EXPECT_FALSE(find_crossing(points, {{0, 1, 2}, {1, 3, 2}, {4, 5, 6}}).has_value());
}

// The tree finds a crossing exactly when the sweep does, on soups of small triangles with a few
// large ones (as the box's triangles are beside the skin's), and what it reports crosses.
TEST(BoundaryCrossing, TreeAgreesWithTheSweepOnRandomSoups) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int with_crossing = 0;
  for (int soup = 0; soup < 60; ++soup) {
    std::vector<Vector3d> points;
    std::vector<std::array<int, 3>> triangles;
    const int small = 20 + soup * 5;
    const double size = soup % 2 ? 0.02 : 0.08;  // sparse soups have no crossing, dense ones do
    for (int i = 0; i < small + 3; ++i) {
      const Vector3d c(unit(rng), unit(rng), unit(rng));
      const double s = i < small ? size : 0.7;
      const int base = static_cast<int>(points.size());
      for (int k = 0; k < 3; ++k) points.push_back(c + s * Vector3d(unit(rng) - 0.5, unit(rng) - 0.5, unit(rng) - 0.5));
      triangles.push_back({base, base + 1, base + 2});
    }
    const auto fast = find_crossing(points, triangles);
    const auto slow = find_crossing_by_sweep(points, triangles);
    ASSERT_EQ(fast.has_value(), slow.has_value()) << "soup " << soup;
    if (!fast) continue;
    ++with_crossing;
    // What the tree reports crosses: its point lies on both triangles' planes.
    for (int t : {fast->edge_triangle, fast->pierced_triangle}) {
      const auto& f = triangles[t];
      const Vector3d n = (points[f[1]] - points[f[0]]).cross(points[f[2]] - points[f[0]]).normalized();
      EXPECT_NEAR(n.dot(fast->point - points[f[0]]), 0.0, 1e-9) << "soup " << soup;
    }
  }
  EXPECT_GT(with_crossing, 10);
  EXPECT_LT(with_crossing, 60);
}

}  // namespace
}  // namespace semimesh::farfield
