// The far-field wall region: a graded triangulation between a rectangle and a hole.
#include "semimesh/farfield/detail/wall_annulus.hpp"

#include "semimesh/farfield/far_field.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <set>

namespace semimesh::farfield {
namespace {

using Vec2 = Eigen::Vector2d;

// A loop around the rectangle [x0,x1] x [y0,y1] with n segments per side, counter-clockwise.
std::vector<Vec2> rectangle(double x0, double y0, double x1, double y1, int n) {
  const std::array<Vec2, 4> corners = {Vec2(x0, y0), Vec2(x1, y0), Vec2(x1, y1), Vec2(x0, y1)};
  std::vector<Vec2> loop;
  for (int side = 0; side < 4; ++side)
    for (int i = 0; i < n; ++i)
      loop.push_back(corners[side] + (corners[(side + 1) % 4] - corners[side]) * (double(i) / n));
  return loop;
}

double signed_area(const Annulus& a, const std::array<int, 3>& t) {
  const Vec2 u = a.points[t[1]] - a.points[t[0]], v = a.points[t[2]] - a.points[t[0]];
  return 0.5 * (u.x() * v.y() - u.y() * v.x());
}

TEST(WallAnnulus, FillsTheRegionBetweenTheLoopsWithPositiveTriangles) {
  const auto outer = rectangle(-5, -4, 6, 4, 11);   // 1.0 segments
  const auto hole = rectangle(-0.5, -0.25, 0.5, 0.25, 10);  // 0.1 / 0.05 segments
  const Annulus a = triangulate_annulus(outer, hole, 0.8, 1.2);

  double area = 0.0;
  for (const auto& t : a.triangles) {
    const double s = signed_area(a, t);
    EXPECT_GT(s, 0.0);
    area += s;
  }
  EXPECT_NEAR(area, 11.0 * 8.0 - 1.0 * 0.5, 1e-9);
  // Boundary points kept in place and order.
  for (std::size_t i = 0; i < outer.size(); ++i) EXPECT_EQ(a.points[i], outer[i]);
  for (std::size_t i = 0; i < hole.size(); ++i) EXPECT_EQ(a.points[outer.size() + i], hole[i]);
}

TEST(WallAnnulus, BoundaryEdgesAreExactlyTheLoopSegments) {
  const auto outer = rectangle(-3, -3, 3, 3, 6);
  const auto hole = rectangle(-0.5, -0.5, 0.5, 0.5, 8);
  const Annulus a = triangulate_annulus(outer, hole, 0.5, 1.2);
  std::map<std::pair<int, int>, int> uses;
  for (const auto& t : a.triangles)
    for (int k = 0; k < 3; ++k) ++uses[{std::min(t[k], t[(k + 1) % 3]), std::max(t[k], t[(k + 1) % 3])}];
  std::set<std::pair<int, int>> expected;
  const int no = static_cast<int>(outer.size()), nh = static_cast<int>(hole.size());
  for (int i = 0; i < no; ++i) expected.insert({std::min(i, (i + 1) % no), std::max(i, (i + 1) % no)});
  for (int i = 0; i < nh; ++i) expected.insert({no + std::min(i, (i + 1) % nh), no + std::max(i, (i + 1) % nh)});
  std::set<std::pair<int, int>> boundary;
  for (const auto& [edge, count] : uses) {
    EXPECT_LE(count, 2);
    if (count == 1) boundary.insert(edge);
  }
  EXPECT_EQ(boundary, expected);
}

TEST(WallAnnulus, EdgesGrowFromTheHoleAndStayBelowTheCap) {
  const auto outer = rectangle(-6, -6, 6, 6, 12);
  const auto hole = rectangle(-0.5, -0.5, 0.5, 0.5, 20);  // 0.05 segments
  const double cap = 0.7, growth = 1.2;
  const Annulus a = triangulate_annulus(outer, hole, cap, growth);
  double near_max = 0.0, all_max = 0.0;
  double min_sine = 1.0;
  for (const auto& t : a.triangles) {
    Vec2 centroid = Vec2::Zero();
    double longest = 0.0, shortest = 1e300;
    for (int k = 0; k < 3; ++k) {
      centroid += a.points[t[k]] / 3.0;
      const double l = (a.points[t[k]] - a.points[t[(k + 1) % 3]]).norm();
      longest = std::max(longest, l);
      shortest = std::min(shortest, l);
    }
    all_max = std::max(all_max, longest);
    if (centroid.lpNorm<Eigen::Infinity>() < 0.6) near_max = std::max(near_max, longest);
    // sine of the smallest angle: 2 area / (product of the two longer edges) >= 2 area / longest^2
    min_sine = std::min(min_sine, 2.0 * signed_area(a, t) / (longest * longest));
  }
  EXPECT_LT(near_max, 0.05 * 2.5);  // next to the hole: about the hole's own segments
  EXPECT_LT(all_max, 1.0 * 1.5);    // the box segments are 1.0, the interior cap 0.7
  EXPECT_GT(min_sine, std::sin(15.0 * M_PI / 180.0));
  EXPECT_GT(a.points.size(), 500u);  // graded, not a coarse fan onto the hole
  EXPECT_LT(a.points.size(), 20000u);
}

TEST(WallAnnulus, HoleOutsideTheOuterLoopIsReported) {
  const auto outer = rectangle(-1, -1, 1, 1, 4);
  const auto hole = rectangle(0.5, 0.5, 1.5, 1.5, 4);
  EXPECT_THROW(triangulate_annulus(outer, hole, 0.5, 1.2), FarFieldError);
  EXPECT_THROW(triangulate_annulus(outer, {Vec2(0, 0), Vec2(0.1, 0)}, 0.5, 1.2), FarFieldError);
}

}  // namespace
}  // namespace semimesh::farfield
