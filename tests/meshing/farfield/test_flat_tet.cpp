// The finder of tetrahedra flat to round-off in TetGen's answer (run_tetgen refuses such an answer).
#include "semimesh/farfield/detail/flat_tet.hpp"

#include <gtest/gtest.h>

namespace semimesh::farfield {
namespace {

using Eigen::Vector3d;

// The fuselage sweep's case (seed 5 run 18) in miniature: three nodes cut on one straight layer
// edge, collinear to round-off, and a fourth point off the line. TetGen built [0 1 2 3] there
// (6 V / L^3 ~ 1e-16); [0 2 3 4] is a sound tet of the same points.
const std::vector<Vector3d> kCutNodes = {{2.6979933886905574, 0.05717997669424655, 1.0027949034038368},
                                       {2.7004354352367637, 0.068615972033095871, 1.0059995943836315},
                                       {2.7028774817829704, 0.080051967371945199, 1.0092042853634264},
                                       {2.7128600704240786, 0.046316264100980026, 1.0072655955580807},
                                       {2.70, 0.06, 1.05}};

TEST(FlatTet, FindsThreeCollinearCutNodesAndAPointOffTheLine) {
  const auto flat = find_flat_tet(kCutNodes, {{0, 2, 3, 4}, {0, 1, 2, 3}}, 1e-12);
  ASSERT_TRUE(flat.has_value());
  EXPECT_EQ(flat->tet, 1u);
  EXPECT_LT(flat->relative, 1e-14);
}

TEST(FlatTet, SoundTetsAndSliversAboveTheTolerancePass) {
  EXPECT_FALSE(find_flat_tet(kCutNodes, {{0, 2, 3, 4}}, 1e-12).has_value());
  // A sliver: the unit square's corners, one lifted by 1e-6 (6 V / L^3 = 1e-6 / 2^1.5).
  const std::vector<Vector3d> sliver = {{0, 0, 0}, {1, 0, 0}, {1, 1, 1e-6}, {0, 1, 0}};
  EXPECT_FALSE(find_flat_tet(sliver, {{0, 1, 2, 3}}, 1e-12).has_value());
  EXPECT_TRUE(find_flat_tet(sliver, {{0, 1, 2, 3}}, 1e-6).has_value());
}

TEST(FlatTet, NamesTheFlattestOfSeveral) {
  const std::vector<Vector3d> points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 1e-15}, {1, 1, 1e-14}};
  const auto flat = find_flat_tet(points, {{0, 1, 2, 4}, {0, 1, 2, 3}}, 1e-12);
  ASSERT_TRUE(flat.has_value());
  EXPECT_EQ(flat->tet, 1u);
}

}  // namespace
}  // namespace semimesh::farfield
