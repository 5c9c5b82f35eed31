// The boundary of a surface mesh: the curve mesh nodes of its loops, mapped into the surface's
// parameter space. A node at a CAD vertex appears once per image of the vertex in (u, v): once,
// except on seams and at poles.
#pragma once

#include "semimesh/cad/labels.hpp"
#include "semimesh/surface/surface_mesh.hpp"

#include <vector>

namespace semimesh::surface::detail {

/// Fills `mesh.uv/points/origin` with the boundary nodes and returns the loops as closed chains of
/// node ids in walking order ([loops][nodes], the last node joins back to the first).
/// A periodic face is cut open along its seams: a seam's nodes appear twice, one period apart in
/// (u, v), the image with the face on the use's left for each use. A pole appears twice too, as
/// the two ends of a segment along the side of the parameter box that maps onto it (remove_pole_
/// triangles then drops the triangle on that segment). Nodes of one CAD vertex at one (u, v) are one
/// node. Throws SurfaceMeshError when a curve node is off the surface or a curve is used twice in
/// the same direction.
std::vector<std::vector<int>> add_boundary_nodes(const cad::Model& model, int surface, const CurveMeshes& curves,
                                                 SurfaceMesh& mesh);

/// Drops the triangles with two corners at one CAD vertex (on a pole segment: no area in space).
void remove_pole_triangles(SurfaceMesh& mesh);

/// Spacing of the grid that parameter coordinates are snapped to: a power of two near 2^-32 of the
/// surface's parameter box (of the boundary nodes' (u, v) box where the surface is unbounded), so
/// that snapping is exact arithmetic and does not depend on where the box starts.
double parameter_grid_step(const cad::Surface& face, const SurfaceMesh& mesh);

/// (u, v) rounded to the nearest multiple of `step`.
Vec2 snap_to_grid(const Vec2& uv, double step);

/// Makes the mesher's input independent of how the CAD backend describes the same face: turns
/// each loop so the face lies on its left in (u, v), starts it at its lowest node in (u, v) order,
/// sorts the holes by that node and renumbers the nodes in the resulting walking order. Positions
/// are compared snapped to the grid, so two models agreeing to ~1e-13 decide alike. Updates
/// `loops` to the new ids; mesh.uv stays unsnapped.
void canonicalise_boundary(double grid_step, SurfaceMesh& mesh, std::vector<std::vector<int>>& loops);

}  // namespace semimesh::surface::detail
