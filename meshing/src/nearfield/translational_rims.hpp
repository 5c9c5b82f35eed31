// The H-type's rear interfaces made translational for PyFR (output.target = "pyfr"; docs/solvers.md).
// PyFR refuses a pyramid whose base's corners are not a parallelogram. A rear interface (a, b, b',
// a') cut by the wing layer's split at the same fractions f_k on both layer edges gives quads whose
// defect a_k - b_k + b_{k+1} - a_{k+1} is (f_{k+1} - f_k) ((b' - b) - (a' - a)): they are all
// parallelograms when the two layer edges are translates of each other, whatever a - b is. The
// wake sweeps the rear interfaces above the cut downstream unchanged (no widening), so its outflow
// face inherits them; those below the cut face the far field themselves.
#pragma once

#include "junction_shell.hpp"

#include <cstddef>
#include <map>

namespace semimesh::nearfield::detail {

// What make_rear_interfaces_translational did: how many offset nodes it moved, each side's layer
// edge (its mean one, by CAD surface) and the root row's layer nodes on a rear interface (the
// strip tops at the trailing edge's root corners), by the side whose rear interface they bound.
struct TranslationalRims {
  std::size_t moved = 0;
  std::map<int, Vec3> side_edge;  ///< side surface -> the layer edge of its rear interfaces
  std::map<int, int> root_corner;  ///< layer node of a strip top -> its side surface
};

/// Moves the offset node of every rear-interface node that belongs to one side only (one CAD
/// surface: upper, lower, tip) so all of that side's layer edges there are the side's mean one.
/// Left as they are: the root row (pinned at the junction's halos: open_root_corners moves
/// those of the trailing edge's root corners) and the corners two sides share (e.g. the tip's
/// trailing-edge corners), where no one vector serves both sides. A sharp trailing edge: the
/// crack's nodes only. With `along` (the wake's direction, when it runs to the far field's
/// downstream face), every layer edge there, the corners' included, is also given the same reach
/// along it (the largest of theirs), so the wake's outer faces meet that face on one line-up of
/// nodes (docs/solvers.md).
TranslationalRims make_rear_interfaces_translational(JunctionShell& js, const Vec3* along = nullptr);

}  // namespace semimesh::nearfield::detail
