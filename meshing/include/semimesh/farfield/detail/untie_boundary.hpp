// TetGen's boundary points moved off exact ties for its Delaunay phase, and the check that its
// answer holds on the true points. Why: where input points are exactly cospherical or coplanar (an
// extruded wing's rows of equal sections, a wake block's structured faces, a planar wall layer's
// tops) TetGen's insphere and orientation predicates cannot decide in floating point and are
// evaluated exactly: on the paper's case its Delaunay phase took 0.8 s for 67 k points, 0.37 s with
// the boundary points moved by 1e-8 of their shortest edge (docs/benchmarks.md, "Session 38").
#pragma once

#include <Eigen/Core>

#include <array>
#include <cstddef>
#include <optional>
#include <vector>

namespace semimesh::farfield {

/// [points][3]: `points` with each point that a triangle uses moved by at most `share` of its
/// shortest edge among the triangles, per coordinate, in a pseudo-random direction fixed by its
/// index (the same on every run and thread count); the points no triangle uses are unchanged. A
/// point keeps coordinate k where one of its triangles lies in a plane x_k = c (all three equal
/// there): such planes (a box face, a planar wall, a wall layer's tops) stay exact, else four of
/// their points could make a tet of TetGen's that is flat on the true points (the paper's
/// geometry at 1.4e5 elements: four points of the wall layer's tops, z = 0.1).
/// `triangles` [triangles][3]: indices into `points`.
std::vector<Eigen::Vector3d> untie_boundary(const std::vector<Eigen::Vector3d>& points,
                                            const std::vector<std::array<int, 3>>& triangles, double share);

/// The first tetrahedron (index into `tets`, [tets][4] into `points`) whose six times volume at
/// `points` is not positive: one that a mesh of moved points turns over or flattens on the true ones.
std::optional<std::size_t> first_unpositive_tet(const std::vector<Eigen::Vector3d>& points,
                                                const std::vector<std::array<int, 4>>& tets);

}  // namespace semimesh::farfield
