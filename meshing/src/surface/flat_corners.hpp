// No triangle may turn a smooth stretch of a surface's boundary into one of its corners.
//
// A triangle whose two edges at node n both lie on the boundary has, once its edges are curved
// onto the CAD curves, the angle between the curves' tangents at n as its corner angle. Where the
// boundary is smooth at n (inside a curve, or at a CAD vertex where two curves meet tangentially,
// e.g. the leading edge of a wing's flat tip cap) that angle is 180 degrees: det J of the curved
// triangle, and of the prism extruded from it, is zero at n however fine the mesh. Such corners
// get a second triangle: the opposite edge is swapped, or split at its (u, v) midpoint when the
// swap would not be valid in (u, v) or would end on a boundary node.
#pragma once

#include "semimesh/surface/surface_mesh.hpp"

namespace semimesh::surface::detail {

/// Boundary corner angles above this (degrees, between the curves' tangents) count as smooth.
constexpr double kSmoothCornerDeg = 135.0;

/// Triangles must be counter-clockwise in (u, v); they stay so. Returns the number of corners fixed.
int fix_flat_corners(const cad::Model& model, int surface, SurfaceMesh& mesh);

}  // namespace semimesh::surface::detail
