#include "semimesh/farfield/detail/boundary_crossing.hpp"


#include "semimesh/geometry/box_tree.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <numeric>
#include <utility>

namespace semimesh::farfield {
namespace {

using geometry::Box;
using geometry::BoxTree;
using geometry::triangle_boxes;
using Eigen::Vector3d;

// Where segment pq passes strictly through the interior of triangle abc, if it does.
std::optional<Vector3d> pierce(const Vector3d& p, const Vector3d& q, const Vector3d& a, const Vector3d& b,
                               const Vector3d& c) {
  const Vector3d n = (b - a).cross(c - a);
  const double dp = n.dot(p - a), dq = n.dot(q - a);
  if ((dp >= 0 && dq >= 0) || (dp <= 0 && dq <= 0)) return std::nullopt;
  const Vector3d x = p + dp / (dp - dq) * (q - p);
  if (n.dot((b - a).cross(x - a)) > 0 && n.dot((c - b).cross(x - b)) > 0 && n.dot((a - c).cross(x - c)) > 0) return x;
  return std::nullopt;
}

bool share_a_point(const std::array<int, 3>& s, const std::array<int, 3>& t) {
  for (int a : s)
    for (int b : t)
      if (a == b) return true;
  return false;
}

// Whether an edge of triangle s passes through the interior of triangle t (or one of t's through
// s), for triangles sharing no point.
std::optional<Crossing> crossing_of(const std::vector<Vector3d>& points, const std::vector<std::array<int, 3>>& triangles,
                                    int s, int t) {
  if (share_a_point(triangles[s], triangles[t])) return std::nullopt;
  for (const auto& [e, f] : {std::pair{s, t}, std::pair{t, s}}) {
    const auto& edge = triangles[e];
    const auto& face = triangles[f];
    for (int k = 0; k < 3; ++k)
      if (auto x = pierce(points[edge[k]], points[edge[(k + 1) % 3]], points[face[0]], points[face[1]], points[face[2]]))
        return Crossing{e, f, *x};
  }
  return std::nullopt;
}

}  // namespace

std::optional<Crossing> find_crossing(const std::vector<Vector3d>& points, const std::vector<std::array<int, 3>>& triangles) {
  const std::vector<Box> boxes = triangle_boxes(points, triangles);
  const BoxTree tree(boxes);
  for (int s = 0; s < static_cast<int>(triangles.size()); ++s) {
    std::optional<Crossing> found;
    tree.visit_overlaps(boxes[s], [&](int t) {
      if (!found && t > s) found = crossing_of(points, triangles, s, t);
    });
    if (found) return found;
  }
  return std::nullopt;
}

std::optional<Crossing> find_crossing_by_sweep(const std::vector<Vector3d>& points,
                                               const std::vector<std::array<int, 3>>& triangles) {
  const int n = static_cast<int>(triangles.size());
  const std::vector<Box> boxes = triangle_boxes(points, triangles);
  std::vector<int> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int a, int b) { return boxes[a].lo.x() < boxes[b].lo.x(); });
  for (int a = 0; a < n; ++a)
    for (int b = a + 1; b < n && boxes[order[b]].lo.x() <= boxes[order[a]].hi.x(); ++b) {
      const int s = order[a], t = order[b];
      if (!boxes[s].overlaps(boxes[t])) continue;
      if (auto c = crossing_of(points, triangles, s, t)) return c;
    }
  return std::nullopt;
}

}  // namespace semimesh::farfield
