// The finder of boundary edges shorter than TetGen's merge distance (checked before TetGen runs).
#include "semimesh/farfield/detail/short_edge.hpp"

#include <gtest/gtest.h>

#include <algorithm>

namespace semimesh::farfield {
namespace {

using Eigen::Vector3d;

// Bounding box [0,3] x [0,4] x [0,12]: diagonal 13, so a relative tolerance of 1e-8 is 1.3e-7.
const std::vector<Vector3d> kPoints = {{0, 0, 0}, {3, 4, 12}, {1, 1, 1}, {1 + 1e-7, 1, 1}, {2, 2, 2}, {2, 2, 2 + 5e-8}};

TEST(ShortEdge, FindsTheShortestEdgeUnderTheRelativeTolerance) {
  const auto edge = find_edge_below_tolerance(kPoints, {{0, 2, 3}, {1, 4, 5}}, 1e-8);
  ASSERT_TRUE(edge.has_value());
  EXPECT_EQ(std::min(edge->from, edge->to), 4);
  EXPECT_EQ(std::max(edge->from, edge->to), 5);
  EXPECT_NEAR(edge->length, 5e-8, 1e-15);
  EXPECT_NEAR(edge->tolerance, 13e-8, 1e-15);
}

TEST(ShortEdge, EdgesAtLeastTheToleranceLongPass) {
  EXPECT_FALSE(find_edge_below_tolerance(kPoints, {{0, 2, 3}, {1, 4, 5}}, 3e-9).has_value());  // 3.9e-8 < 5e-8
  EXPECT_FALSE(find_edge_below_tolerance(kPoints, {{0, 1, 2}, {1, 2, 4}}, 1e-8).has_value());
}

}  // namespace
}  // namespace semimesh::farfield
