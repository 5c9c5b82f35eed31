// Points filling the region a closed triangulated boundary encloses, spaced like the boundary
// next to it and growing away from it, for TetGen's Delaunay phase to mesh. Why: left to TetGen's
// quality refinement (-q) alone, the far field's inside costs ~250 us per inserted point on the
// paper's case and more per point as the mesh grows (its insertions next to a kept boundary are
// undone and tried again); its Delaunay phase takes ~20 us per point at any size
// (docs/benchmarks.md, "Interior points for TetGen").
#pragma once

#include <Eigen/Core>

#include <array>
#include <vector>

namespace semimesh::farfield {

struct InteriorPointParams {
  /// >= 1: the spacing h(x) = min(max_spacing, min_i [h_i + (growth - 1) |x - x_i|]) over the
  /// boundary's vertices x_i, h_i the mean length of the boundary edges at x_i.
  double growth = 1.2;
  double max_spacing = 1.0;  ///< > 0
};

/// [points][3] inside the region bounded by `triangles` (indices into `boundary`; closed: every edge
/// in an even number of triangles, orientation not needed; the region is where a ray crosses the
/// boundary an odd number of times, e.g. a box minus a body). One point per cell of an octree whose
/// cells are refined until their side is at most kLeafSide h(centre), at the cell's centre moved by
/// a fixed pseudo-random offset (so that no four points lie exactly on a circle); a point closer
/// than kClearance h(centre) to the boundary is left out, for the boundary's own vertices stand there.
/// The result does not depend on the thread count. Throws std::invalid_argument on parameters out
/// of range.
std::vector<Eigen::Vector3d> interior_points(const std::vector<Eigen::Vector3d>& boundary,
                                             const std::vector<std::array<int, 3>>& triangles,
                                             const InteriorPointParams& params);

/// Whether x lies inside the region bounded by `triangles` as interior_points understands it (odd
/// crossings along rays, a ray grazing an edge replaced by another): exposed for tests.
bool inside_boundary(const std::vector<Eigen::Vector3d>& boundary, const std::vector<std::array<int, 3>>& triangles,
                     const Eigen::Vector3d& x);

}  // namespace semimesh::farfield
