#include "semimesh/ho/closest_point.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

namespace semimesh::ho {
namespace {

TEST(ClosestPointOnTriangle, EachVoronoiRegionGivesItsFoot) {
  const Eigen::Vector3d a(0, 0, 0), b(2, 0, 0), c(0, 1, 0.5);
  struct Case {
    Eigen::Vector3d p, foot;
  };
  const Eigen::Vector3d inside = (a + b + c) / 3.0, n = (b - a).cross(c - a).normalized();
  for (const Case& k : {Case{{-1, -1, 0}, a}, Case{{3, -1, 0}, b}, Case{{0, 2, 1.5}, c},
                        Case{{1, -2, 0.3}, {1, 0, 0}},  // below edge ab: its foot has y = z = 0
                        Case{inside + 0.7 * n, inside}}) {
    const TriangleFoot f = closest_point_on_triangle(k.p, a, b, c);
    EXPECT_LT((f.point - k.foot).norm(), 1e-14) << k.p.transpose();
    EXPECT_LT((f.barycentric[0] * a + f.barycentric[1] * b + f.barycentric[2] * c - f.point).norm(), 1e-14);
  }
}

// Against the slow reference: the nearest of a fine lattice of the triangle's points is never nearer.
TEST(ClosestPointOnTriangle, NoLatticePointOfTheTriangleIsNearer) {
  const Eigen::Vector3d a(0, 0, 0), b(2, 0, 0), c(0, 1, 0.5);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> coordinate(-2.0, 3.0);
  constexpr int n = 200;
  for (int trial = 0; trial < 50; ++trial) {
    const Eigen::Vector3d p(coordinate(random), coordinate(random), coordinate(random));
    const TriangleFoot f = closest_point_on_triangle(p, a, b, c);
    EXPECT_GE(f.barycentric.minCoeff(), 0.0);
    EXPECT_NEAR(f.barycentric.sum(), 1.0, 1e-14);
    double lattice_best = 1e300;
    for (int i = 0; i <= n; ++i)
      for (int j = 0; i + j <= n; ++j)
        lattice_best = std::min(lattice_best, (p - (a + (b - a) * i / n + (c - a) * j / n)).norm());
    const double found = (p - f.point).norm();
    EXPECT_LE(found, lattice_best + 1e-12);
    EXPECT_GE(found, lattice_best - 0.02);  // the lattice's spacing bounds how far it can be off
  }
}

}  // namespace
}  // namespace semimesh::ho
