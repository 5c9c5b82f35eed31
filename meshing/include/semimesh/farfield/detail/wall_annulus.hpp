// A graded triangulation of a planar region with one hole, in 2D coordinates of the plane: the
// far-field part of the wall, between the box's bottom rectangle and the near field's footprint.
#pragma once

#include <Eigen/Core>

#include <array>
#include <vector>

namespace semimesh::farfield {

struct Annulus {
  /// [points] outer loop points first (input order), then hole points, then interior points
  std::vector<Eigen::Vector2d> points;
  /// [triangles][3] counter-clockwise in the plane's (x, y)
  std::vector<std::array<int, 3>> triangles;
};

/// Triangulates the region inside `outer` and outside `hole` (closed loops, first != last, either
/// direction). Boundary edges are exactly the loop segments (no point is added on them). Interior
/// points follow the size h(x) = min(max_size, min over segments s of |s| + (growth - 1) dist(x, s)):
/// edge lengths start at the loop's own and grow by `growth` away from it, up to max_size.
/// Throws FarFieldError when a loop has fewer than 3 points, the loops cross or touch, or the hole
/// is not inside the outer loop.
Annulus triangulate_annulus(const std::vector<Eigen::Vector2d>& outer, const std::vector<Eigen::Vector2d>& hole,
                            double max_size, double growth);

}  // namespace semimesh::farfield
