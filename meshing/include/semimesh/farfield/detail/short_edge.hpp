// Finds a boundary edge too short for TetGen: used to refuse such a boundary with a clear message
// before TetGen merges its ends and fails on it.
#pragma once

#include <Eigen/Core>

#include <array>
#include <optional>
#include <vector>

namespace semimesh::farfield {

struct ShortEdge {
  int from = -1;           ///< the edge's points
  int to = -1;
  double length = 0.0;
  double tolerance = 0.0;  ///< the length it is shorter than
};

/// The shortest edge of the triangles if it is shorter than relative_tolerance times the diagonal
/// of the bounding box of all the points (TetGen's merge distance, see tetgen_volume.cpp).
std::optional<ShortEdge> find_edge_below_tolerance(const std::vector<Eigen::Vector3d>& points,
                                                   const std::vector<std::array<int, 3>>& triangles,
                                                   double relative_tolerance);

}  // namespace semimesh::farfield
