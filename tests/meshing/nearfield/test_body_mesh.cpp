// The body mesh's open edges (nearfield/body_mesh.hpp): the rim of a surface with a hole, directed
// as its triangles run, against a slow count of every edge's triangles; none on a closed surface;
// an edge of three triangles or of two running the same way is refused, naming its midpoint.
#include "semimesh/nearfield/body_mesh.hpp"
#include "semimesh/nearfield/error.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <string>
#include <utility>
#include <vector>

namespace semimesh::nearfield {
namespace {

// A (cols + 1) x (rows + 1) grid of points in z = 0, each cell two triangles counter-clockwise
// seen from +z, the cells in `holes` left out.
BodyMesh grid(int cols, int rows, const std::vector<std::pair<int, int>>& holes = {}) {
  BodyMesh body;
  for (int j = 0; j <= rows; ++j)
    for (int i = 0; i <= cols; ++i) body.points.emplace_back(i, j, 0.0);
  const auto id = [&](int i, int j) { return j * (cols + 1) + i; };
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < cols; ++i) {
      if (std::find(holes.begin(), holes.end(), std::make_pair(i, j)) != holes.end()) continue;
      body.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      body.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return body;
}

// Slow and plain: the directed edges of each triangle that no other triangle has in either direction.
std::vector<std::pair<int, int>> open_edges_by_count(const BodyMesh& body) {
  std::vector<std::pair<int, int>> open;
  for (std::size_t t = 0; t < body.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      const int a = body.triangles[t][k], b = body.triangles[t][(k + 1) % 3];
      int others = 0;
      for (std::size_t u = 0; u < body.triangles.size(); ++u)
        for (int m = 0; m < 3 && u != t; ++m) {
          const int c = body.triangles[u][m], d = body.triangles[u][(m + 1) % 3];
          others += (c == a && d == b) || (c == b && d == a);
        }
      if (others == 0) open.emplace_back(a, b);
    }
  std::sort(open.begin(), open.end());
  return open;
}

std::vector<std::pair<int, int>> sorted(std::vector<std::pair<int, int>> edges) {
  std::sort(edges.begin(), edges.end());
  return edges;
}

TEST(BodyMesh, OpenEdgesAreTheRimsDirectedAsTheirTriangles) {
  const BodyMesh plate = grid(4, 3, {{1, 1}, {2, 1}});  // an outer rim and a hole's
  const auto open = open_edges(plate);
  EXPECT_EQ(open.size(), 2u * (4 + 3) + 2u * (2 + 1));
  EXPECT_EQ(sorted(open), open_edges_by_count(plate));
  // The outer rim runs counter-clockwise seen from +z: its bottom edges go +x.
  EXPECT_NE(std::find(open.begin(), open.end(), std::make_pair(0, 1)), open.end());
  // Triangles given in any order: the same edges.
  BodyMesh shuffled = plate;
  std::shuffle(shuffled.triangles.begin(), shuffled.triangles.end(), std::mt19937(3));
  EXPECT_EQ(sorted(open_edges(shuffled)), open_edges_by_count(plate));
}

TEST(BodyMesh, ClosedSurfaceHasNoOpenEdges) {
  BodyMesh tetrahedron;
  tetrahedron.points = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)};
  tetrahedron.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};  // outward
  EXPECT_TRUE(open_edges(tetrahedron).empty());
}

// The message open_edges refuses `body` with; empty when it takes it.
std::string refusal(const BodyMesh& body) {
  try {
    open_edges(body);
  } catch (const NearFieldError& e) {
    return e.what();
  }
  return "";
}

TEST(BodyMesh, EdgeOfThreeTrianglesOrOfTwoRunningTheSameWayIsRefusedAtItsMidpoint) {
  BodyMesh fin = grid(1, 1);  // the edge (0, 3) from (0, 0, 0) to (1, 1, 0), then a third triangle on it
  fin.points.emplace_back(0.5, 0.5, 1.0);
  fin.triangles.push_back({0, 3, 4});
  const std::string three = refusal(fin);
  EXPECT_NE(three.find("an edge has 3 triangles"), std::string::npos) << three;
  EXPECT_NE(three.find("(0.5, 0.5, 0)"), std::string::npos) << three;
  BodyMesh flipped = grid(1, 1);
  std::swap(flipped.triangles[1][1], flipped.triangles[1][2]);  // the second triangle turned over
  const std::string same_way = refusal(flipped);
  EXPECT_NE(same_way.find("oriented inconsistently"), std::string::npos) << same_way;
  EXPECT_NE(same_way.find("(0.5, 0.5, 0)"), std::string::npos) << same_way;
}

}  // namespace
}  // namespace semimesh::nearfield
