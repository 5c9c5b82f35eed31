// The tests that decide where the layer is thinned, on configurations with known answers.
#include "semimesh/nearfield/layer_checks.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

namespace semimesh::nearfield {
namespace {

// Brute force: the smallest distance to a dense barycentric sampling of the triangle.
double sampled_distance(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const int n = 200;
  double best = 1e300;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; i + j <= n; ++j) {
      const double s = double(i) / n, t = double(j) / n;
      best = std::min(best, (p - (a + s * (b - a) + t * (c - a))).norm());
    }
  return best;
}

TEST(LayerChecks, PointTriangleDistanceMatchesSampling) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> coordinate(-1.0, 1.0);
  auto point = [&] { return Vec3(coordinate(random), coordinate(random), coordinate(random)); };
  const Vec3 a(0, 0, 0), b(1, 0.2, 0), c(0.3, 0.9, 0.1);
  for (int k = 0; k < 40; ++k) {
    const Vec3 p = 2.0 * point();
    // Sampling overestimates by at most the sample spacing (about |edge| / 200).
    EXPECT_NEAR(point_triangle_distance(p, a, b, c), sampled_distance(p, a, b, c), 8e-3) << p.transpose();
    EXPECT_LE(point_triangle_distance(p, a, b, c), sampled_distance(p, a, b, c) + 1e-12);
  }
  EXPECT_NEAR(point_triangle_distance(Vec3(0.3, 0.3, 2.0), Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)), 2.0, 1e-15);
}

// A right prism over a unit triangle is sound; moving the offsets toward each other (a concave
// fan) makes it unsound before it inverts; a twisted top inverts it.
TEST(LayerChecks, PrismSoundness) {
  const Vec3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0), up(0, 0, 0.5);
  EXPECT_TRUE(prism_is_sound({a, b, c, a + up, b + up, c + up}));
  const Vec3 centre = (a + b + c) / 3.0;
  auto shrunk = [&](double keep) {
    return std::array<Vec3, 6>{a, b, c, centre + keep * (a - centre) + up, centre + keep * (b - centre) + up,
                               centre + keep * (c - centre) + up};
  };
  EXPECT_TRUE(prism_is_sound(shrunk(0.5)));
  EXPECT_FALSE(prism_is_sound(shrunk(0.2)));   // top area 4% of the bottom: about to cross
  EXPECT_FALSE(prism_is_sound(shrunk(-0.5)));  // crossed: inverted top
  EXPECT_FALSE(prism_is_sound({a, b, c, a - up, b - up, c - up}));
}

// Two parallel unit squares facing each other across a gap of 1: the offsets of the lower square
// (toward the upper one) at thickness t come within 1 - t of the other square, crowded when that is
// less than t / 2, i.e. t > 2/3. The square's own triangles never count.
TEST(LayerChecks, FacingPlatesAreCrowdedBeyondTwoThirdsOfTheGap) {
  BodyMesh body;
  body.points = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  body.triangles = {{0, 1, 2}, {0, 2, 3},   // lower plate, normal +z (toward the upper one)
                    {4, 6, 5}, {4, 7, 6}};  // upper plate, normal -z
  body.node_surface.assign(8, 0);
  body.triangle_surface.assign(4, 0);
  body.cad.resize(8);
  const auto neighbours = node_neighbours(body);
  auto crowded_at = [&](double t) {
    std::vector<Vec3> outer(8);
    for (int i = 0; i < 8; ++i) outer[i] = body.points[i] + Vec3(0, 0, i < 4 ? t : -t);
    return crowded_nodes(body, neighbours, outer, std::vector<double>(8, t));
  };
  for (char c : crowded_at(0.6)) EXPECT_FALSE(c);
  for (char c : crowded_at(0.7)) EXPECT_TRUE(c);
}

// The grid search against the full scan on two wavy sheets 0.5 apart, 1922 nodes, with thicknesses
// from 0.2 to 0.8: some offsets reach the other sheet, some do not; both must find the same nodes.
TEST(LayerChecks, GridSearchFindsWhatTheScanFinds) {
  BodyMesh body;
  const int n = 31;
  for (int sheet = 0; sheet < 2; ++sheet)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const double x = 3.0 * i / (n - 1), y = 3.0 * j / (n - 1);
        body.points.emplace_back(x, y, sheet == 0 ? 0.1 * std::sin(3 * x) : 0.5 + 0.1 * std::cos(2 * y));
      }
  for (int sheet = 0; sheet < 2; ++sheet)
    for (int j = 0; j + 1 < n; ++j)
      for (int i = 0; i + 1 < n; ++i) {
        const int a = sheet * n * n + j * n + i, b = a + 1, c = a + n + 1, d = a + n;
        if (sheet == 0) body.triangles.push_back({a, b, c}), body.triangles.push_back({a, c, d});
        else body.triangles.push_back({a, c, b}), body.triangles.push_back({a, d, c});
      }
  body.node_surface.assign(body.points.size(), 0);
  body.triangle_surface.assign(body.triangles.size(), 0);
  body.cad.resize(body.points.size());
  const auto neighbours = node_neighbours(body);
  std::vector<Vec3> outer(body.points.size());
  std::vector<double> thickness(body.points.size());
  for (std::size_t k = 0; k < body.points.size(); ++k) {
    thickness[k] = 0.2 + 0.6 * std::fmod(0.618034 * static_cast<double>(k), 1.0);
    outer[k] = body.points[k] + Vec3(0, 0, k < static_cast<std::size_t>(n * n) ? thickness[k] : -thickness[k]);
  }
  const std::vector<char> fast = crowded_nodes(body, neighbours, outer, thickness);
  const std::vector<char> slow = crowded_nodes_by_scan(body, neighbours, outer, thickness);
  EXPECT_EQ(fast, slow);
  const auto crowded = std::count(slow.begin(), slow.end(), 1);
  EXPECT_GT(crowded, 100);
  EXPECT_LT(crowded, static_cast<long>(body.points.size()) - 100);
}

}  // namespace
}  // namespace semimesh::nearfield
