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

/// The first crossing found between two triangles that share no point: an edge of one passing
/// through the interior of the other. Coplanar overlaps and triangles sharing a point are not
/// examined. Cost: a sweep over the triangles' bounding boxes along x.
std::optional<Crossing> find_crossing(const std::vector<Eigen::Vector3d>& points,
                                      const std::vector<std::array<int, 3>>& triangles);

}  // namespace semimesh::farfield
