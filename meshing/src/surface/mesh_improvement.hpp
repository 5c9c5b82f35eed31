// Quality improvement of a triangle mesh on a surface, measured in 3D and kept valid in (u, v):
// edge swaps that raise the smaller minimum angle of the two triangles, collapses of too short
// interior edges, and smoothing of interior
// nodes toward equilateral positions or the 3D centroid of their neighbours (accepted only when
// the worst angle around the node does not get worse).
#pragma once

#include "semimesh/surface/surface_mesh.hpp"

namespace semimesh::surface::detail {

/// Triangles must be counter-clockwise in (u, v); they stay so. A swap that unfolds a triangle
/// facing against the surface in space counts as a gain. Returns the number of swaps.
int swap_edges(const cad::Surface& face, SurfaceMesh& mesh);

/// Merges the two ends of interior edges (both nodes interior) much shorter than the size field
/// asks, when the merged node keeps its triangles valid and does not lower the worst angle.
/// Removes the merged nodes; boundary nodes keep their ids. Returns the number of collapses.
int collapse_short_edges(const cad::Surface& face, const SizeField& size, SurfaceMesh& mesh);

/// Moves interior nodes (origin.curve == -1) on `face`. Returns the number of nodes moved.
int smooth_nodes(const cad::Surface& face, SurfaceMesh& mesh);

}  // namespace semimesh::surface::detail
