// The locator of self-crossings of a triangulated boundary (used in TetGen error messages).
#include "semimesh/farfield/detail/boundary_crossing.hpp"

#include <gtest/gtest.h>

#include <cmath>

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

}  // namespace
}  // namespace semimesh::farfield
