#include "semimesh/farfield/detail/untie_boundary.hpp"

#include "semimesh/farfield/detail/fixed_offset.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cstdint>
#include <limits>

namespace semimesh::farfield {

std::vector<Eigen::Vector3d> untie_boundary(const std::vector<Eigen::Vector3d>& points,
                                            const std::vector<std::array<int, 3>>& triangles, double share) {
  std::vector<double> shortest(points.size(), std::numeric_limits<double>::infinity());
  std::vector<std::uint8_t> frozen(points.size(), 0);  // bit k: coordinate k stays
  for (const auto& t : triangles) {
    for (int k = 0; k < 3; ++k) {
      const int a = t[k], b = t[(k + 1) % 3];
      const double length = (points[a] - points[b]).norm();
      shortest[a] = std::min(shortest[a], length);
      shortest[b] = std::min(shortest[b], length);
    }
    // A triangle in a plane x_k = c (a box face, a planar wall, a wall layer's tops) keeps its
    // points on that plane: moved off it, four of its points could make a tet of TetGen's that is
    // flat on the true points (seen: the wall layer's tops at z = 0.1).
    for (int axis = 0; axis < 3; ++axis)
      if (points[t[0]][axis] == points[t[1]][axis] && points[t[1]][axis] == points[t[2]][axis])
        for (int v : t) frozen[v] |= static_cast<std::uint8_t>(1u << axis);
  }
  std::vector<Eigen::Vector3d> moved = points;
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (!(shortest[i] < std::numeric_limits<double>::infinity())) continue;
    const Eigen::Vector3d offset = fixed_offset(i);
    for (int axis = 0; axis < 3; ++axis)
      if (!(frozen[i] & (1u << axis))) moved[i][axis] += share * shortest[i] * offset[axis];
  }
  return moved;
}

std::optional<std::size_t> first_unpositive_tet(const std::vector<Eigen::Vector3d>& points,
                                                const std::vector<std::array<int, 4>>& tets) {
  for (std::size_t t = 0; t < tets.size(); ++t) {
    const Eigen::Vector3d& p0 = points[tets[t][0]];
    const double volume6 =
        (points[tets[t][1]] - p0).cross(points[tets[t][2]] - p0).dot(points[tets[t][3]] - p0);
    if (!(volume6 > 0.0)) return t;
  }
  return std::nullopt;
}

}  // namespace semimesh::farfield
