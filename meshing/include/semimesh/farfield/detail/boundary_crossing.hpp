// Finds where a triangulated surface crosses itself: used to say WHERE the far-field boundary is
// broken when TetGen refuses it.
#pragma once

#include <Eigen/Core>

#include <array>
#include <optional>
#include <vector>

namespace semimesh::farfield {

struct Crossing {
  int edge_triangle = -1;   ///< triangle whose edge pierces...
  int pierced_triangle = -1;  ///< ...the interior of this one
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
};

/// A crossing between two triangles that share no point, if there is one: an edge of one passing
/// through the interior of the other. Coplanar overlaps and triangles sharing a point are not
/// examined. Cost: a bounding-box tree, about n log n (at 10^7 elements the sweep below ran for
/// hours after TetGen refused a boundary).
std::optional<Crossing> find_crossing(const std::vector<Eigen::Vector3d>& points,
                                      const std::vector<std::array<int, 3>>& triangles);

/// The slow reference of find_crossing: a sweep over the bounding boxes along x, every pair whose
/// x-ranges overlap tested (n^2 where the boundary is long in x). Finds a crossing exactly when
/// find_crossing does (tests pin the two together).
std::optional<Crossing> find_crossing_by_sweep(const std::vector<Eigen::Vector3d>& points,
                                               const std::vector<std::array<int, 3>>& triangles);

}  // namespace semimesh::farfield
