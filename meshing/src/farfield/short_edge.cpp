#include "semimesh/farfield/detail/short_edge.hpp"

#include <Eigen/Geometry>

namespace semimesh::farfield {
namespace {

double bounding_box_diagonal(const std::vector<Eigen::Vector3d>& points) {
  if (points.empty()) return 0.0;
  Eigen::AlignedBox3d box;
  for (const Eigen::Vector3d& p : points) box.extend(p);
  return box.diagonal().norm();
}

}  // namespace

std::optional<ShortEdge> find_edge_below_tolerance(const std::vector<Eigen::Vector3d>& points,
                                                   const std::vector<std::array<int, 3>>& triangles,
                                                   double relative_tolerance) {
  const double tolerance = relative_tolerance * bounding_box_diagonal(points);
  std::optional<ShortEdge> shortest;
  for (const std::array<int, 3>& t : triangles) {
    for (int k = 0; k < 3; ++k) {
      const int from = t[k], to = t[(k + 1) % 3];
      const double length = (points[to] - points[from]).norm();
      if (length < tolerance && (!shortest || length < shortest->length)) shortest = ShortEdge{from, to, length, tolerance};
    }
  }
  return shortest;
}

}  // namespace semimesh::farfield
