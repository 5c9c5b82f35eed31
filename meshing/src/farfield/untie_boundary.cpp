#include "semimesh/farfield/detail/untie_boundary.hpp"

#include "semimesh/farfield/detail/fixed_offset.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <limits>

namespace semimesh::farfield {

std::vector<Eigen::Vector3d> untie_boundary(const std::vector<Eigen::Vector3d>& points,
                                            const std::vector<std::array<int, 3>>& triangles, double share) {
  std::vector<double> shortest(points.size(), std::numeric_limits<double>::infinity());
  for (const auto& t : triangles)
    for (int k = 0; k < 3; ++k) {
      const int a = t[k], b = t[(k + 1) % 3];
      const double length = (points[a] - points[b]).norm();
      shortest[a] = std::min(shortest[a], length);
      shortest[b] = std::min(shortest[b], length);
    }
  std::vector<Eigen::Vector3d> moved = points;
  for (std::size_t i = 0; i < points.size(); ++i)
    if (shortest[i] < std::numeric_limits<double>::infinity()) moved[i] += share * shortest[i] * fixed_offset(i);
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
