#include "semimesh/farfield/detail/boundary_crossing.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <numeric>

namespace semimesh::farfield {
namespace {

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

}  // namespace

std::optional<Crossing> find_crossing(const std::vector<Vector3d>& points, const std::vector<std::array<int, 3>>& triangles) {
  const int n = static_cast<int>(triangles.size());
  std::vector<Vector3d> lo(n), hi(n);
  for (int i = 0; i < n; ++i) {
    lo[i] = hi[i] = points[triangles[i][0]];
    for (int k = 1; k < 3; ++k) {
      lo[i] = lo[i].cwiseMin(points[triangles[i][k]]);
      hi[i] = hi[i].cwiseMax(points[triangles[i][k]]);
    }
  }
  std::vector<int> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int a, int b) { return lo[a].x() < lo[b].x(); });

  auto edge_through = [&](int s, int t) -> std::optional<Crossing> {
    const auto& e = triangles[s];
    const auto& f = triangles[t];
    for (int k = 0; k < 3; ++k)
      if (auto x = pierce(points[e[k]], points[e[(k + 1) % 3]], points[f[0]], points[f[1]], points[f[2]]))
        return Crossing{s, t, *x};
    return std::nullopt;
  };
  for (int a = 0; a < n; ++a)
    for (int b = a + 1; b < n && lo[order[b]].x() <= hi[order[a]].x(); ++b) {
      const int s = order[a], t = order[b];
      if ((lo[t].array() > hi[s].array()).any() || (lo[s].array() > hi[t].array()).any()) continue;
      if (share_a_point(triangles[s], triangles[t])) continue;
      if (auto c = edge_through(s, t)) return c;
      if (auto c = edge_through(t, s)) return c;
    }
  return std::nullopt;
}

}  // namespace semimesh::farfield
