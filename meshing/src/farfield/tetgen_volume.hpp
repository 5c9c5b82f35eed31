// Tetrahedra of a closed triangulated boundary through TetGen 1.5 (AGPL-3.0-or-later: only the
// semimesh_farfield target links it).
#pragma once

#include <Eigen/Core>

#include <array>
#include <atomic>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace semimesh::farfield {

struct TetgenInput {
  std::vector<Eigen::Vector3d> points;         ///< [points] the boundary's, then any interior points
  std::vector<std::array<int, 3>> triangles;   ///< [triangles][3] the boundary, kept exactly
  double radius_edge_ratio = 1.5;              ///< -q bound
  double max_volume = 0.0;                     ///< -a bound; 0: none
  int max_added_points = -1;                   ///< -S bound on the refinement's points; -1: none
  /// > 0: TetGen first meshes the boundary points moved by up to this share of their shortest
  /// edge (untie_boundary), the answer taken on the true points where it holds there; 0: not.
  double untie = 0.0;
  /// What the triangles are, for messages: each part's name and the end of its run of triangles.
  std::vector<std::pair<std::size_t, std::string>> parts;
};

using BesideChild = std::function<void(const std::atomic<bool>& stop)>;

struct TetgenOutput {
  std::vector<Eigen::Vector3d> points;         ///< [points] the input points first, same order, then Steiner points
  std::vector<std::array<int, 4>> tets;        ///< [tets][4] positive volume (Gmsh's reference orientation)
  double seconds = 0.0;                        ///< TetGen's, all its tries
  bool untied = false;                         ///< the answer is TetGen's on the untied boundary
};

/// Runs TetGen with switches "pYQ q<ratio> [a<volume>] [S<points>]": the region enclosed by the
/// triangles is filled (the outside of the boundary, reached from the convex hull, is carved away),
/// no point is added on the boundary (Y). Points that no triangle uses are interior points, kept in
/// the Delaunay phase; the refinement then adds at most `max_added_points` (without interior
/// points the refinement makes every size: tets start at the size of the boundary triangles they
/// touch and grow away from them by the radius-edge bound alone).
/// TetGen runs in a child process (see tetgen_volume.cpp: TetGen 1.5.0 crashes while reporting
/// errors). Throws FarFieldError, before TetGen runs, when a boundary edge is shorter than the
/// distance at which TetGen merges points (1e-8 of the boundary's bounding-box diagonal); with
/// TetGen's failure explained (self-intersecting boundary, facets too close, ...) and, when the
/// boundary crosses itself, the two triangles and the point; when TetGen moved or dropped an
/// input point; or when a tet of its answer is flat to round-off (6 V under 1e-12 of its longest
/// edge cubed: its sign is round-off, and the weld's round-off moves turn it over), naming where. `quiet`: TetGen's own messages (a failed
/// assertion's, on stderr) are dropped, for a first try that a second one follows.
/// `beside` (optional): work that only speeds up later stages, run on another thread while TetGen's
/// process runs; `stop` is set when TetGen has answered and `beside` is then waited for (it should
/// return soon). Its exceptions are dropped: what it computes must be computed again without it.
/// `input.untie` > 0: TetGen meshes the boundary points moved off their exact ties first (its
/// Delaunay phase then decides in floating point: twice as fast on the paper's case); its tets are
/// taken on the true points when each stays positive and none is flat there (`untied`), else
/// TetGen runs again on the true points (`beside` then runs beside the first run only).
TetgenOutput run_tetgen(const TetgenInput& input, bool quiet = false, const BesideChild& beside = {});

}  // namespace semimesh::farfield
